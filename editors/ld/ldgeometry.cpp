#include "editors/ld/ldgeometry.h"

#include "editors/ld/ldgraph.h"

#include <algorithm>
#include <cmath>

namespace iec::editors::ld {

using namespace model;
using namespace geometry;

namespace {

QString variableOf(const Element &e)
{
    if (const auto *contact = std::get_if<Contact>(&e))
        return contact->variable;
    if (const auto *coil = std::get_if<Coil>(&e))
        return coil->variable;
    if (const auto *out = std::get_if<OutVariable>(&e))
        return out->expression;
    if (const auto *in = std::get_if<InVariable>(&e))
        return in->expression;
    if (const auto *jump = std::get_if<Jump>(&e))
        return jump->label;
    return {};
}

// A box's pin rows: rung pin first, the others in their order.
int rowOf(int pin, int rungPin)
{
    if (rungPin < 0 || pin == rungPin)
        return rungPin < 0 ? pin : 0;
    return pin < rungPin ? pin + 1 : pin;
}

double variableWidth(const QString &text)
{
    return std::max(40.0, textWidth(text) + 12);
}

} // namespace

QSizeF boxSize(const Block &block)
{
    const double width = boxWidth(block);
    const std::size_t rows = std::max(block.inputVariables.size() + block.inOutVariables.size(), block.outputVariables.size());
    return {width, kBoxTitle + double(std::max<std::size_t>(rows, 1)) * kPinPitch};
}

int boxInputRow(const Block &, int pin, const RungPins &rungPins)
{
    return rowOf(pin, rungPins.input);
}

int boxOutputRow(const Block &, int pin, const RungPins &rungPins)
{
    return rowOf(pin, rungPins.output);
}

QPointF inputPinOffset(const Element &element, int pin, const RungPins &rungPins)
{
    if (const auto *block = std::get_if<Block>(&element))
        return {0, kBoxTitle + boxInputRow(*block, pin, rungPins) * kPinPitch + kPinPitch / 2};
    const ElementHeader &h = header(element);
    return {0, h.height.value_or(kSymbolHeight) / 2};
}

QPointF outputPinOffset(const Element &element, int pin, const RungPins &rungPins)
{
    const ElementHeader &h = header(element);
    if (const auto *block = std::get_if<Block>(&element))
        return {h.width.value_or(boxSize(*block).width()), kBoxTitle + boxOutputRow(*block, pin, rungPins) * kPinPitch + kPinPitch / 2};
    return {h.width.value_or(kSymbolWidth), h.height.value_or(kSymbolHeight) / 2};
}

namespace {

// One end of the wires that enter or leave a laid-out node: the element, its pin, and the path
// between the node's boundary on its main line and the pin.
struct Port {
    quint64 id = 0;
    int pin = 0;
    QList<QPointF> path; // entries: boundary first; exits: pin first
};

struct Placed {
    std::vector<Port> entries;
    std::vector<Port> exits;
};

// Sizes of a node before it is placed; children mirror the rung's children.
struct Measure {
    double width = 0;
    double height = 0;
    double line = 0; // the main line, from the node's top
    bool output = false; // ends the rung on the right (an output, or branches of outputs)
    std::vector<Measure> children;
};

class RungLayout
{
public:
    // The wires a rung's layout follows stay inside its network, so its graph holds only the
    // network's own elements: laying out every network of a large body stays linear in its size.
    RungLayout(const LadderDocument &document, const LdNetwork &network, NetworkGeometry &geometry)
        : m_document(document)
        , m_elements(membersOf(document, network))
        , m_graph(m_elements)
        , m_geometry(geometry)
    {
        m_indexOf.reserve(m_elements.size());
        for (std::size_t i = 0; i < m_elements.size(); ++i)
            m_indexOf.emplace(header(m_elements[i]).localId, i);
    }

