// iecstudio-cli convert IN.xml OUT.xml: read a PLCopen project and write it back as TC6 2.01.

#include "app/cli/commands.h"
#include "app/cli/diagnostics.h"

#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"

namespace iec::cli {

namespace {

bool isXml(const QString &path)
{
    return path.endsWith(QLatin1String(".xml"), Qt::CaseInsensitive);
}

} // namespace

int runConvert(const QStringList &arguments, Io io)
{
    if (arguments.size() != 2) {
        io.err << "Usage: iecstudio-cli convert IN OUT\n";
        return ExitUsage;
    }
    const QString &input = arguments.at(0);
    const QString &output = arguments.at(1);
    if (!isXml(input) || !isXml(output)) {
        io.err << "iecstudio-cli: convert reads and writes PLCopen XML (.xml) in this build.\n";
        return ExitUsage;
    }
    const model::plcopen::ReadResult result = model::plcopen::readProjectFile(input);
    printDiagnostics(input, result.diagnostics, io.err);
    if (result.fileError)
        return ExitIoError;
    if (!result.ok)
        return ExitFailed; // never write a project that was only partly understood
    QString error;
    if (!model::plcopen::saveProjectFile(result.project, output, &error)) {
        io.err << "iecstudio-cli: " << error << "\n";
        return ExitIoError;
    }
    return ExitOk;
}

} // namespace iec::cli
