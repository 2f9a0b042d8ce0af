// The cursor of the FBD editor: where it is drawn, where the arrow keys and clicks put it, and
// whether it still stands after an undo (editors/fbd/fbdedits.h).
#include "editors/fbd/fbdedits.h"

#include <cmath>

namespace iec::editors::fbd {

using namespace model;
using Kind = FbdCursor::Kind;

namespace {

const CursorSpot *spotOf(const std::vector<FbdGeometry> &layout, const FbdCursor &cursor)
{
    if (cursor.network < 0 || cursor.network >= int(layout.size()))
        return nullptr;
    for (const CursorSpot &spot : layout[std::size_t(cursor.network)].spots)
        if (spot.cursor == cursor)
            return &spot;
    return nullptr;
}

} // namespace

std::optional<QRectF> cursorRect(const std::vector<FbdGeometry> &layout, const FbdCursor &cursor)
{
    if (const CursorSpot *spot = spotOf(layout, cursor))
        return spot->rect;
    return std::nullopt;
}

FbdCursor moveCursor(const std::vector<FbdGeometry> &layout, const FbdCursor &cursor, int dx, int dy)
{
    if (layout.empty())
        return FbdCursor::atNetwork(0);
    const int network = std::clamp(cursor.network, 0, int(layout.size()) - 1);
    const CursorSpot *from = spotOf(layout, cursor);
    const QPointF origin = from ? from->rect.center() : QPointF(0, layout[std::size_t(network)].top + 10);
    // The nearest spot in the direction: along it counts once, across it three times, so the
    // cursor stays on its line where it can; up and down may leave the network.
    const CursorSpot *best = nullptr;
    double bestCost = 0;
    const int firstNetwork = dy != 0 ? std::max(0, network - 1) : network;
    const int lastNetwork = dy != 0 ? std::min(int(layout.size()) - 1, network + 1) : network;
    for (int n = firstNetwork; n <= lastNetwork; ++n) {
        for (const CursorSpot &spot : layout[std::size_t(n)].spots) {
            const QPointF delta = spot.rect.center() - origin;
            const double along = dx ? delta.x() * dx : delta.y() * dy;
            const double across = std::abs(dx ? delta.y() : delta.x());
            if (along <= 1 || spot.cursor == cursor)
                continue;
            const double cost = along + 3 * across;
            if (!best || cost < bestCost) {
                best = &spot;
                bestCost = cost;
            }
        }
    }
    return best ? best->cursor : cursor;
}

std::optional<FbdCursor> cursorAt(const std::vector<FbdGeometry> &layout, QPointF point)
{
    for (std::size_t n = 0; n < layout.size(); ++n) {
        const FbdGeometry &g = layout[n];
        if (point.y() < g.top || point.y() >= g.top + g.height)
            continue;
        const CursorSpot *best = nullptr;
        for (const CursorSpot &spot : g.spots) {
            if (!spot.rect.adjusted(-2, -2, 2, 2).contains(point))
                continue;
            const double area = spot.rect.width() * spot.rect.height();
            if (!best || area < best->rect.width() * best->rect.height())
                best = &spot;
        }
        return best ? best->cursor : FbdCursor::atNetwork(int(n));
    }
    return std::nullopt;
}

FbdCursor validCursor(const FbdDocument &document, const FbdCursor &cursor)
{
    const int count = int(document.networks.size());
    if (count == 0)
        return FbdCursor::atNetwork(0);
    const int network = std::clamp(cursor.network, 0, count - 1);
    if (cursor.kind == Kind::Network || cursor.kind == Kind::End)
        return {cursor.kind, network, 0, 0};
    const Element *e = document.element(cursor.element);
    if (!e || document.networkOf(cursor.element) != cursor.network)
        return FbdCursor::atNetwork(network);
    if (cursor.kind == Kind::Input && cursor.pin >= inputCount(*e))
        return FbdCursor::at(Kind::Box, network, cursor.element);
    if (cursor.kind == Kind::Output && cursor.pin >= outputCount(*e))
        return FbdCursor::atNetwork(network);
    return cursor;
}

} // namespace iec::editors::fbd
