#include "interpreter/sfc/sfcstatus.h"

#include "interpreter/runtime/runtime.h"

namespace iec::interp::sfc {

// Placeholder until the SFC engine lands.
std::optional<ChartState> chartState(const Runtime &runtime, const model::Pou &pou, const QString &instancePath)
{
    Q_UNUSED(runtime);
    Q_UNUSED(pou);
    Q_UNUSED(instancePath);
    return std::nullopt;
}

std::vector<ChartState> programChartStates(const Runtime &runtime, const model::Project &project)
{
    Q_UNUSED(runtime);
    Q_UNUSED(project);
    return {};
}

} // namespace iec::interp::sfc
