#include "app/cli/commands.h"

#include <array>

namespace iec::cli {

namespace {

constexpr std::array<Command, 5> kCommands{{
    {"check", "check FILE", "Compile every POU and list the diagnostics; exit 1 on an error.", runCheck},
    {"info", "info FILE [--json]", "Count POUs, data types, variables and graphical elements.", runInfo},
    {"convert", "convert IN OUT", "Convert between PLCopen XML (.xml) and IEC text (.st), either way.", runConvert},
    {"run", "run FILE [--program P] [--cycles N] [--cycle-time 10ms] [--set NAME=VALUE[@CYCLE]]... "
            "[--watch NAME]... [--trace OUT.csv|OUT.vcd]",
     "Run scan cycles on a virtual clock and print the watched values.", runRun},
    {"render", "render FILE --pou NAME [--action NAME | --transition NAME] OUT.svg|OUT.png|OUT.pdf",
     "Draw a graphical body (a POU's, or one of its actions or transitions) without a display.", runRender},
}};

} // namespace

std::span<const Command> commands()
{
    return kCommands;
}

int printUsage(QTextStream &stream)
{
    stream << "Usage: iecstudio-cli COMMAND [ARGUMENTS]\n\n"
           << "IEC Studio on the command line: check, inspect, convert, run and render IEC 61131-3 projects\n"
           << "(PLCopen XML, or IEC text: .st, and CoDeSys 2.3 exports, .exp).\n\n"
           << "Commands:\n";
    for (const Command &command : kCommands)
        stream << "  " << qSetFieldWidth(10) << Qt::left << command.name << qSetFieldWidth(0) << command.summary
               << "\n" << "            iecstudio-cli " << command.synopsis << "\n";
    stream << "\nOptions:\n"
           << "  -h, --help     Show this help.\n"
           << "  -v, --version  Show the version.\n\n"
           << "Exit status: 0 success, 1 errors found, 2 wrong usage, 3 a file could not be read or written.\n";
    return ExitOk;
}

} // namespace iec::cli
