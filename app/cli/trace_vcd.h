#pragma once

#include "app/cli/trace.h"

namespace iec::cli {

// Value Change Dump (IEEE 1364) as GTKWave reads it: BOOL as 1-bit wires, integers, bit strings,
// enums and times (nanoseconds) as vectors of their width, REAL/LREAL as `real`. Time unit 1 us
// (1 ns when the cycle is not a whole number of microseconds); values at #0 are the initial ones.
class VcdTrace : public Trace
{
public:
    VcdTrace(const QString &path, std::vector<TracedVariable> variables)
        : Trace(path, std::move(variables))
    { }
    void begin(interp::Runtime &runtime) override;
    void sample(int cycle, interp::Runtime &runtime) override;

private:
    void writeChanges(interp::Runtime &runtime);

    std::int64_t m_nsPerUnit = 1000;
    std::vector<QString> m_last; // the last value written per variable
};

// Whether every variable has a VCD form; else `error` names the first that has none.
bool vcdCanHold(const std::vector<TracedVariable> &variables, QString &error);

} // namespace iec::cli