    Measure measure(const RungNode &node) const
    {
        Measure m;
        if (node.isElement())
            return measureElement(node.localId);
        for (const RungNode &child : node.children)
            m.children.push_back(measure(child));
        if (node.kind == RungNode::Kind::Series) {
            for (const Measure &c : m.children)
                m.line = std::max(m.line, c.line);
            for (std::size_t i = 0; i < m.children.size(); ++i) {
                const Measure &c = m.children[i];
                m.width += c.width + (i ? kWire : 0);
                m.height = std::max(m.height, m.line - c.line + c.height);
            }
            m.output = !m.children.empty() && m.children.back().output;
            return m;
        }
        for (std::size_t i = 0; i < m.children.size(); ++i) {
            const Measure &c = m.children[i];
            m.width = std::max(m.width, c.width + 2 * kBranchPad);
            m.height += c.height + (i ? kRowGap : 0);
        }
        m.line = m.children.empty() ? 0 : m.children.front().line;
        m.output = std::ranges::all_of(m.children, [](const Measure &c) { return c.output; });
        return m;
    }

    // Places a series with its left boundary at x and its top at `top`, stretched to `width`:
    // the room left over goes before the outputs at its end, so coils line up on the right.
    // `lead`/`tail` are the stubs before the first and after the last child (the main rung's
    // wires to the rails); a parallel first or last in the main rung uses the rail as its link.
    Placed placeSeries(const RungNode &node, const Measure &m, double x, double top, double width, std::vector<int> &path,
        bool mainRung)
    {
        const double line = top + m.line;
        const std::size_t n = node.children.size();
        if (n == 0) {
            m_geometry.wirePoints.push_back({path, 0, QPointF(x + kWire, line)});
            return {};
        }
        const bool leftRail = mainRung && node.children.front().kind == RungNode::Kind::Parallel;
        const bool rightRail = mainRung && node.children.back().kind == RungNode::Kind::Parallel;
        const double lead = mainRung && !leftRail ? kWire : 0;
        const double tail = mainRung && !rightRail ? kWire : 0;
        std::size_t tailStart = n;
        while (tailStart > 0 && m.children[tailStart - 1].output)
            --tailStart;
        const double extra = std::max(0.0, width - m.width - lead - tail);
        Placed placed;
        std::vector<Port> previous;
        double cx = x + lead;
        for (std::size_t i = 0; i < n; ++i) {
            if (i == tailStart)
                cx += extra;
            const Measure &c = m.children[i];
            const double childTop = line - c.line;
            path.push_back(int(i));
            Placed child;
            if (node.children[i].kind == RungNode::Kind::Parallel)
                child = placeParallel(node.children[i], c, cx, childTop,
                    rightRail && i == n - 1 ? x + width - cx : c.width, path, leftRail && i == 0, rightRail && i == n - 1);
            else
                child = placeNode(node.children[i], c, cx, childTop, path);
            path.pop_back();
            const double pointX = i > 0 ? cx - kWire / 2 : (mainRung ? x + lead / 2 : x - kBranchPad / 2);
            m_geometry.wirePoints.push_back({path, int(i), QPointF(pointX, line)});
            if (i == 0)
                placed.entries = withStart(child.entries, x, leftRail);
            else
                connect(previous, child.entries);
            previous = std::move(child.exits);
            cx += c.width + kWire;
        }
        const double right = x + width;
        m_geometry.wirePoints.push_back({path, int(n), QPointF(cx - kWire / 2, line)});
        for (Port &exit : previous) {
            if (!rightRail)
                exit.path << QPointF(right, line);
            placed.exits.push_back(std::move(exit));
        }
        return placed;
    }

    void finish() { simplifyAll(); }

private:
    static std::vector<Port> withStart(std::vector<Port> ports, double x, bool railLink)
    {
        for (Port &port : ports) {
            if (!railLink)
                port.path.prepend(QPointF(x, port.path.front().y()));
        }
        return ports;
    }

    void connect(const std::vector<Port> &exits, const std::vector<Port> &entries)
    {
        for (const Port &exit : exits) {
            for (const Port &entry : entries) {
                WireRun run {exit.id, exit.pin, entry.id, entry.pin, exit.path + entry.path};
                m_geometry.wires.push_back(std::move(run));
            }
        }
    }

