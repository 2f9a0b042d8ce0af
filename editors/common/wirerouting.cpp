#include "editors/common/wirerouting.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <vector>

namespace iec::editors {

namespace {

// A bend costs as much as this much wire, so the router prefers a short detour to an extra corner.
constexpr double kBendCost = 40;
constexpr double kCentreBias = 1e-5;

enum Direction { East, West, North, South, DirectionCount };

// Candidate x and y lines of a sparse orthogonal grid: the pins' stubs and the outlines of the
// obstacles grown by the clearance. A shortest orthogonal path around rectangles always runs on
// such lines, so searching them is enough and stays small.
struct RoutingGrid {
    std::vector<double> xs;
    std::vector<double> ys;
    QList<QRectF> blocked;
    double centreX = 0;

    [[nodiscard]] int width() const { return int(xs.size()); }
    [[nodiscard]] int height() const { return int(ys.size()); }
    [[nodiscard]] int node(int ix, int iy) const { return iy * width() + ix; }
};

void sortUnique(std::vector<double> &values)
{
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end(),
                             [](double a, double b) { return std::abs(a - b) < 1e-6; }),
                 values.end());
}

bool pointBlocked(const QList<QRectF> &blocked, QPointF point)
{
    return std::any_of(blocked.begin(), blocked.end(), [&](const QRectF &rect) {
        return point.x() > rect.left() && point.x() < rect.right() && point.y() > rect.top()
            && point.y() < rect.bottom();
    });
}

// True when the axis-parallel segment a–b passes through the inside of any blocked rectangle.
bool segmentBlocked(const QList<QRectF> &blocked, QPointF a, QPointF b)
{
    return std::any_of(blocked.begin(), blocked.end(), [&](const QRectF &rect) {
        if (a.y() == b.y()) {
            const double left = std::min(a.x(), b.x());
            const double right = std::max(a.x(), b.x());
            return a.y() > rect.top() && a.y() < rect.bottom() && right > rect.left() && left < rect.right();
        }
        const double top = std::min(a.y(), b.y());
        const double bottom = std::max(a.y(), b.y());
        return a.x() > rect.left() && a.x() < rect.right() && bottom > rect.top() && top < rect.bottom();
    });
}

RoutingGrid buildGrid(const RouteRequest &request, QPointF start, QPointF goal)
{
    RoutingGrid grid;
    const double c = request.clearance;
    for (const QRectF &obstacle : request.obstacles) {
        // Grown a little less than the clearance, so lines at exactly `clearance` stay usable.
        const QRectF grown = obstacle.adjusted(-c + 0.5, -c + 0.5, c - 0.5, c - 0.5);
        grid.blocked << grown;
        grid.xs.insert(grid.xs.end(), {obstacle.left() - c, obstacle.right() + c});
        grid.ys.insert(grid.ys.end(), {obstacle.top() - c, obstacle.bottom() + c});
    }
    grid.xs.insert(grid.xs.end(), {start.x(), goal.x(), (start.x() + goal.x()) / 2});
    grid.ys.insert(grid.ys.end(), {start.y(), goal.y(), (start.y() + goal.y()) / 2});
    grid.centreX = (start.x() + goal.x()) / 2;
    sortUnique(grid.xs);
    sortUnique(grid.ys);
    return grid;
}

int indexOf(const std::vector<double> &values, double value)
{
    const auto it = std::lower_bound(values.begin(), values.end(), value - 1e-6);
    return int(it - values.begin());
}

