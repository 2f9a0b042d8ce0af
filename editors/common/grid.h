#pragma once

#include <QPointF>
#include <QRectF>

namespace iec::editors {

// Grid snapping for every diagram editor. The grid size comes from the settings; positions in
// the model are in the file's units, which the editors draw 1:1.
QPointF snapToGrid(QPointF point, int gridSize);
QRectF snapToGrid(const QRectF &rect, int gridSize);

} // namespace iec::editors
