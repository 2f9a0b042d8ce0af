#include "model/plcopen/fragment.h"

#include "model/plcopen/schema_project.h"

namespace iec::model::plcopen {

namespace {

constexpr const char *kFragmentElement = "fragment";

struct ByteWriter : pugi::xml_writer {
    QByteArray bytes;
    void write(const void *data, size_t size) override { bytes.append(static_cast<const char *>(data), qsizetype(size)); }
};

QString tr(const char *text)
{
    return QCoreApplication::translate("iec::model::plcopen", text); // the context lupdate gives tr() here
}

} // namespace

QByteArray writeElementsFragment(const QString &language, const std::vector<Element> &elements)
{
    pugi::xml_document document;
    pugi::xml_node root = document.append_child(kFragmentElement);
    root.append_attribute("xmlns").set_value(kTc6Namespace);
    root.append_attribute("xmlns:xhtml").set_value(kXhtmlNamespace);
    root.append_attribute("language").set_value(toFileUtf8(language).constData());
    WriteContext context;
    XmlOut out(root, context);
    out.choiceList(elements);
    ByteWriter writer;
    constexpr int kMaxIndentedDepth = 256; // as writeProject: hostile nesting is written flat
    document.save(writer, "  ", nestsDeeperThan(document, kMaxIndentedDepth) ? pugi::format_raw : pugi::format_indent,
        pugi::encoding_utf8);
    return writer.bytes;
}

namespace {

// The children of `root` as elements; an error when something is lost.
void readChildren(const QByteArray &xml, const pugi::xml_node root, bool withLanguage, FragmentReadResult &result)
{
    ReadContext context;
    context.indexLines(xml.constData(), xml.size());
    XmlIn in(root, context);
    if (withLanguage)
        in.attr("language", result.language);
    in.choiceList(result.elements);
    Extras unknown;
    in.finish(unknown);
    result.diagnostics = std::move(context.diagnostics);
    for (const Diagnostic &diagnostic : result.diagnostics) {
        if (diagnostic.severity == Diagnostic::Severity::Error) {
            result.error = tr("It cannot be read: %1").arg(diagnostic.message);
            return;
        }
    }
    // Unknown children would be lost on paste: refuse rather than drop them silently.
    if (!unknown.elements.empty())
        result.error = tr("It holds something that is not an element of a body.");
}

} // namespace

FragmentReadResult readElementsUnder(const QByteArray &xml)
{
    FragmentReadResult result;
    pugi::xml_document document;
    const pugi::xml_parse_result parsed = document.load_buffer(
        xml.constData(), std::size_t(xml.size()), pugi::parse_default | pugi::parse_ws_pcdata_single, pugi::encoding_auto);
    if (!parsed) {
        result.error = tr("It is not well-formed XML: %1.").arg(QString::fromUtf8(parsed.description()));
        return result;
    }
    readChildren(xml, document.document_element(), false, result);
    return result;
}

QByteArray writeElementsUnder(const char *rootName, const std::vector<Element> &elements)
{
    pugi::xml_document document;
    pugi::xml_node root = document.append_child(rootName);
    WriteContext context;
    XmlOut out(root, context);
    out.choiceList(elements);
    ByteWriter writer;
    document.save(writer, "", pugi::format_raw | pugi::format_no_declaration, pugi::encoding_utf8);
    return writer.bytes;
}

FragmentReadResult readElementsFragment(const QByteArray &xml)
{
    FragmentReadResult result;
    pugi::xml_document document;
    const pugi::xml_parse_result parsed = document.load_buffer(
        xml.constData(), std::size_t(xml.size()), pugi::parse_default | pugi::parse_ws_pcdata_single, pugi::encoding_auto);
    if (!parsed) {
        result.error = tr("It is not well-formed XML: %1.").arg(QString::fromUtf8(parsed.description()));
        return result;
    }
    const pugi::xml_node root = document.document_element();
    if (!hasLocalName(root, kFragmentElement)) {
        result.error = tr("It is XML with a <%1> root, not elements copied in IEC Studio.").arg(QString::fromUtf8(root.name()));
        return result;
    }
    readChildren(xml, root, true, result);
    return result;
}

} // namespace iec::model::plcopen
