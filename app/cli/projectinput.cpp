#include "app/cli/projectinput.h"

#include "app/cli/diagnostics.h"

#include "interpreter/compiler/parser.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/sourcefile.h"

#include "model/plcopen/reader.h"

#include <QFile>
#include <QFileInfo>

namespace iec::cli {

namespace {

LoadedProject loadXml(const QString &path, QTextStream &stream)
{
    model::plcopen::ReadResult result = model::plcopen::readProjectFile(path);
    printDiagnostics(path, result.diagnostics, stream);
    if (result.fileError)
        return {ExitIoError, {}};
    // A project that was only partly understood is not compiled: its errors come first.
    return {result.ok ? ExitOk : ExitFailed, std::move(result.project)};
}

LoadedProject loadSt(const QString &path, QTextStream &stream)
{
    const std::optional<QString> text = readTextFile(path, stream);
    if (!text)
        return {ExitIoError, {}};
    interp::frontend::TextReadResult result = interp::frontend::readIecText(*text, QFileInfo(path).completeBaseName());
    printDiagnostics(path, result.diagnostics, stream);
    return {result.diagnostics.hasErrors() ? ExitFailed : ExitOk, std::move(result.project)};
}

} // namespace

FileFormat formatOf(const QString &path)
{
    if (path.endsWith(QLatin1String(".xml"), Qt::CaseInsensitive))
        return FileFormat::Xml;
    // .exp: CoDeSys 2.3's export, IEC text with its own comments (ST and IL POUs read).
    if (path.endsWith(QLatin1String(".st"), Qt::CaseInsensitive) || path.endsWith(QLatin1String(".exp"), Qt::CaseInsensitive))
        return FileFormat::St;
    return FileFormat::Other;
}

std::optional<QString> readTextFile(const QString &path, QTextStream &stream)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        stream << path << ": error: The file cannot be read: " << file.errorString() << ".\n";
        return std::nullopt;
    }
    interp::frontend::SourceText source = interp::frontend::decodeSourceFile(file.readAll());
    if (source.windows1252Line > 0)
        stream << path << ':' << source.windows1252Line << ":1: warning: " << interp::frontend::windows1252Note() << '\n';
    return std::move(source.text);
}

LoadedProject loadProject(const QString &path, QTextStream &stream)
{
    return formatOf(path) == FileFormat::St ? loadSt(path, stream) : loadXml(path, stream);
}

LoadedUnit loadUnit(const QString &path, interp::Diagnostics &diagnostics, QTextStream &stream)
{
    if (formatOf(path) == FileFormat::St) {
        const std::optional<QString> text = readTextFile(path, stream);
        if (!text)
            return {ExitIoError, {}};
        interp::Diagnostics parsing;
        LoadedUnit loaded {ExitOk, {interp::parseUnit(*text, parsing), false}};
        loaded.unit.parseErrors = parsing.hasUnrequestedErrors();
        diagnostics.append(parsing);
        return loaded;
    }
    LoadedProject project = loadXml(path, stream);
    if (project.status != ExitOk)
        return {project.status, {}};
    return {ExitOk, interp::frontend::buildUnit(project.project, diagnostics)};
}

} // namespace iec::cli
