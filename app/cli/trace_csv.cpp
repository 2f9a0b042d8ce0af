#include "app/cli/trace_csv.h"

#include "interpreter/runtime/traceformats.h"

namespace iec::cli {

// Any variable, arrays and strings too: the CSV trace writes what --watch prints. (The IDE's
// Trace pane writes the same format through interp::makeCsvWriter, for the values it records.)
void CsvTrace::begin(interp::Runtime &)
{
    out() << "cycle,time_ms";
    for (const TracedVariable &variable : variables())
        out() << ',' << interp::csvField(variable.name);
    out() << '\n';
}

void CsvTrace::sample(int cycle, interp::Runtime &runtime)
{
    out() << cycle << ',' << interp::formatMilliseconds(runtime.timeNs());
    for (const TracedVariable &variable : variables())
        out() << ',' << interp::csvField(runtime.read(variable.ref));
    out() << '\n';
}

} // namespace iec::cli
