#pragma once

#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <vector>

namespace iec::cli {

// --set NAME=VALUE[@CYCLE]: written at the start of `cycle` (1 is the first).
struct ScheduledWrite {
    QString name;
    QString value;
    int cycle = 1;
};

// The arguments of `iecstudio-cli run`.
struct RunOptions {
    QString file;
    QString program; // --program: run this PROGRAM alone
    int cycles = 1; // --cycles
    std::optional<std::int64_t> cycleNs; // --cycle-time; default: the shortest task interval, else 10 ms
    std::vector<ScheduledWrite> writes; // --set, in the order given
    QStringList watches; // --watch, in the order given
    QString trace; // --trace OUT.csv | OUT.vcd
};

// Parses the arguments after `run`; on a mistake returns nullopt and sets `error` to one sentence.
std::optional<RunOptions> parseRunOptions(const QStringList &arguments, QString &error);

} // namespace iec::cli
