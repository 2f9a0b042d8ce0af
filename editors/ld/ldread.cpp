// Reading the networks of an LD body: which elements form a network, and whether its power flow
// is a series-parallel rung (then the editor lays it out and edits it structurally) or a graph
// drawn freehand (then it is shown as drawn).
#include "editors/ld/ldgraph.h"
#include "editors/ld/ldnetwork.h"
#include "editors/ld/ldtree.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <numeric>
#include <optional>
#include <set>

namespace iec::editors::ld {

using namespace model;

namespace {

// ---- which elements form a network

// Elements that belong to a network by where they are, not by wires: its comment, its label,
// CODESYS's network title and branch markers, a rail that carries no wire yet.
bool isLoose(const LdGraph &graph, std::size_t i)
{
    const Element &e = graph.element(i);
    if (std::holds_alternative<Comment>(e) || std::holds_alternative<Label>(e))
        return true;
    if (const auto *vendor = std::get_if<VendorElement>(&e))
        return !vendor->inputVariables && !vendor->outputVariables && !vendor->inOutVariables;
    if (graph.isRail(i))
        return graph.inputs(i).empty() && graph.readers(i).empty();
    return false;
}

// One network in the making: the elements wired together (the anchor) and the loose ones placed
// with it.
struct Unit {
    std::vector<std::size_t> members;
    double top = 0;
    double bottom = 0;
    std::size_t firstIndex = 0;
};

class UnionFind
{
public:
    explicit UnionFind(std::size_t size)
        : m_parent(size)
    {
        std::iota(m_parent.begin(), m_parent.end(), std::size_t(0));
    }
    std::size_t find(std::size_t i)
    {
        while (m_parent[i] != i) {
            m_parent[i] = m_parent[m_parent[i]];
            i = m_parent[i];
        }
        return i;
    }
    void unite(std::size_t a, std::size_t b) { m_parent[find(a)] = find(b); }

private:
    std::vector<std::size_t> m_parent;
};

// Groups the wired elements: wires join elements, except through power rails, which several
// networks may share (Beremiz draws one left rail for all; CODESYS writes one for the body).
std::vector<Unit> wiredUnits(const LdGraph &graph)
{
    const std::size_t count = graph.size();
    UnionFind groups(count);
    const auto shared = [&](std::size_t i) { return graph.isRail(i) && !isNetworkRail(graph.element(i)); };
    for (std::size_t i = 0; i < count; ++i) {
        if (shared(i))
            continue;
        for (const LdGraph::Wire &wire : graph.inputs(i)) {
            if (!shared(wire.source))
                groups.unite(i, wire.source);
        }
    }
    std::map<std::size_t, Unit> byRoot;
    for (std::size_t i = 0; i < count; ++i) {
        if (shared(i) || isLoose(graph, i))
            continue;
        Unit &unit = byRoot[groups.find(i)];
        if (unit.members.empty())
            unit.firstIndex = i;
        unit.members.push_back(i);
    }
    // A rail that carries no wire stands for an empty network of its own (the editor's new
    // networks); rails with wires join every network they feed or end.
    std::vector<Unit> units;
    std::map<std::size_t, std::size_t> unitOfRoot;
    for (auto &[root, unit] : byRoot) {
        unitOfRoot[root] = units.size();
        units.push_back(std::move(unit));
    }
    for (std::size_t i = 0; i < count; ++i) {
        if (!shared(i) || isLoose(graph, i))
            continue;
        std::set<std::size_t> joined;
        for (const LdGraph::Wire &wire : graph.inputs(i))
            if (!graph.isRail(wire.source))
                joined.insert(unitOfRoot[groups.find(wire.source)]);
        for (const LdGraph::Reader &reader : graph.readers(i))
            if (!graph.isRail(reader.target))
                joined.insert(unitOfRoot[groups.find(reader.target)]);
        for (std::size_t u : joined)
            units[u].members.push_back(i);
    }
    for (std::size_t i = 0; i < count; ++i) {
        if (graph.isRail(i) && isLoose(graph, i) && std::holds_alternative<LeftPowerRail>(graph.element(i)))
            units.push_back(Unit {{i}, 0, 0, i});
    }
    for (Unit &unit : units) {
        std::ranges::sort(unit.members);
        unit.firstIndex = unit.members.front();
        // A shared rail spans every network it feeds: the network's own elements give its band,
        // or the comments between the networks would all fall into the first one.
        std::vector<std::size_t> own;
        std::ranges::copy_if(unit.members, std::back_inserter(own), [&](std::size_t i) { return !shared(i); });
        const std::vector<std::size_t> &extent = own.empty() ? unit.members : own;
        unit.top = graph.top(extent);
        unit.bottom = graph.bottom(extent);
    }
    return units;
}

// Free coordinates: networks top to bottom; a loose element belongs to the network whose band
// (from the bottom of the one above to its own bottom) holds it. What lies below the last
// network forms an empty network of its own (a label at the end, a new network's rails).
std::vector<Unit> placeByPosition(const LdGraph &graph, std::vector<Unit> units, const std::vector<std::size_t> &loose)
{
    std::ranges::stable_sort(units, [](const Unit &a, const Unit &b) {
        return std::tie(a.top, a.firstIndex) < std::tie(b.top, b.firstIndex);
    });
    std::optional<Unit> trailing;
    for (std::size_t i : loose) {
        const double y = graph.position(i).y;
        auto it = std::ranges::find_if(units, [&](const Unit &unit) { return y <= unit.bottom; });
        if (it != units.end()) {
            it->members.push_back(i);
            continue;
        }
        if (!trailing)
            trailing = Unit {{}, y, y, i};
        trailing->members.push_back(i);
    }
    if (trailing)
        units.push_back(std::move(*trailing));
    return units;
}

// Positions made up on import (CODESYS): networks in file order; a network's comment, label and
// title come before its elements, so a loose element joins the next network in the file.
std::vector<Unit> placeByFileOrder(const LdGraph &graph, std::vector<Unit> units, const std::vector<std::size_t> &loose)
{
    std::ranges::sort(units, [](const Unit &a, const Unit &b) { return a.firstIndex < b.firstIndex; });
    std::vector<Unit> result;
    Unit pending;
    std::size_t next = 0;
    const auto kindOf = [&](std::size_t i) { return graph.element(i).index(); };
    const auto flushPending = [&] {
        if (!pending.members.empty())
            result.push_back(std::move(pending));
        pending = Unit {};
    };
    for (std::size_t i : loose) {
        while (next < units.size() && units[next].firstIndex < i) {
            Unit unit = std::move(units[next++]);
            unit.members.insert(unit.members.end(), pending.members.begin(), pending.members.end());
            pending = Unit {};
            result.push_back(std::move(unit));
        }
        // A second comment (or title, label) before any wired element starts the next network.
        const bool repeats = std::ranges::any_of(pending.members, [&](std::size_t m) { return kindOf(m) == kindOf(i); });
        if (repeats)
            flushPending();
        if (pending.members.empty())
            pending.firstIndex = i;
        pending.members.push_back(i);
    }
    for (; next < units.size(); ++next) {
        Unit unit = std::move(units[next]);
        unit.members.insert(unit.members.end(), pending.members.begin(), pending.members.end());
        pending = Unit {};
        result.push_back(std::move(unit));
    }
    flushPending();
    return result;
}

// ---- the rung of one network

// A rung element between two points of the power flow: from the point its power comes from to
// the point it passes power to (END for outputs that feed nothing).
struct Edge {
    std::size_t from = 0;
    std::size_t to = 0;
    RungNode node;
    double rank = 0; // where the edge is drawn: orders parallel branches top to bottom
    bool alive = true;
};

void appendFlattened(std::vector<RungNode> &into, RungNode node, RungNode::Kind kind)
{
    if (node.kind == kind) {
        for (RungNode &child : node.children)
            into.push_back(std::move(child));
    } else
        into.push_back(std::move(node));
}

// Reduces the two-terminal graph of edges to one START→END edge by merging parallel edges and
// edges in series. Returns nullopt when the graph is not series-parallel.
std::optional<RungNode> reduceSeriesParallel(std::vector<Edge> edges, std::size_t start, std::size_t end)
{
    if (edges.empty())
        return RungNode::series();
    for (bool changed = true; changed;) {
        changed = false;
        // Edges between the same two points are branches of one parallel.
        std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> byEnds;
        for (std::size_t e = 0; e < edges.size(); ++e)
            if (edges[e].alive)
                byEnds[{edges[e].from, edges[e].to}].push_back(e);
        for (auto &[ends, group] : byEnds) {
            if (group.size() < 2)
                continue;
            std::ranges::stable_sort(group, [&](std::size_t a, std::size_t b) { return edges[a].rank < edges[b].rank; });
            std::vector<RungNode> branches;
            for (std::size_t e : group) {
                appendFlattened(branches, std::move(edges[e].node), RungNode::Kind::Parallel);
                edges[e].alive = false;
            }
            Edge merged {ends.first, ends.second, RungNode::parallel(std::move(branches)), edges[group.front()].rank};
            edges.push_back(std::move(merged));
            changed = true;
        }
        // A point with one edge in and one edge out joins the two in series.
        std::map<std::size_t, std::vector<std::size_t>> into;
        std::map<std::size_t, std::vector<std::size_t>> outOf;
        for (std::size_t e = 0; e < edges.size(); ++e) {
            if (!edges[e].alive)
                continue;
            into[edges[e].to].push_back(e);
            outOf[edges[e].from].push_back(e);
        }
        for (auto &[point, ins] : into) {
            if (point == start || point == end || ins.size() != 1 || outOf[point].size() != 1)
                continue;
            Edge &first = edges[ins.front()];
            Edge &second = edges[outOf[point].front()];
            if (!first.alive || !second.alive || &first == &second)
                continue;
            std::vector<RungNode> chain;
            appendFlattened(chain, std::move(first.node), RungNode::Kind::Series);
            appendFlattened(chain, std::move(second.node), RungNode::Kind::Series);
            Edge merged {first.from, second.to, RungNode::series(std::move(chain)), std::min(first.rank, second.rank)};
            first.alive = false;
            second.alive = false;
            edges.push_back(std::move(merged));
            changed = true;
            break; // the maps are stale now
        }
    }
    std::vector<const Edge *> left;
    for (const Edge &edge : edges)
        if (edge.alive)
            left.push_back(&edge);
    if (left.size() != 1 || left.front()->from != start || left.front()->to != end)
        return std::nullopt;
    RungNode rung = left.front()->node;
    tree::normalize(rung); // branches are series, a lone element is a series of one
    return rung;
}

class RungReader
{
public:
    RungReader(const LdGraph &graph, const std::vector<std::size_t> &members, bool layoutGenerated)
        : m_graph(graph)
        , m_members(members)
        , m_layoutGenerated(layoutGenerated)
    { }

