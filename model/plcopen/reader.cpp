#include "model/plcopen/reader.h"

#include "model/layout.h"
#include "model/plcopen/repair.h"
#include "model/plcopen/schema_project.h"

#include <QFile>

#include <algorithm>

namespace iec::model::plcopen {

namespace {

constexpr unsigned kParseOptions = pugi::parse_default | pugi::parse_ws_pcdata_single;

bool isPlcopenNamespace(const char *uri)
{
    return !*uri || !std::strcmp(uri, kTc6Namespace) || !std::strcmp(uri, kTc6OldNamespace);
}

void checkNamespace(pugi::xml_node root, ReadContext &context)
{
    const char *colon = std::strchr(root.name(), ':');
    const std::string declaration
        = colon ? "xmlns:" + std::string(root.name(), colon - root.name()) : std::string("xmlns");
    const char *uri = root.attribute(declaration.c_str()).value();
    if (!isPlcopenNamespace(uri))
        context.report(Diagnostic::Severity::Warning, root,
            QCoreApplication::translate("iec::model::plcopen::Reader",
                "The namespace '%1' is not PLCopen TC6 XML 2.01; the file is read anyway.")
                .arg(QString::fromUtf8(uri)));
}

void layoutBodies(std::vector<Body> &bodies)
{
    for (Body &body : bodies)
        generateLayoutIfUnplaced(body);
}

void layoutProject(Project &project)
{
    for (Pou &pou : project.types.pous) {
        layoutBodies(pou.bodies);
        for (PouAction &action : pou.actions)
            generateLayoutIfUnplaced(action.body);
        for (PouTransition &transition : pou.transitions)
            generateLayoutIfUnplaced(transition.body);
    }
}

} // namespace

bool ReadResult::hasErrors() const
{
    return std::ranges::any_of(
        diagnostics, [](const Diagnostic &d) { return d.severity == Diagnostic::Severity::Error; });
}

ReadResult readProject(const QByteArray &bytes)
{
    ReadResult result;
    ReadContext context;
    context.indexLines(bytes.constData(), bytes.size());

    pugi::xml_document document;
    const QByteArray mended = withNulAsAnotherControlCharacter(bytes);
    const pugi::xml_parse_result parsed
        = document.load_buffer(mended.constData(), std::size_t(mended.size()), kParseOptions, pugi::encoding_auto);
    if (!parsed) {
        context.reportAtOffset(Diagnostic::Severity::Error, qsizetype(parsed.offset),
            QCoreApplication::translate("iec::model::plcopen::Reader", "The file is not well-formed XML: %1.")
                .arg(QString::fromUtf8(parsed.description())));
        result.diagnostics = std::move(context.diagnostics);
        return result;
    }
    const pugi::xml_node root = document.document_element();
    if (!hasLocalName(root, "project")) {
        context.report(Diagnostic::Severity::Error, root,
            QCoreApplication::translate("iec::model::plcopen::Reader",
                "The root element is <%1>, not <project>: this is not a PLCopen XML file.")
                .arg(QString::fromUtf8(root.name())));
        result.diagnostics = std::move(context.diagnostics);
        return result;
    }
    checkNamespace(root, context);
    dropCharactersXmlDoesNotAllow(document, context);
    keepFirstOfRepeatedAttributes(document, context);
    repairOldForms(root, context);
    result.isProject = true;

    XmlIn in(root, context);
    Schema<Project>::describe(in, result.project);
    // Declarations found in vendor addData follow the ordinary ones, in file order.
    std::ranges::move(context.addDataTypes, std::back_inserter(result.project.types.dataTypes));
    std::ranges::move(context.addDataPous, std::back_inserter(result.project.types.pous));
    layoutProject(result.project);

    // Unknown content is reported when an element is finished; present everything in file order.
    std::ranges::stable_sort(context.diagnostics, {}, [](const Diagnostic &d) { return std::pair(d.line, d.column); });
    result.diagnostics = std::move(context.diagnostics);
    result.ok = !result.hasErrors();
    return result;
}

ReadResult readProjectFile(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        ReadResult result;
        result.fileError = true;
        result.diagnostics.push_back({.severity = Diagnostic::Severity::Error,
            .message = QCoreApplication::translate("iec::model::plcopen::Reader", "Cannot open %1: %2.")
                           .arg(path, file.errorString())});
        return result;
    }
    return readProject(file.readAll());
}

} // namespace iec::model::plcopen
