// iecstudio-cli convert IN OUT: between PLCopen XML (.xml) and IEC text (.st), either way.

#include "app/cli/commands.h"
#include "app/cli/projectinput.h"

#include "interpreter/frontend/iecprinter.h"

#include "model/plcopen/writer.h"
#include "model/savefile.h"

#include <QFileInfo>

namespace iec::cli {

namespace {

// IEC text has no file header; a project read from .st gets one from the file it came from, so
// converting the same file twice gives the same bytes.
void fillHeader(model::Project &project, const QString &input)
{
    if (!project.fileHeader.creationDateTime.isEmpty())
        return;
    project.fileHeader.productVersion = QStringLiteral(IECSTUDIO_VERSION);
    project.fileHeader.creationDateTime = QFileInfo(input).lastModified().toUTC().toString(Qt::ISODate);
}

bool writeProject(model::Project &project, const QString &input, const QString &output, Io io, QString &error)
{
    if (formatOf(output) == FileFormat::Xml) {
        fillHeader(project, input);
        return model::plcopen::saveProjectFile(project, output, &error);
    }
    std::vector<interp::frontend::PrintWarning> warnings;
    const QString text = interp::frontend::printProject(project, &warnings);
    for (const interp::frontend::PrintWarning &warning : warnings)
        io.err << input << ":" << warning.pou << ": warning: " << warning.message << "\n";
    return model::saveFileAtomically(output, text.toUtf8(), &error);
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
    if (formatOf(input) == FileFormat::Other || formatOf(output) == FileFormat::Other) {
        io.err << "iecstudio-cli: convert reads PLCopen XML (.xml) and IEC text (.st, .exp) and writes .xml or .st.\n";
        return ExitUsage;
    }
    LoadedProject loaded = loadProject(input, io.err);
    if (loaded.status != ExitOk)
        return loaded.status; // never write a project that was only partly understood
    QString error;
    if (!writeProject(loaded.project, input, output, io, error)) {
        io.err << "iecstudio-cli: " << error << "\n";
        return ExitIoError;
    }
    return ExitOk;
}

} // namespace iec::cli