    // The rung, or nullopt when the network is not one.
    std::optional<RungNode> read(std::unordered_map<quint64, RungPins> &boxPins)
    {
        if (!findPowerFlow() || !checkTheRest())
            return std::nullopt;
        std::optional<RungNode> rung = reduce();
        if (rung) {
            for (const auto &[i, pins] : m_pins)
                boxPins[m_graph.localId(i)] = pins;
        }
        return rung;
    }

private:
    bool isMember(std::size_t i) const { return std::ranges::binary_search(m_members, i); }

    // Follows the power from the left rails: every element it reaches, and the pins of boxes.
    bool findPowerFlow()
    {
        std::vector<std::size_t> queue;
        for (std::size_t i : m_members)
            if (std::holds_alternative<LeftPowerRail>(m_graph.element(i)))
                queue.push_back(i);
        std::set<std::size_t> seen(queue.begin(), queue.end());
        while (!queue.empty()) {
            const std::size_t source = queue.back();
            queue.pop_back();
            const int sourcePin = outputPinOf(source);
            for (const LdGraph::Reader &reader : m_graph.readers(source)) {
                if (!isMember(reader.target) || std::holds_alternative<RightPowerRail>(m_graph.element(reader.target)))
                    continue;
                if (std::holds_alternative<Block>(m_graph.element(source)) && reader.sourcePin != sourcePin)
                    continue; // a side output: an assignment, checked below
                const RungRole role = rungRole(m_graph.element(reader.target));
                if (role == RungRole::Other)
                    return false; // power into a variable, a connector...
                if (role == RungRole::Box) {
                    RungPins &pins = m_pins[reader.target];
                    if (pins.input >= 0 && pins.input != reader.pin)
                        return false; // a box fed by two rungs
                    pins.input = reader.pin;
                }
                m_flow.insert(reader.target);
                if (seen.insert(reader.target).second)
                    queue.push_back(reader.target);
            }
        }
        for (auto &[box, pins] : m_pins)
            pins.output = outputPinOf(box);
        return !m_flow.empty() || std::ranges::none_of(m_members, [&](std::size_t i) { return isWired(i); });
    }

