#include "editors/common/zoomsteps.h"

#include <algorithm>
#include <array>

namespace iec::editors {

namespace {

constexpr std::array<double, 11> kSteps{0.25, 0.33, 0.5, 0.67, 0.75, 1.0, 1.25, 1.5, 2.0, 3.0, 4.0};
// A factor within this distance of a step counts as that step, so fit-to-window results that land
// a hair off a step do not make the next click a no-op.
constexpr double kTolerance = 1e-3;

} // namespace

double minimumZoom() { return kSteps.front(); }
double maximumZoom() { return kSteps.back(); }

double clampZoom(double factor)
{
    return std::clamp(factor, minimumZoom(), maximumZoom());
}

double nextZoomIn(double current)
{
    for (const double step : kSteps) {
        if (step > current + kTolerance)
            return step;
    }
    return maximumZoom();
}

double nextZoomOut(double current)
{
    for (auto it = kSteps.rbegin(); it != kSteps.rend(); ++it) {
        if (*it < current - kTolerance)
            return *it;
    }
    return minimumZoom();
}

} // namespace iec::editors