// Dijkstra over (node, direction of arrival) so that bends can be charged.
QList<QPointF> searchPath(const RoutingGrid &grid, QPointF start, QPointF goal)
{
    const int nodeCount = grid.width() * grid.height();
    const int startNode = grid.node(indexOf(grid.xs, start.x()), indexOf(grid.ys, start.y()));
    const int goalNode = grid.node(indexOf(grid.xs, goal.x()), indexOf(grid.ys, goal.y()));
    const auto state = [](int node, int direction) { return node * DirectionCount + direction; };
    // One extra state stands for "entered the input pin": reaching the goal from above or below
    // costs one more bend there, reaching it westwards would double back and is not allowed.
    const int terminal = nodeCount * DirectionCount;
    std::vector<double> cost(std::size_t(terminal) + 1, std::numeric_limits<double>::infinity());
    std::vector<int> previous(cost.size(), -1);
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    // The wire leaves the output pin eastwards.
    cost[std::size_t(state(startNode, East))] = 0;
    open.push({0, state(startNode, East)});

    int reached = -1;
    while (!open.empty()) {
        const auto [currentCost, current] = open.top();
        open.pop();
        if (currentCost > cost[std::size_t(current)])
            continue;
        if (current == terminal) {
            reached = previous[std::size_t(terminal)];
            break;
        }
        const int node = current / DirectionCount;
        const int arrival = current % DirectionCount;
        if (node == goalNode && arrival != West) {
            const double entered = currentCost + (arrival == East ? 0 : kBendCost);
            if (entered < cost[std::size_t(terminal)]) {
                cost[std::size_t(terminal)] = entered;
                previous[std::size_t(terminal)] = current;
                open.push({entered, terminal});
            }
            continue;
        }
        const int ix = node % grid.width();
        const int iy = node / grid.width();
        const QPointF here(grid.xs[std::size_t(ix)], grid.ys[std::size_t(iy)]);
        static constexpr int dx[] = {1, -1, 0, 0};
        static constexpr int dy[] = {0, 0, -1, 1};
        for (int direction = 0; direction < DirectionCount; ++direction) {
            const int nx = ix + dx[direction];
            const int ny = iy + dy[direction];
            if (nx < 0 || ny < 0 || nx >= grid.width() || ny >= grid.height())
                continue;
            const QPointF there(grid.xs[std::size_t(nx)], grid.ys[std::size_t(ny)]);
            if (pointBlocked(grid.blocked, there) || segmentBlocked(grid.blocked, here, there))
                continue;
            double step = std::abs(there.x() - here.x()) + std::abs(there.y() - here.y());
            // Among routes of equal length and bends, prefer vertical runs near the middle
            // between the pins: wires then read as steps, not as hooks at one end.
            if (here.x() == there.x())
                step *= 1 + kCentreBias * std::abs(here.x() - grid.centreX);
            const double next = currentCost + step + (direction == arrival ? 0 : kBendCost);
            const int nextState = state(grid.node(nx, ny), direction);
            if (next < cost[std::size_t(nextState)]) {
                cost[std::size_t(nextState)] = next;
                previous[std::size_t(nextState)] = current;
                open.push({next, nextState});
            }
        }
    }
    QList<QPointF> path;
    for (int current = reached; current >= 0; current = previous[std::size_t(current)]) {
        const int node = current / DirectionCount;
        path.prepend(QPointF(grid.xs[std::size_t(node % grid.width())], grid.ys[std::size_t(node / grid.width())]));
    }
    return path;
}

// Used when the obstacles leave no way through: right, across at mid height, into the pin.
QList<QPointF> fallbackRoute(QPointF from, QPointF to)
{
    const double midX = (from.x() + to.x()) / 2;
    return {from, {midX, from.y()}, {midX, to.y()}, to};
}

} // namespace

QList<QPointF> simplifyPolyline(const QList<QPointF> &points)
{
    QList<QPointF> result;
    for (const QPointF &point : points) {
        if (!result.isEmpty() && result.last() == point)
            continue;
        if (result.size() >= 2) {
            const QPointF &a = result.at(result.size() - 2);
            const QPointF &b = result.last();
            const bool straight = (a.x() == b.x() && b.x() == point.x()) || (a.y() == b.y() && b.y() == point.y());
            if (straight)
                result.removeLast();
        }
        result << point;
    }
    return result;
}

std::optional<QList<QPointF>> tryRouteOrthogonal(const RouteRequest &request)
{
    // The stubs: the wire runs `clearance` straight out of the output and into the input.
    const QPointF start(request.from.x() + request.clearance, request.from.y());
    const QPointF goal(request.to.x() - request.clearance, request.to.y());
    const RoutingGrid grid = buildGrid(request, start, goal);
    QList<QPointF> middle = searchPath(grid, start, goal);
    if (middle.isEmpty())
        return std::nullopt;
    middle.prepend(request.from);
    middle.append(request.to);
    return simplifyPolyline(middle);
}

QList<QPointF> routeOrthogonal(const RouteRequest &request)
{
    if (auto route = tryRouteOrthogonal(request))
        return *std::move(route);
    return simplifyPolyline(fallbackRoute(request.from, request.to));
}

} // namespace iec::editors