    bool isWired(std::size_t i) const { return !m_graph.inputs(i).empty() || !m_graph.readers(i).empty(); }

    // The output a box passes power on: the one that feeds rung elements, else ENO, else its first
    // output when its first input is in the rung (TON's Q); -1 for a box that ends the rung.
    int outputPinOf(std::size_t i) const
    {
        const auto *block = std::get_if<Block>(&m_graph.element(i));
        if (!block)
            return 0;
        std::set<int> feeding;
        for (const LdGraph::Reader &reader : m_graph.readers(i)) {
            const RungRole role = rungRole(m_graph.element(reader.target));
            const bool rail = std::holds_alternative<RightPowerRail>(m_graph.element(reader.target));
            if (rail || (role != RungRole::Other && role != RungRole::Assignment))
                feeding.insert(reader.sourcePin);
        }
        if (feeding.size() == 1)
            return *feeding.begin();
        if (feeding.size() > 1)
            return -2; // two rungs leave the box: not a rung
        for (std::size_t p = 0; p < block->outputVariables.size(); ++p)
            if (block->outputVariables[p].formalParameter.compare(QLatin1String("ENO"), Qt::CaseInsensitive) == 0)
                return int(p);
        const auto pins = m_pins.find(i);
        if (pins != m_pins.end() && pins->second.input == 0 && !block->outputVariables.empty())
            return 0;
        return -1;
    }

