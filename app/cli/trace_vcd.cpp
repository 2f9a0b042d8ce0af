#include "app/cli/trace_vcd.h"

namespace iec::cli {

void VcdTrace::begin(interp::Runtime &runtime)
{
    m_writer = interp::makeVcdWriter(out(), variables(), runtime.cycleNs(), QStringLiteral("iecstudio-cli run"));
    m_writer->begin(interp::captureRow(runtime, variables()));
}

void VcdTrace::sample(int, interp::Runtime &runtime)
{
    m_writer->write(interp::captureRow(runtime, variables()));
}

} // namespace iec::cli