    Placed placeParallel(const RungNode &node, const Measure &m, double x, double top, double width, std::vector<int> &path,
        bool leftRail, bool rightRail)
    {
        Placed placed;
        const double line = top + m.line;
        double branchTop = top;
        for (std::size_t b = 0; b < node.children.size(); ++b) {
            const Measure &c = m.children[b];
            path.push_back(int(b));
            Placed branch = placeSeries(node.children[b], c, x + kBranchPad, branchTop, width - 2 * kBranchPad, path, false);
            path.pop_back();
            const double branchLine = branchTop + c.line;
            for (Port &entry : branch.entries) {
                if (leftRail)
                    entry.path.prepend(QPointF(x, branchLine));
                else
                    entry.path = QList<QPointF> {QPointF(x, line), QPointF(x, branchLine)} + entry.path;
                placed.entries.push_back(std::move(entry));
            }
            for (Port &exit : branch.exits) {
                exit.path << QPointF(x + width, branchLine);
                if (!rightRail)
                    exit.path << QPointF(x + width, line);
                placed.exits.push_back(std::move(exit));
            }
            branchTop += c.height + kRowGap;
        }
        return placed;
    }

    Placed placeNode(const RungNode &node, const Measure &m, double x, double top, std::vector<int> &path)
    {
        if (node.kind == RungNode::Kind::Series)
            return placeSeries(node, m, x, top, m.width, path, false);
        return placeElement(node.localId, m, x, top);
    }

    // ---- elements

    const Element &elementOf(quint64 id) const
    {
        const auto local = m_indexOf.find(id);
        return local != m_indexOf.end() ? m_elements[local->second] : *m_document.element(id);
    }

    static std::vector<Element> membersOf(const LadderDocument &document, const LdNetwork &network)
    {
        std::vector<Element> members;
        members.reserve(network.members.size());
        for (quint64 id : network.members)
            if (const Element *e = document.element(id))
                members.push_back(*e);
        return members;
    }

    Measure measureElement(quint64 id) const
    {
        const Element &e = elementOf(id);
        Measure m;
        m.output = isOutput(e);
        switch (rungRole(e)) {
        case RungRole::Contact:
        case RungRole::Coil:
            m.width = std::max(kSymbolWidth, textWidth(variableOf(e))) + 2 * kCellPad;
            m.height = kNameHeight + kSymbolHeight;
            m.line = kNameHeight + kSymbolHeight / 2;
            break;
        case RungRole::Box: {
            const auto &block = std::get<Block>(e);
            const SideSizes sides = measureSides(id, block);
            const QSizeF box = boxSize(block);
            m.width = sides.left + box.width() + sides.right;
            m.line = kNameHeight + kBoxTitle + kPinPitch / 2;
            m.height = kNameHeight + std::max(box.height(), sides.height);
            break;
        }
        case RungRole::Jump:
        case RungRole::Return:
        case RungRole::Assignment:
        case RungRole::Other:
            m.width = symbolWidth(e);
            m.height = kNameHeight + kSymbolHeight;
            m.line = kNameHeight + kSymbolHeight / 2;
            break;
        }
        return m;
    }

    static double symbolWidth(const Element &e)
    {
        switch (rungRole(e)) {
        case RungRole::Jump: return roundUp(textWidth(variableOf(e)) + 30, 10);
        case RungRole::Return: return roundUp(textWidth(QStringLiteral("RETURN")) + 16, 10);
        case RungRole::Assignment: return roundUp(variableWidth(variableOf(e)), 10);
        default: return kSymbolWidth;
        }
    }

    // What hangs on a box's other pins.
    struct SideSizes {
        double left = 0;   // variables and operator boxes on the inputs, with their wires
        double right = 0;  // assignments on the outputs
        double height = 0; // how far down they reach below the box's top
    };