    // Every member is a rung element, a rail, a label/comment, or a variable on a box's side pin.
    bool checkTheRest()
    {
        for (const auto &[box, pins] : m_pins) {
            if (pins.output == -2 || !checkSides(box, pins, 0))
                return false;
        }
        for (std::size_t i : m_members) {
            if (m_flow.contains(i) || m_side.contains(i) || m_graph.isRail(i) || isLoose(m_graph, i))
                continue;
            return false;
        }
        // Rung elements take power only from the rung.
        for (std::size_t i : m_flow) {
            for (const LdGraph::Wire &wire : m_graph.inputs(i)) {
                if (std::holds_alternative<Block>(m_graph.element(i)) && wire.pin != m_pins[i].input)
                    continue;
                if (!m_flow.contains(wire.source) && !std::holds_alternative<LeftPowerRail>(m_graph.element(wire.source)))
                    return false;
            }
        }
        return true;
    }

    // A box's other pins: inputs from variables (or operator boxes fed by variables, CoDeSys's
    // "insert at blocks"), outputs to assignments. Each side element serves that one pin.
    bool checkSides(std::size_t box, const RungPins &pins, int depth)
    {
        if (depth > 32)
            return false;
        for (const LdGraph::Wire &wire : m_graph.inputs(box)) {
            if (depth == 0 && wire.pin == pins.input)
                continue;
            if (!isMember(wire.source) || m_flow.contains(wire.source) || m_graph.readers(wire.source).size() != 1)
                return false;
            const Element &source = m_graph.element(wire.source);
            if (std::holds_alternative<Block>(source)) {
                if (!checkSides(wire.source, RungPins {-1, 0}, depth + 1))
                    return false;
            } else if (!std::holds_alternative<InVariable>(source))
                return false;
            m_side.insert(wire.source);
        }
        for (const LdGraph::Reader &reader : m_graph.readers(box)) {
            if (depth == 0 && reader.sourcePin == pins.output)
                continue;
            if (depth > 0)
                continue; // an operator box's output feeds the pin it serves
            if (!std::holds_alternative<OutVariable>(m_graph.element(reader.target)) || m_graph.inputs(reader.target).size() != 1)
                return false;
            m_side.insert(reader.target);
        }
        return true;
    }

