#pragma once

#include <QStringList>
#include <QTextStream>

#include <span>

namespace iec::cli {

// Exit codes shared by every subcommand.
enum ExitCode : int {
    ExitOk = 0,
    ExitFailed = 1,  // the command ran and found errors (diagnostics, failed checks)
    ExitUsage = 2,   // wrong arguments
    ExitIoError = 3, // a file could not be read or written
};

struct Io {
    QTextStream &out;
    QTextStream &err;
};

struct Command {
    const char *name;
    const char *synopsis;
    const char *summary;
    int (*run)(const QStringList &arguments, Io io);
};

// Every subcommand, in the order `--help` lists them.
std::span<const Command> commands();

int printUsage(QTextStream &stream);

// The subcommands, one file each (cmd_*.cpp).
int runInfo(const QStringList &arguments, Io io);
int runConvert(const QStringList &arguments, Io io);
int runCheck(const QStringList &arguments, Io io);
int runRun(const QStringList &arguments, Io io);
int runRender(const QStringList &arguments, Io io); // cmd_render.cpp, in iec_cli_render

} // namespace iec::cli
