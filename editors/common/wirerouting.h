#pragma once

#include <QList>
#include <QPointF>
#include <QRectF>

#include <optional>

namespace iec::editors {

struct RouteRequest {
    QPointF from;           // an output pin: the wire leaves it to the right
    QPointF to;             // an input pin: the wire enters it from the left
    QList<QRectF> obstacles; // boxes the wire must not cross (the two pins' own boxes included)
    double clearance = 10;   // distance kept from boxes, and the stub length at both pins
};

// An orthogonal route from `from` to `to` that avoids the obstacles, with as few bends and as
// little length as it can: the polyline's points, first `from`, last `to`, every segment
// horizontal or vertical, no two consecutive segments in line. The CFC editor routes every wire
// with it; FBD and LD use it for connections their layouts do not draw themselves.
QList<QPointF> routeOrthogonal(const RouteRequest &request);
// The same route, or nullopt when the obstacles leave no way (routeOrthogonal then falls back to
// a route through them; CFC draws the wire straight and red instead).
std::optional<QList<QPointF>> tryRouteOrthogonal(const RouteRequest &request);

// Removes repeated points and points in the middle of a straight run.
QList<QPointF> simplifyPolyline(const QList<QPointF> &points);

} // namespace iec::editors