    std::optional<RungNode> reduce()
    {
        // Points of the power flow: START, then an "in" and an "out" point per rung element.
        const std::size_t start = 0;
        std::vector<std::size_t> flow(m_flow.begin(), m_flow.end());
        std::map<std::size_t, std::size_t> slot;
        for (std::size_t k = 0; k < flow.size(); ++k)
            slot[flow[k]] = k;
        UnionFind points(1 + 2 * flow.size());
        const auto in = [&](std::size_t i) { return 1 + 2 * slot[i]; };
        const auto out = [&](std::size_t i) { return 2 + 2 * slot[i]; };
        std::map<std::size_t, std::set<std::size_t>> sourcesOf; // element -> its rung sources (rails as SIZE_MAX)
        constexpr std::size_t kRail = std::numeric_limits<std::size_t>::max();
        for (std::size_t i : flow) {
            for (const LdGraph::Wire &wire : m_graph.inputs(i)) {
                if (std::holds_alternative<Block>(m_graph.element(i)) && wire.pin != m_pins[i].input)
                    continue;
                const bool rail = std::holds_alternative<LeftPowerRail>(m_graph.element(wire.source));
                points.unite(in(i), rail ? start : out(wire.source));
                sourcesOf[i].insert(rail ? kRail : wire.source);
            }
        }
        // Wired OR: every element fed from one point must be fed by all that meet there.
        std::map<std::size_t, std::set<std::size_t>> meeting;
        meeting[points.find(start)].insert(kRail);
        for (std::size_t i : flow)
            if (hasOutput(i))
                meeting[points.find(out(i))].insert(i);
        for (std::size_t i : flow)
            if (sourcesOf[i] != meeting[points.find(in(i))])
                return std::nullopt;
        // Outputs that feed nothing end the rung; so does a wire into the right rail.
        std::set<std::size_t> fedPoints;
        for (std::size_t i : flow)
            fedPoints.insert(points.find(in(i)));
        const std::size_t end = 1 + 2 * flow.size() + 1;
        std::vector<Edge> edges;
        for (std::size_t i : flow) {
            std::size_t to = end;
            if (hasOutput(i) && fedPoints.contains(points.find(out(i)))) {
                to = points.find(out(i));
                if (feedsRightRail(i))
                    return std::nullopt; // power leaves to the rail and on into the rung
            }
            edges.push_back(Edge {points.find(in(i)), to, RungNode::element(m_graph.localId(i)), rank(i)});
        }
        return reduceSeriesParallel(std::move(edges), points.find(start), end);
    }

    bool hasOutput(std::size_t i) const
    {
        const RungRole role = rungRole(m_graph.element(i));
        if (role == RungRole::Box)
            return m_pins.at(i).output >= 0;
        return role == RungRole::Contact || role == RungRole::Coil;
    }

    bool feedsRightRail(std::size_t i) const
    {
        return std::ranges::any_of(m_graph.readers(i),
            [&](const LdGraph::Reader &r) { return std::holds_alternative<RightPowerRail>(m_graph.element(r.target)); });
    }

    double rank(std::size_t i) const
    {
        return m_layoutGenerated ? double(i) : m_graph.position(i).y * 1e6 + m_graph.position(i).x;
    }

    const LdGraph &m_graph;
    const std::vector<std::size_t> &m_members;
    bool m_layoutGenerated;
    std::set<std::size_t> m_flow;
    std::set<std::size_t> m_side;
    std::map<std::size_t, RungPins> m_pins;
};

LdNetwork makeNetwork(const LdGraph &graph, Unit unit, bool layoutGenerated, std::unordered_map<quint64, RungPins> &boxPins)
{
    std::ranges::sort(unit.members);
    LdNetwork network;
    for (std::size_t i : unit.members) {
        const Element &e = graph.element(i);
        const quint64 id = graph.localId(i);
        network.members.push_back(id);
        if (std::holds_alternative<LeftPowerRail>(e) && !network.leftRail)
            network.leftRail = id;
        else if (std::holds_alternative<RightPowerRail>(e) && !network.rightRail)
            network.rightRail = id;
        else if (std::holds_alternative<Label>(e) && !network.label)
            network.label = id;
        else if (std::holds_alternative<Comment>(e) && !network.comment)
            network.comment = id;
        else if (std::holds_alternative<VendorElement>(e) && !network.title && isLoose(graph, i))
            network.title = id;
    }
    RungReader reader(graph, unit.members, layoutGenerated);
    if (std::optional<RungNode> rung = reader.read(boxPins))
        network.rung = std::move(*rung);
    else
        network.freehand = true;
    return network;
}

} // namespace

LadderDocument readLadder(std::vector<Element> elements, bool layoutGenerated)
{
    LadderDocument document;
    document.elements = std::move(elements);
    document.reindex();
    const LdGraph graph(document.elements);
    std::vector<std::size_t> loose;
    for (std::size_t i = 0; i < graph.size(); ++i)
        if (isLoose(graph, i) && !std::holds_alternative<LeftPowerRail>(graph.element(i)))
            loose.push_back(i);
    std::vector<Unit> units = wiredUnits(graph);
    units = layoutGenerated ? placeByFileOrder(graph, std::move(units), loose) : placeByPosition(graph, std::move(units), loose);
    for (Unit &unit : units)
        document.networks.push_back(makeNetwork(graph, std::move(unit), layoutGenerated, document.boxPins));
    return document;
}

} // namespace iec::editors::ld
