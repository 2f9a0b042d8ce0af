#pragma once

#include "model/graphics.h"

#include <QList>
#include <QPointF>

#include <optional>
#include <vector>

// Writing a layout into the elements (LD, FBD): points as PLCopen positions, a wire's corners as
// a connection's waypoints, and the offsets of pins.
namespace iec::editors {

model::Position toPosition(QPointF point);
// The waypoints of a wire drawn from its source to its target: PLCopen lists them from the input
// end (Beremiz draws them so).
std::vector<model::Position> waypointsFrom(const QList<QPointF> &sourceToTarget);
// The pin's offset from its element (the connection point is created when missing).
void setRelPosition(std::optional<model::ConnectionPointIn> &point, QPointF offset);
void setRelPosition(std::optional<model::ConnectionPointOut> &point, QPointF offset);

} // namespace iec::editors
