// iecstudio-cli info FILE [--json]: what a project contains. Formats: docs/cli-info.md.

#include "app/cli/commands.h"
#include "app/cli/diagnostics.h"
#include "app/cli/projectinput.h"

#include "model/plcopen/reader.h"
#include "model/statistics.h"

#include <QJsonDocument>
#include <QJsonObject>

namespace iec::cli {

namespace {

QJsonObject countsObject(const std::map<QString, int> &counts)
{
    QJsonObject object;
    for (const auto &[name, count] : counts)
        object.insert(name, count);
    return object;
}

void printJson(const QString &name, const model::ProjectStatistics &stats, QTextStream &out)
{
    const QJsonObject root {
        {QStringLiteral("project"), name},
        {QStringLiteral("pous"),
            QJsonObject {{QStringLiteral("total"), stats.pous},
                {QStringLiteral("byKind"), countsObject(stats.pousByKind)},
                {QStringLiteral("byLanguage"), countsObject(stats.pousByLanguage)}}},
        {QStringLiteral("dataTypes"), stats.dataTypes},
        {QStringLiteral("variables"), stats.variables},
        {QStringLiteral("actions"), stats.actions},
        {QStringLiteral("transitions"), stats.transitions},
        {QStringLiteral("elements"),
            QJsonObject {{QStringLiteral("total"), stats.elements},
                {QStringLiteral("byKind"), countsObject(stats.elementsByKind)}}},
    };
    out << QJsonDocument(root).toJson(QJsonDocument::Indented);
}

void printCounts(const std::map<QString, int> &counts, QTextStream &out)
{
    for (const auto &[name, count] : counts)
        out << "  " << name << ": " << count << "\n";
}

void printText(const QString &name, const model::ProjectStatistics &stats, QTextStream &out)
{
    out << "project: " << name << "\n";
    out << "POUs: " << stats.pous << "\n";
    printCounts(stats.pousByKind, out);
    out << "POUs by language:\n";
    printCounts(stats.pousByLanguage, out);
    out << "data types: " << stats.dataTypes << "\n";
    out << "variables: " << stats.variables << "\n";
    out << "actions: " << stats.actions << "\n";
    out << "transitions: " << stats.transitions << "\n";
    out << "graphical elements: " << stats.elements << "\n";
    printCounts(stats.elementsByKind, out);
}

} // namespace

int runInfo(const QStringList &arguments, Io io)
{
    const bool json = arguments.contains(QLatin1String("--json"));
    QStringList files = arguments;
    files.removeAll(QStringLiteral("--json"));
    if (files.size() != 1 || files.front().startsWith(QLatin1Char('-'))) {
        io.err << "Usage: iecstudio-cli info FILE [--json]\n";
        return ExitUsage;
    }
    const auto print = [&](const model::Project &project) {
        const model::ProjectStatistics stats = model::statistics(project);
        if (json)
            printJson(project.contentHeader.name, stats, io.out);
        else
            printText(project.contentHeader.name, stats, io.out);
    };
    if (formatOf(files.front()) == FileFormat::St) { // IEC text (.st, .exp), read as check reads it
        const LoadedProject loaded = loadProject(files.front(), io.err);
        if (loaded.status != ExitIoError)
            print(loaded.project);
        return loaded.status;
    }
    const model::plcopen::ReadResult result = model::plcopen::readProjectFile(files.front());
    printDiagnostics(files.front(), result.diagnostics, io.err);
    if (result.fileError)
        return ExitIoError;
    if (!result.isProject)
        return ExitFailed; // nothing to count
    print(result.project);
    return result.ok ? ExitOk : ExitFailed;
}

} // namespace iec::cli
