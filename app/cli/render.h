#pragma once

// `iecstudio-cli render` draws with the editors, which need a GUI application object (offscreen
// when no display is set). main() hands the whole command line over before it creates its
// QCoreApplication; this header stays free of GUI includes, so the rest of the CLI does too.
namespace iec::cli {

int renderMain(int argc, char *argv[]);

} // namespace iec::cli