    SideSizes measureSides(quint64 id, const Block &block) const
    {
        SideSizes sides;
        const RungPins pins = m_document.pinsOf(id);
        const auto local = m_indexOf.find(id);
        if (local == m_indexOf.end())
            return sides;
        const std::size_t index = local->second;
        for (const LdGraph::Wire &wire : m_graph.inputs(index)) {
            if (wire.pin == pins.input)
                continue;
            const QSizeF size = sideTreeSize(wire.source, 0);
            sides.left = std::max(sides.left, size.width() + kSideGap);
            const double row = kBoxTitle + rowOf(wire.pin, pins.input) * kPinPitch + kPinPitch / 2;
            sides.height = std::max(sides.height, row + size.height() / 2);
        }
        for (std::size_t p = 0; p < block.outputVariables.size(); ++p) {
            if (int(p) == pins.output)
                continue;
            if (const auto &out = block.outputVariables[p].connectionPointOut; out && out->expression)
                sides.right = std::max(sides.right, textWidth(*out->expression) + 10);
        }
        for (const LdGraph::Reader &reader : m_graph.readers(index)) {
            if (reader.sourcePin == pins.output || !std::holds_alternative<OutVariable>(m_graph.element(reader.target)))
                continue;
            sides.right = std::max(sides.right, variableWidth(variableOf(m_graph.element(reader.target))) + kSideGap);
        }
        return sides;
    }

    // A variable, or an operator box with what hangs on its own inputs.
    QSizeF sideTreeSize(std::size_t index, int depth) const
    {
        const Element &e = m_graph.element(index);
        const auto *block = std::get_if<Block>(&e);
        if (!block || depth > 16)
            return {roundUp(variableWidth(variableOf(e)), 10), kVariableHeight};
        double left = 0;
        double height = 0;
        for (const LdGraph::Wire &wire : m_graph.inputs(index)) {
            const QSizeF size = sideTreeSize(wire.source, depth + 1);
            left = std::max(left, size.width() + kSideGap);
            height += size.height() + kRowGap;
        }
        const QSizeF box = boxSize(*block);
        return {left + box.width(), std::max(box.height(), height)};
    }

    Placed placeElement(quint64 id, const Measure &m, double x, double top)
    {
        const Element &e = elementOf(id);
        const double line = top + m.line;
        Placed placed;
        if (const auto *block = std::get_if<Block>(&e)) {
            const RungPins pins = m_document.pinsOf(id);
            const SideSizes sides = measureSides(id, *block);
            const QSizeF box = boxSize(*block);
            const QRectF rect(x + sides.left, top + kNameHeight, box.width(), box.height());
            m_geometry.rects[id] = rect;
            if (const auto local = m_indexOf.find(id); local != m_indexOf.end())
                placeSides(local->second, pins, rect);
            if (pins.input >= 0)
                placed.entries.push_back({id, pins.input, {QPointF(x, line), QPointF(rect.left(), pinY(rect, 0))}});
            if (pins.output >= 0)
                placed.exits.push_back({id, pins.output, {QPointF(rect.right(), pinY(rect, 0)), QPointF(x + m.width, line)}});
            return placed;
        }
        // Contacts sit in the middle of their cell, coils at its right end, so that parallel
        // coils line up at the right rail whatever their names.
        const RungRole role = rungRole(e);
        const double width = role == RungRole::Contact || role == RungRole::Coil ? kSymbolWidth : symbolWidth(e);
        const double left = role == RungRole::Contact ? x + (m.width - width) / 2
            : role == RungRole::Coil                  ? x + m.width - kCellPad - width
                                                      : x;
        const QRectF rect(left, line - kSymbolHeight / 2, width, kSymbolHeight);
        m_geometry.rects[id] = rect;
        placed.entries.push_back({id, 0, {QPointF(x, line), QPointF(rect.left(), line)}});
        if (role == RungRole::Contact || role == RungRole::Coil)
            placed.exits.push_back({id, 0, {QPointF(rect.right(), line), QPointF(x + m.width, line)}});
        return placed;
    }

    // Side inputs to the left of their pins (stacked downwards where they would overlap), side
    // assignments to the right.
    static double pinY(const QRectF &box, int row) { return box.top() + kBoxTitle + row * kPinPitch + kPinPitch / 2; }

