#pragma once

#include "app/cli/trace.h"

namespace iec::cli {

// cycle,time_ms,NAME...: one row per cycle, values as IEC literals (the same text as --watch).
class CsvTrace : public Trace
{
public:
    CsvTrace(const QString &path, std::vector<TracedVariable> variables)
        : Trace(path, std::move(variables))
    { }
    void begin(interp::Runtime &runtime) override;
    void sample(int cycle, interp::Runtime &runtime) override;
};

} // namespace iec::cli
