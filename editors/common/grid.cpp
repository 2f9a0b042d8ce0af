#include "editors/common/grid.h"

#include <cmath>

namespace iec::editors {

namespace {

double snap(double value, int gridSize)
{
    if (gridSize <= 1)
        return value;
    return std::round(value / gridSize) * gridSize;
}

} // namespace

QPointF snapToGrid(QPointF point, int gridSize)
{
    return {snap(point.x(), gridSize), snap(point.y(), gridSize)};
}

QRectF snapToGrid(const QRectF &rect, int gridSize)
{
    // The size snaps too, so that every pin of a snapped box lands on the grid.
    return {snapToGrid(rect.topLeft(), gridSize),
            QSizeF(std::max<double>(gridSize, snap(rect.width(), gridSize)),
                   std::max<double>(gridSize, snap(rect.height(), gridSize)))};
}

} // namespace iec::editors
