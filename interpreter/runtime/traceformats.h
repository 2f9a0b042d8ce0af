#pragma once

#include "interpreter/runtime/tracedata.h"

#include <QTextStream>

#include <memory>
#include <vector>

namespace iec::interp {

// Writes traced rows as a file (formats: docs/cli.md). The CLI's `run --trace` and the IDE's
// Trace pane share these, so both give the same file for the same samples.
// The first row is the initial one: VCD dumps it as the start values; CSV writes it as a row
// only when it comes after a cycle (its cycle is above 0).
class TraceWriter
{
public:
    virtual ~TraceWriter() = default;
    virtual void begin(const TraceRow &initial) = 0;
    virtual void write(const TraceRow &row) = 0;
};

// cycle,time_ms,NAME...: one row per cycle, values as IEC literals (the same text as --watch).
std::unique_ptr<TraceWriter> makeCsvWriter(QTextStream &out, std::vector<TraceVariable> variables);

// Value Change Dump (IEEE 1364) as GTKWave reads it: BOOL as 1-bit wires, integers, bit strings,
// enums and times (nanoseconds) as vectors of their width, REAL/LREAL as `real`. Time unit 1 us
// (1 ns when the cycle is not a whole number of microseconds). `generator` goes in $version.
std::unique_ptr<TraceWriter> makeVcdWriter(QTextStream &out, std::vector<TraceVariable> variables,
                                           std::int64_t cycleNs, const QString &generator);

// Whether every variable has a VCD form; else `error` names the first that has none.
bool vcdCanHold(const std::vector<TraceVariable> &variables, QString &error);

// A CSV field (RFC 4180): quoted, its quotes doubled, when it holds a comma, quote or line break.
QString csvField(const QString &text);

// Virtual milliseconds, without a fraction when whole: 10, 2.5.
QString formatMilliseconds(std::int64_t ns);

} // namespace iec::interp