    void placeSides(std::size_t index, const RungPins &pins, const QRectF &rect)
    {
        double nextFree = -1e9;
        const quint64 id = header(m_graph.element(index)).localId;
        std::vector<LdGraph::Wire> wires = m_graph.inputs(index);
        std::ranges::sort(wires, [&](const auto &a, const auto &b) { return rowOf(a.pin, pins.input) < rowOf(b.pin, pins.input); });
        for (const LdGraph::Wire &wire : wires) {
            if (wire.pin == pins.input)
                continue;
            const QSizeF size = sideTreeSize(wire.source, 0);
            const double y = pinY(rect, rowOf(wire.pin, pins.input));
            const double treeTop = std::max(y - kVariableHeight / 2, nextFree);
            const QPointF out = placeSideTree(wire.source, QPointF(rect.left() - kSideGap - size.width(), treeTop), 0);
            m_geometry.wires.push_back({m_graph.localId(wire.source), wire.sourcePin, id, wire.pin, orthogonal(out, QPointF(rect.left(), y))});
            nextFree = treeTop + size.height() + kRowGap;
        }
        for (const LdGraph::Reader &reader : m_graph.readers(index)) {
            if (reader.sourcePin == pins.output || !std::holds_alternative<OutVariable>(m_graph.element(reader.target)))
                continue;
            const double y = pinY(rect, rowOf(reader.sourcePin, pins.output));
            const double width = roundUp(variableWidth(variableOf(m_graph.element(reader.target))), 10);
            const QRectF target(rect.right() + kSideGap, y - kVariableHeight / 2, width, kVariableHeight);
            m_geometry.rects[m_graph.localId(reader.target)] = target;
            m_geometry.wires.push_back({id, reader.sourcePin, m_graph.localId(reader.target), 0,
                {QPointF(rect.right(), y), QPointF(target.left(), y)}});
        }
    }

    // Places a side tree with its top-left at `at`; returns its output pin.
    QPointF placeSideTree(std::size_t index, QPointF at, int depth)
    {
        const Element &e = m_graph.element(index);
        const quint64 id = header(e).localId;
        const QSizeF size = sideTreeSize(index, depth);
        const auto *block = std::get_if<Block>(&e);
        if (!block || depth > 16) {
            const QRectF rect(at, QSizeF(size.width(), kVariableHeight));
            m_geometry.rects[id] = rect;
            return {rect.right(), rect.center().y()};
        }
        const QSizeF box = boxSize(*block);
        const QRectF rect(at.x() + size.width() - box.width(), at.y(), box.width(), box.height());
        m_geometry.rects[id] = rect;
        double nextFree = at.y();
        for (const LdGraph::Wire &wire : m_graph.inputs(index)) {
            const QSizeF child = sideTreeSize(wire.source, depth + 1);
            const double y = pinY(rect, wire.pin);
            const double childTop = std::max(y - child.height() / 2, nextFree);
            const QPointF out = placeSideTree(wire.source, QPointF(rect.left() - kSideGap - child.width(), childTop), depth + 1);
            m_geometry.wires.push_back({m_graph.localId(wire.source), wire.sourcePin, id, wire.pin, orthogonal(out, QPointF(rect.left(), y))});
            nextFree = childTop + child.height() + kRowGap;
        }
        return {rect.right(), rect.top() + kBoxTitle + kPinPitch / 2};
    }

    static QList<QPointF> orthogonal(QPointF from, QPointF to)
    {
        if (qFuzzyCompare(from.y() + 1, to.y() + 1))
            return {from, to};
        const double middle = (from.x() + to.x()) / 2;
        return {from, QPointF(middle, from.y()), QPointF(middle, to.y()), to};
    }

    void simplifyAll()
    {
        for (WireRun &run : m_geometry.wires) {
            QList<QPointF> points;
            for (const QPointF &p : std::as_const(run.points)) {
                if (!points.isEmpty() && points.back() == p)
                    continue;
                if (points.size() >= 2) {
                    const QPointF a = points[points.size() - 2];
                    const QPointF b = points.back();
                    if ((a.x() == b.x() && b.x() == p.x()) || (a.y() == b.y() && b.y() == p.y()))
                        points.removeLast();
                }
                points << p;
            }
            run.points = points;
        }
    }

