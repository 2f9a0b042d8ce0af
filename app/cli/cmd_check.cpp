// iecstudio-cli check FILE: compile every POU and list the diagnostics. Formats: docs/cli.md.

#include "app/cli/commands.h"
#include "app/cli/diagnostics.h"
#include "app/cli/projectinput.h"

namespace iec::cli {

int runCheck(const QStringList &arguments, Io io)
{
    if (arguments.size() != 1 || arguments.front().startsWith(QLatin1Char('-'))) {
        io.err << "Usage: iecstudio-cli check FILE\n";
        return ExitUsage;
    }
    const QString &file = arguments.front();
    interp::Diagnostics diagnostics;
    const LoadedUnit loaded = loadUnit(file, diagnostics, io.out);
    if (loaded.status == ExitOk)
        interp::frontend::compileUnit(loaded.unit, diagnostics);
    printDiagnostics(file, diagnostics, io.out);
    if (loaded.status != ExitOk)
        return loaded.status;
    return diagnostics.hasErrors() ? ExitFailed : ExitOk;
}

} // namespace iec::cli
