#pragma once

#include "interpreter/runtime/symbols.h"

#include <QString>

#include <cstdint>
#include <vector>

namespace iec::interp {

class Runtime;

// A traced variable: the name as the user wrote it and where it lives.
struct TraceVariable {
    QString name;
    VariableRef ref;
};

// One sample of every traced variable, after a cycle: each value's own bytes in a slot of
// kTraceSlot bytes (for a bit, the byte holding it), so a sample is formatted exactly as the
// live value would have been.
struct TraceRow {
    static constexpr std::size_t kTraceSlot = 8;
    int cycle = 0;
    std::int64_t timeNs = 0; // the runtime's clock when sampled (the next cycle's start)
    std::vector<std::uint8_t> bytes;
};

// Whether a variable can be traced: BOOL, a number, a bit string, an enum, a time or a date
// (no strings, arrays or structures), or one bit of a word.
bool isTraceable(const VariableRef &ref);
// A sentence for the user when it cannot be, naming it.
QString notTraceableReason(const TraceVariable &variable);

TraceRow captureRow(const Runtime &runtime, const std::vector<TraceVariable> &variables);
// The value of variable `index` in a row: as an IEC literal (TRUE, 42, T#1s), and as a number
// to plot (BOOL 0 or 1; times and dates in milliseconds; enums their value).
QString rowLiteral(const TraceRow &row, std::size_t index, const VariableRef &ref);
double rowNumber(const TraceRow &row, std::size_t index, const VariableRef &ref);
// The raw bits of a value in a row (little endian, as the VM), for bit-exact formats.
std::uint64_t rowBits(const TraceRow &row, std::size_t index, const VariableRef &ref);
bool isBoolean(const VariableRef &ref);

} // namespace iec::interp
