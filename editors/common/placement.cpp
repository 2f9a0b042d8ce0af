#include "editors/common/placement.h"

namespace iec::editors {

using namespace model;

Position toPosition(QPointF point)
{
    return {point.x(), point.y()};
}

std::vector<Position> waypointsFrom(const QList<QPointF> &sourceToTarget)
{
    std::vector<Position> points;
    for (qsizetype i = sourceToTarget.size() - 1; i >= 0; --i)
        points.push_back(toPosition(sourceToTarget[i]));
    return points;
}

void setRelPosition(std::optional<ConnectionPointIn> &point, QPointF offset)
{
    if (!point)
        point.emplace();
    point->relPosition = toPosition(offset);
}

void setRelPosition(std::optional<ConnectionPointOut> &point, QPointF offset)
{
    if (!point)
        point.emplace();
    point->relPosition = toPosition(offset);
}

} // namespace iec::editors
