// Moving the LD cursor with the arrow keys: along the rung through elements and the wire points
// between them, and between networks.
#include "editors/ld/ldedits.h"

#include <cmath>
#include <optional>

namespace iec::editors::ld {

namespace {

// A place the cursor can stand in a network, with where it is drawn.
struct Stop {
    LdCursor cursor;
    QPointF at;
};

std::vector<Stop> stopsOf(const LadderDocument &document, const NetworkGeometry &g, int network)
{
    std::vector<Stop> stops;
    const LdNetwork &net = document.networks[std::size_t(network)];
    for (const auto &[id, rect] : g.rects) {
        if (id == net.leftRail || id == net.rightRail)
            continue;
        stops.push_back({LdCursor::atElement(network, id), rect.center()});
    }
    for (const WirePoint &point : g.wirePoints)
        stops.push_back({LdCursor::atWire(network, point), point.position});
    // A stable order, so equal costs pick the same stop every time.
    std::ranges::sort(stops, [](const Stop &a, const Stop &b) {
        return std::tuple(a.at.y(), a.at.x()) < std::tuple(b.at.y(), b.at.x());
    });
    return stops;
}

std::optional<QPointF> positionOf(const LdCursor &cursor, const NetworkGeometry &g)
{
    if (cursor.kind == LdCursor::Kind::Element) {
        const auto it = g.rects.find(cursor.element());
        if (it != g.rects.end())
            return it->second.center();
    }
    if (cursor.kind == LdCursor::Kind::Wire) {
        for (const WirePoint &point : g.wirePoints)
            if (point == cursor.wire)
                return point.position;
    }
    return std::nullopt;
}

// The nearest stop in the direction (dx, dy): along the direction counts once, across it three
// times, so the cursor stays on its line where it can.
std::optional<Stop> nearest(const std::vector<Stop> &stops, QPointF from, int dx, int dy)
{
    std::optional<Stop> best;
    double bestCost = 0;
    for (const Stop &stop : stops) {
        const QPointF delta = stop.at - from;
        const double along = dx ? delta.x() * dx : delta.y() * dy;
        const double across = std::abs(dx ? delta.y() : delta.x());
        if (along <= 1)
            continue;
        const double cost = along + 3 * across;
        if (!best || cost < bestCost) {
            best = stop;
            bestCost = cost;
        }
    }
    return best;
}

// Where the cursor lands when it enters a network: the first stop on its main line.
LdCursor entryOf(const LadderDocument &document, const std::vector<NetworkGeometry> &layout, int network)
{
    const NetworkGeometry &g = layout[std::size_t(network)];
    const std::vector<Stop> stops = stopsOf(document, g, network);
    const auto from = QPointF(0, g.lineY);
    if (const auto stop = nearest(stops, from, 1, 0))
        return stop->cursor;
    return LdCursor::atNetwork(network);
}

} // namespace

LdCursor moveCursor(const LadderDocument &document, const std::vector<NetworkGeometry> &layout, const LdCursor &cursor,
    int dx, int dy)
{
    const int count = int(document.networks.size());
    if (count == 0 || int(layout.size()) != count)
        return LdCursor::atNetwork(0);
    const int network = std::clamp(cursor.network, 0, count - 1);
    if (cursor.kind == LdCursor::Kind::Network) {
        if (dy < 0)
            return LdCursor::atNetwork(std::max(0, network - 1));
        if (dx > 0 || dy > 0)
            return dy > 0 && layout[std::size_t(network)].rects.size() <= 2 ? LdCursor::atNetwork(std::min(count - 1, network + 1))
                                                                             : entryOf(document, layout, network);
        return cursor;
    }
    const NetworkGeometry &g = layout[std::size_t(network)];
    const std::optional<QPointF> from = positionOf(cursor, g);
    if (!from)
        return LdCursor::atNetwork(network);
    if (const auto stop = nearest(stopsOf(document, g, network), *from, dx, dy))
        return stop->cursor;
    // Off the network's edge: up and left to the network itself, down to the next one.
    if (dy > 0 && network + 1 < count)
        return LdCursor::atNetwork(network + 1);
    if (dy < 0 || dx < 0)
        return LdCursor::atNetwork(network);
    return cursor;
}

} // namespace iec::editors::ld
