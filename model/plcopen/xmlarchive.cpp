#include "model/plcopen/xmlarchive.h"
#include "model/plcopen/schema_project.h"

#include <sstream>

namespace iec::model::plcopen {

namespace {

struct StringWriter : pugi::xml_writer {
    std::string text;
    void write(const void *data, size_t size) override { text.append(static_cast<const char *>(data), size); }
};

// Text content gathered from every pcdata/cdata node below `node`.
QString descendantText(pugi::xml_node node)
{
    std::string text;
    walkDescendants(node, [&](pugi::xml_node child) {
        if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata)
            text += child.value();
        return child.type() == pugi::node_element;
    });
    return QString::fromStdString(text);
}

bool hasOnlyText(pugi::xml_node node)
{
    for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
        if (child.type() != pugi::node_pcdata && child.type() != pugi::node_cdata)
            return false;
    }
    return true;
}

} // namespace

const char *localName(pugi::xml_node node)
{
    const char *name = node.name();
    const char *colon = std::strchr(name, ':');
    return colon ? colon + 1 : name;
}

bool hasLocalName(pugi::xml_node node, const char *name)
{
    return std::strcmp(localName(node), name) == 0;
}

QString rawXml(pugi::xml_node node)
{
    StringWriter writer;
    node.print(writer, "", pugi::format_raw, pugi::encoding_utf8);
    return QString::fromStdString(writer.text);
}

bool nestsDeeperThan(pugi::xml_node root, int limit)
{
    int depth = 1;
    pugi::xml_node node = root.first_child();
    while (node) {
        if (depth > limit)
            return true;
        if (node.first_child()) {
            node = node.first_child();
            ++depth;
            continue;
        }
        while (node != root && !node.next_sibling()) {
            node = node.parent();
            --depth;
        }
        if (node == root)
            return false;
        node = node.next_sibling();
    }
    return false;
}

void appendFragment(pugi::xml_node parent, const QString &xml)
{
    if (xml.isEmpty())
        return;
    if (xml.trimmed().isEmpty()) {
        // Only white space (an addData entry holding nothing else): a fragment parse drops it, so
        // it is written as text, which the reader keeps (found by fuzz_plcopen).
        parent.append_child(pugi::node_pcdata).set_value(toFileUtf8(xml).constData());
        return;
    }
    pugi::xml_document fragment;
    const QByteArray bytes = toFileUtf8(xml);
    if (!fragment.load_buffer(bytes.constData(), bytes.size(),
            pugi::parse_default | pugi::parse_fragment | pugi::parse_ws_pcdata_single, pugi::encoding_utf8))
        return; // the model only holds text we serialized ourselves; nothing to salvage otherwise
    for (pugi::xml_node child = fragment.first_child(); child; child = child.next_sibling())
        parent.append_copy(child);
}

void readFormattedText(pugi::xml_node node, FormattedText &text)
{
    std::vector<pugi::xml_node> elements;
    for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
        if (child.type() == pugi::node_element)
            elements.push_back(child);
    }
    if (elements.empty()) {
        text.text = descendantText(node); // not XHTML at all; be lenient
    } else if (elements.size() == 1 && hasOnlyText(elements.front())) {
        text.text = descendantText(elements.front()); // <xhtml:p> or CODESYS' <xhtml xmlns=..>
    } else {
        // The text is that of the elements kept: text beside them (not XHTML, so not written back)
        // would make the model read from the file differ from the one read after saving it.
        for (pugi::xml_node element : elements) {
            text.text += descendantText(element);
            text.xhtml += rawXml(element);
        }
    }
}

void writeProgramText(pugi::xml_node node, const QString &text)
{
    pugi::xml_node paragraph = node.append_child("xhtml:p");
    // CDATA cannot contain "]]>": end the section between "]]" and ">" and start a new one.
    const std::string utf8 = toFileUtf8(text).toStdString();
    std::size_t start = 0;
    for (std::size_t found = utf8.find("]]>"); found != std::string::npos; found = utf8.find("]]>", start)) {
        paragraph.append_child(pugi::node_cdata).set_value(utf8.substr(start, found + 2 - start).c_str());
        start = found + 2;
    }
    paragraph.append_child(pugi::node_cdata).set_value(utf8.substr(start).c_str());
}

void writeFormattedText(pugi::xml_node node, const FormattedText &text)
{
    if (!text.xhtml.isEmpty())
        appendFragment(node, text.xhtml);
    else
        writeProgramText(node, text.text);
}

std::string dataTypeTag(const DataType &type)
{
    struct Visitor {
        std::string operator()(const ElementaryType &t) const
        {
            return t.name.isEmpty() ? std::string("ANY") : t.name.toStdString();
        }
        std::string operator()(const StringType &t) const { return t.wide ? "wstring" : "string"; }
        std::string operator()(const ArrayType &) const { return "array"; }
        std::string operator()(const DerivedType &) const { return "derived"; }
        std::string operator()(const EnumType &) const { return "enum"; }
        std::string operator()(const StructType &) const { return "struct"; }
        std::string operator()(const SubrangeType &t) const
        {
            return t.isUnsigned ? "subrangeUnsigned" : "subrangeSigned";
        }
        std::string operator()(const PointerType &) const { return "pointer"; }
    };
    return std::visit(Visitor {}, type.kind);
}

const char *varListTag(VarListKind kind)
{
    for (const auto &[candidate, tag] : kVarListTags) {
        if (candidate == kind)
            return tag;
    }
    return "localVars";
}

bool takeLayoutEntry(AddData &entries)
{
    return std::erase_if(entries, [](const AddDataEntry &entry) {
        return entry.name == QLatin1String(kLayoutAddDataName);
    }) > 0;
}

AddData withLayoutEntry(const AddData &entries)
{
    AddData result = entries;
    result.push_back({QString::fromLatin1(kLayoutAddDataName), QStringLiteral("discard"),
        QStringLiteral("<layout generated=\"true\"/>")});
    return result;
}

} // namespace iec::model::plcopen