    const LadderDocument &m_document;
    std::vector<Element> m_elements; // the network's members, in file order
    LdGraph m_graph;
    NetworkGeometry &m_geometry;
    std::unordered_map<quint64, std::size_t> m_indexOf;
};

QStringList commentLines(const Element &e)
{
    const auto &comment = std::get<Comment>(e);
    QString text = comment.content.text;
    return text.isEmpty() ? QStringList() : text.split(QLatin1Char('\n'));
}

// Header lines above the rung: the label, then the comment.
double layoutHeader(const LadderDocument &document, const LdNetwork &network, NetworkGeometry &g, double y)
{
    const double width = g.rightRailX - kRailX;
    if (network.label) {
        g.labelRect = QRectF(kRailX, y, width, kHeaderLine);
        y += kHeaderLine;
    }
    if (network.comment) {
        if (const Element *e = document.element(network.comment)) {
            const double lines = std::max<qsizetype>(1, commentLines(*e).size());
            g.commentRect = QRectF(kRailX, y, width, lines * kHeaderLine);
            y += lines * kHeaderLine;
        }
    }
    return y;
}

// A network drawn freehand: its elements where they are, moved as a whole below the header.
void measureFreehand(const LadderDocument &document, const LdNetwork &network, NetworkGeometry &g)
{
    QRectF box;
    for (quint64 id : network.members) {
        if (id == network.label || id == network.comment || id == network.title)
            continue;
        const Element *e = document.element(id);
        const ElementHeader &h = header(*e);
        const QRectF rect(h.position.x, h.position.y, h.width.value_or(20), h.height.value_or(20));
        g.rects[id] = rect;
        box = box.isNull() ? rect : box.united(rect);
        for (const ConnectionPointIn *point : inputPoints(*e))
            for (const Connection &c : point->connections)
                for (const Position &p : c.waypoints)
                    box = box.united(QRectF(p.x, p.y, 0.1, 0.1));
    }
    g.rightRailX = std::max(kRailX + kMinRungWidth, roundUp(box.right() + kWire, kWidthStep));
    g.rungHeight = std::max(kSymbolHeight, box.height());
    g.lineY = g.rungTop + kNameHeight + kSymbolHeight / 2;
    g.freehandShift = g.rungTop - box.top();
    for (auto &[id, rect] : g.rects)
        rect.translate(0, g.freehandShift);
}

} // namespace

NetworkGeometry layoutNetwork(const LadderDocument &document, std::size_t index, double top)
{
    const LdNetwork &network = document.networks[index];
    NetworkGeometry g;
    g.top = top;
    RungLayout layout(document, network, g);
    Measure measure;
    if (!network.freehand) {
        measure = layout.measure(network.rung);
        const bool railParallels = !network.rung.children.empty();
        const double stubs = railParallels ? 2 * kWire : 0;
        g.rightRailX = kRailX + std::max(kMinRungWidth, roundUp(measure.width + stubs, kWidthStep));
    } else
        g.rightRailX = kRailX + kMinRungWidth;
    const double rungTop = layoutHeader(document, network, g, top + kNetworkPad);
    g.rungTop = rungTop;
    if (network.freehand) {
        measureFreehand(document, network, g);
    } else {
        std::vector<int> path;
        g.rungHeight = std::max(measure.height, kNameHeight + kSymbolHeight);
        g.lineY = rungTop + (network.rung.children.empty() ? kNameHeight + kSymbolHeight / 2 : measure.line);
        Placed placed = layout.placeSeries(network.rung, measure, kRailX, rungTop, g.rightRailX - kRailX, path, true);
        for (Port &entry : placed.entries) {
            entry.path.prepend(QPointF(kRailX, entry.path.front().y()));
            g.wires.push_back({network.leftRail, 0, entry.id, entry.pin, entry.path});
        }
        int railPin = 0;
        for (Port &exit : placed.exits) {
            exit.path << QPointF(g.rightRailX, exit.path.back().y());
            g.wires.push_back({exit.id, exit.pin, network.rightRail, railPin++, exit.path});
        }
        layout.finish();
    }
    g.height = (rungTop - top) + g.rungHeight + kNetworkPad;
    return g;
}

std::vector<NetworkGeometry> layoutLadder(const LadderDocument &document)
{
    std::vector<NetworkGeometry> result;
    result.reserve(document.networks.size());
    double top = 0;
    for (std::size_t n = 0; n < document.networks.size(); ++n) {
        result.push_back(layoutNetwork(document, n, top));
        top += result.back().height;
    }
    return result;
}

} // namespace iec::editors::ld
