#pragma once

#include "app/cli/trace.h"
#include "interpreter/runtime/traceformats.h"

namespace iec::cli {

// A VCD trace (interp::makeVcdWriter) of the values after each cycle; values at #0 are the
// initial ones.
class VcdTrace : public Trace
{
public:
    VcdTrace(const QString &path, std::vector<TracedVariable> variables)
        : Trace(path, std::move(variables))
    { }
    void begin(interp::Runtime &runtime) override;
    void sample(int cycle, interp::Runtime &runtime) override;

private:
    std::unique_ptr<interp::TraceWriter> m_writer;
};

} // namespace iec::cli
