#include "editors/fbd/fbdlayout.h"

#include "editors/common/textmetrics.h"

#include <algorithm>

namespace iec::editors::fbd {

using namespace model;
using namespace layout;

namespace {

// What a node needs, in rows relative to its top row.
struct Measure {
    int rows = 1;
    std::vector<int> outputRows; // the row of each output
    // A box: its instance name row (0 or 1), its input pin rows (relative to the first pin row),
    // and where each input's branch starts (relative to the node's top).
    int instanceRows = 0;
    int boxRows = 1;
    std::vector<int> pinRows;
    std::vector<int> branchTops;
};

class Layouter
{
public:
    Layouter(const FbdDocument &document, const FbdNetwork &network, FbdGeometry &g, double treeTop)
        : m_document(document)
        , m_network(network)
        , m_g(g)
        , m_treeTop(treeTop)
    {
        for (quint64 id : network.members) {
            const Element *e = document.element(id);
            if (!e)
                continue;
            for (int pin = 0; pin < inputCount(*e); ++pin) {
                if (const auto source = sourceOf(document, id, pin)) {
                    if (isSink(*e))
                        m_sinks[key(*source)].push_back(id);
                    else
                        m_mainOutput[source->element] = source->pin;
                }
            }
        }
    }

    // Lays out the tree; returns the rows it takes.
    int run()
    {
        const quint64 root = m_network.root;
        const Measure &m = measure(root);
        place(root, 0, 0);
        // The root's outputs: a crossing line, then the assignments, jumps and returns stacked.
        const QRectF rootRect = m_g.rects[root];
        const double crossX = rootRect.right() + kCrossing;
        const double sinkX = crossX + 10;
        int nextRow = 0;
        double right = rootRect.right() + kCrossing;
        for (int out = 0; out < int(m.outputRows.size()); ++out) {
            const auto it = m_sinks.find(key({root, out}));
            if (it == m_sinks.end())
                continue;
            const double outY = rowMiddle(m.outputRows[std::size_t(out)]);
            for (quint64 sink : it->second) {
                const int row = std::max(m.outputRows[std::size_t(out)], nextRow);
                nextRow = row + 1;
                const QSizeF size = sinkOrVariableSize(*m_document.element(sink));
                const QRectF rect(sinkX, rowTop(row), size.width(), size.height());
                m_g.rects[sink] = rect;
                const double y = rowMiddle(row);
                QList<QPointF> points {QPointF(rootRect.right(), outY)};
                if (y != outY)
                    points << QPointF(crossX, outY) << QPointF(crossX, y);
                points << QPointF(sinkX, y);
                m_g.wires.push_back({root, out, sink, 0, points});
                m_g.spots.push_back({FbdCursor::at(FbdCursor::Kind::Crossing, m_index, sink), QRectF(crossX - 5, y - 6, 14, 12)});
                addSinkSpot(sink, rect);
                right = std::max(right, rect.right());
            }
        }
        const double endY = rowMiddle(m.outputRows.empty() ? 0 : m.outputRows.front());
        m_g.end = QPointF(right + 16, endY);
        m_g.spots.push_back({FbdCursor::at(FbdCursor::Kind::End, m_index), QRectF(m_g.end.x() - 6, endY - 6, 12, 12)});
        return std::max(m.rows, nextRow);
    }

    void setIndex(int index) { m_index = index; }

    // Moves everything placed so that the leftmost element starts at kLeft.
    void shiftToLeft()
    {
        double left = 0;
        bool any = false;
        for (const auto &[id, rect] : m_g.rects) {
            left = any ? std::min(left, rect.left()) : rect.left();
            any = true;
        }
        const double dx = kLeft - left;
        for (auto &[id, rect] : m_g.rects)
            rect.translate(dx, 0);
        for (FbdWire &wire : m_g.wires)
            for (QPointF &p : wire.points)
                p.rx() += dx;
        for (CursorSpot &spot : m_g.spots)
            spot.rect.translate(dx, 0);
        m_g.end.rx() += dx;
    }

private:
    static quint64 key(Port port) { return port.element * 64 + quint64(std::clamp(port.pin, 0, 63)); }
    double rowTop(int row) const { return m_treeTop + row * kRow; }
    double rowMiddle(int row) const { return rowTop(row) + kRow / 2; }

    bool isChild(const std::optional<Port> &source) const
    {
        return source && m_document.element(source->element) && isNode(*m_document.element(source->element));
    }

    const std::vector<quint64> &sinksOn(Port port) const
    {
        static const std::vector<quint64> none;
        const auto it = m_sinks.find(key(port));
        return it == m_sinks.end() ? none : it->second;
    }

    const Measure &measure(quint64 id)
    {
        if (const auto it = m_measures.find(id); it != m_measures.end())
            return it->second;
        Measure m;
        const Element &e = *m_document.element(id);
        if (const auto *block = std::get_if<Block>(&e)) {
            m.instanceRows = block->instanceName ? 1 : 0;
            const int firstPin = m.instanceRows + 1;
            int nextPin = firstPin;
            int used = 0;
            const int pins = inputCount(e);
            m.branchTops.assign(std::size_t(pins), 0);
            for (int pin = 0; pin < pins; ++pin) {
                const auto source = sourceOf(m_document, id, pin);
                int row = nextPin;
                if (isChild(source)) {
                    const Measure &child = measure(source->element);
                    const int out = child.outputRows.empty() ? 0 : child.outputRows[std::size_t(std::clamp(source->pin, 0, int(child.outputRows.size()) - 1))];
                    row = std::max(nextPin, used + out);
                    m.branchTops[std::size_t(pin)] = row - out;
                    used = row - out + child.rows;
                }
                m.pinRows.push_back(row - firstPin);
                nextPin = row + 1;
            }
            const int outputs = int(block->outputVariables.size());
            for (int out = 0; out < outputs; ++out)
                m.outputRows.push_back(firstPin + out);
            m.boxRows = 1 + std::max({nextPin - firstPin, outputs, 1});
            m.rows = std::max(used, m.instanceRows + m.boxRows);
        } else if (std::holds_alternative<InOutVariable>(e)) {
            // An in-out variable sits on the wire from the branch that feeds it (Beremiz draws
            // "Cnt1 := CounterST0.OUT" so, then reads Cnt1 on).
            m.outputRows = {0};
            m.branchTops = {0};
            m.pinRows = {0};
            if (const auto source = sourceOf(m_document, id, 0); isChild(source)) {
                const Measure &child = measure(source->element);
                const int out = child.outputRows.empty() ? 0 : child.outputRows[std::size_t(std::clamp(source->pin, 0, int(child.outputRows.size()) - 1))];
                m.outputRows = {out};
                m.pinRows = {out};
                m.rows = std::max(1, child.rows);
            }
        } else {
            m.outputRows = {0};
        }
        // Assignments on outputs other than the one that leads on are stacked beside them.
        if (id != m_network.root) {
            const int main = mainOutputOf(id);
            for (int out = 0; out < int(m.outputRows.size()); ++out)
                if (out != main)
                    m.rows = std::max(m.rows, m.outputRows[std::size_t(out)] + int(sinksOn({id, out}).size()));
        }
        return m_measures[id] = std::move(m);
    }

    int mainOutputOf(quint64 id) const
    {
        const auto it = m_mainOutput.find(id);
        return it == m_mainOutput.end() ? -1 : it->second;
    }

    // The room between a branch and the pin it feeds: the wire, the assignments on it, the
    // assignments on the branch's other outputs.
    double gapAfter(quint64 child, int mainPin) const
    {
        double inline_ = 0;
        for (quint64 sink : sinksOn({child, mainPin}))
            inline_ += sinkOrVariableSize(*m_document.element(sink)).width() + 10;
        double other = 0;
        const Element &e = *m_document.element(child);
        for (int out = 0; out < outputCount(e); ++out)
            if (out != mainPin)
                for (quint64 sink : sinksOn({child, out}))
                    other = std::max(other, sinkOrVariableSize(*m_document.element(sink)).width() + 20);
        return std::max({kGap, inline_ + kGap, other + 10});
    }

    void addSinkSpot(quint64 sink, const QRectF &rect)
    {
        const Element &e = *m_document.element(sink);
        if (!std::holds_alternative<Return>(e))
            m_g.spots.push_back({FbdCursor::at(FbdCursor::Kind::Text, m_index, sink), rect});
    }

    // Places the node with its right edge at `right` and its top on row `top`.
    void place(quint64 id, double right, int top)
    {
        const Measure &m = m_measures.at(id);
        const Element &e = *m_document.element(id);
        QRectF rect;
        if (const auto *block = std::get_if<Block>(&e)) {
            const double width = boxWidth(*block);
            rect = QRectF(right - width, rowTop(top + m.instanceRows), width, m.boxRows * kRow);
            m_g.inputRows[id] = m.pinRows;
            std::vector<int> outputRows;
            for (int out = 0; out < int(m.outputRows.size()); ++out)
                outputRows.push_back(out);
            m_g.outputRows[id] = outputRows;
            m_g.spots.push_back({FbdCursor::at(FbdCursor::Kind::Box, m_index, id), rect});
            if (block->instanceName)
                m_g.spots.push_back({FbdCursor::at(FbdCursor::Kind::Text, m_index, id),
                    QRectF(rect.center().x() - 50, rect.top() - 17, 100, 15)});
            for (int pin = 0; pin < int(m.pinRows.size()); ++pin) {
                const int row = top + m.instanceRows + 1 + m.pinRows[std::size_t(pin)];
                const double y = rowMiddle(row);
                m_g.spots.push_back({FbdCursor::at(FbdCursor::Kind::Input, m_index, id, pin), QRectF(rect.left() - 12, y - 6, 12, 12)});
                const auto source = sourceOf(m_document, id, pin);
                if (!isChild(source))
                    continue;
                const double gap = gapAfter(source->element, source->pin);
                place(source->element, rect.left() - gap, top + m.branchTops[std::size_t(pin)]);
                const QRectF &child = m_g.rects.at(source->element);
                m_g.wires.push_back({source->element, source->pin, id, pin, {QPointF(child.right(), y), QPointF(rect.left(), y)}});
                placeInlineSinks(source->element, source->pin, child.right(), row);
            }
        } else {
            const QSizeF size = sinkOrVariableSize(e);
            const int row = top + m.outputRows.front();
            rect = QRectF(right - size.width(), rowTop(row), size.width(), size.height());
            m_g.spots.push_back({FbdCursor::at(FbdCursor::Kind::Text, m_index, id), rect});
            const auto source = std::holds_alternative<InOutVariable>(e) ? sourceOf(m_document, id, 0) : std::nullopt;
            if (isChild(source)) {
                m_g.rects[id] = rect; // the branch's wire ends here
                place(source->element, rect.left() - gapAfter(source->element, source->pin), top + m.branchTops.front());
                const QRectF &child = m_g.rects.at(source->element);
                const double y = rowMiddle(row);
                m_g.wires.push_back({source->element, source->pin, id, 0, {QPointF(child.right(), y), QPointF(rect.left(), y)}});
                placeInlineSinks(source->element, source->pin, child.right(), row);
            }
        }
        m_g.rects[id] = rect;
        for (int out = 0; out < int(m.outputRows.size()); ++out) {
            const double y = rowMiddle(top + m.outputRows[std::size_t(out)]);
            m_g.spots.push_back({FbdCursor::at(FbdCursor::Kind::Output, m_index, id, out), QRectF(rect.right(), y - 6, 12, 12)});
        }
        if (id != m_network.root)
            placeSideSinks(id, rect, top, m);
    }

    // Assignments on the output that leads on: on the wire, left to right.
    void placeInlineSinks(quint64 node, int pin, double from, int row)
    {
        double x = from + 10;
        for (quint64 sink : sinksOn({node, pin})) {
            const QSizeF size = sinkOrVariableSize(*m_document.element(sink));
            const QRectF rect(x, rowTop(row), size.width(), size.height());
            m_g.rects[sink] = rect;
            m_g.onWire.insert(sink);
            m_g.wires.push_back({node, pin, sink, 0, {QPointF(from, rowMiddle(row)), QPointF(x, rowMiddle(row))}});
            m_g.spots.push_back({FbdCursor::at(FbdCursor::Kind::Crossing, m_index, sink), QRectF(x - 10, rowMiddle(row) - 6, 10, 12)});
            addSinkSpot(sink, rect);
            x += size.width() + 10;
        }
    }

    // Assignments on an inner node's other outputs: beside them, stacked.
    void placeSideSinks(quint64 id, const QRectF &rect, int top, const Measure &m)
    {
        const int main = mainOutputOf(id);
        for (int out = 0; out < int(m.outputRows.size()); ++out) {
            if (out == main)
                continue;
            int row = top + m.outputRows[std::size_t(out)];
            const double outY = rowMiddle(row);
            for (quint64 sink : sinksOn({id, out})) {
                const QSizeF size = sinkOrVariableSize(*m_document.element(sink));
                const QRectF sinkRect(rect.right() + 20, rowTop(row), size.width(), size.height());
                m_g.rects[sink] = sinkRect;
                const double y = rowMiddle(row);
                QList<QPointF> points {QPointF(rect.right(), outY)};
                if (y != outY)
                    points << QPointF(rect.right() + 10, outY) << QPointF(rect.right() + 10, y);
                points << QPointF(sinkRect.left(), y);
                m_g.wires.push_back({id, out, sink, 0, points});
                m_g.spots.push_back({FbdCursor::at(FbdCursor::Kind::Crossing, m_index, sink), QRectF(sinkRect.left() - 10, y - 6, 10, 12)});
                addSinkSpot(sink, sinkRect);
                ++row;
            }
        }
    }

    const FbdDocument &m_document;
    const FbdNetwork &m_network;
    FbdGeometry &m_g;
    double m_treeTop;
    int m_index = 0;
    std::unordered_map<quint64, std::vector<quint64>> m_sinks; // by key(port), in file order
    std::unordered_map<quint64, int> m_mainOutput;             // a node's output read by a node
    std::unordered_map<quint64, Measure> m_measures;
};

QRectF drawnRect(const Element &e)
{
    const ElementHeader &h = header(e);
    QSizeF size(h.width.value_or(0), h.height.value_or(0));
    if (size.width() <= 0 || size.height() <= 0) {
        if (const auto *block = std::get_if<Block>(&e))
            size = QSizeF(boxWidth(*block), kRow * double(1 + std::max<std::size_t>({block->inputVariables.size() + block->inOutVariables.size(), block->outputVariables.size(), 1})));
        else
            size = sinkOrVariableSize(e);
    }
    return QRectF(QPointF(h.position.x, h.position.y), size);
}

// A network drawn by another tool as it is: its elements where they are, moved to `treeTop`.
double layoutFreehand(const FbdDocument &document, const FbdNetwork &network, int index, FbdGeometry &g, double treeTop)
{
    double minY = 0;
    double maxY = 0;
    bool any = false;
    for (quint64 id : network.members) {
        const Element &e = *document.element(id);
        if (id == network.label || id == network.comment)
            continue;
        const QRectF rect = drawnRect(e);
        minY = any ? std::min(minY, rect.top()) : rect.top();
        maxY = any ? std::max(maxY, rect.bottom()) : rect.bottom();
        any = true;
    }
    const double dy = treeTop - minY;
    for (quint64 id : network.members) {
        const Element &e = *document.element(id);
        if (id == network.label || id == network.comment)
            continue;
        const QRectF rect = drawnRect(e).translated(0, dy);
        g.rects[id] = rect;
        const auto kind = std::holds_alternative<Block>(e) ? FbdCursor::Kind::Box : FbdCursor::Kind::Text;
        g.spots.push_back({FbdCursor::at(kind, index, id), rect});
        g.width = std::max(g.width, rect.right());
        for (int pin = 0; pin < inputCount(e); ++pin) {
            const ConnectionPointIn *point = inputPoint(e, pin);
            if (!point)
                continue;
            for (const Connection &c : point->connections) {
                QList<QPointF> points;
                for (auto it = c.waypoints.rbegin(); it != c.waypoints.rend(); ++it)
                    points << QPointF(it->x, it->y + dy);
                if (points.size() < 2) {
                    const Element *source = document.element(c.refLocalId);
                    if (!source)
                        continue;
                    const QRectF from = drawnRect(*source).translated(0, dy);
                    points = {QPointF(from.right(), from.center().y()), QPointF(rect.left(), rect.center().y())};
                }
                const Element *source = document.element(c.refLocalId);
                g.wires.push_back({c.refLocalId, source ? std::max(0, outputPinIndex(*source, c.formalParameter)) : 0, id, pin, points});
            }
        }
    }
    return any ? maxY - minY : kRow;
}

} // namespace

FbdGeometry layoutNetwork(const FbdDocument &document, std::size_t index, double top)
{
    const FbdNetwork &network = document.networks[index];
    FbdGeometry g;
    g.top = top;
    double y = top + kNetworkPad;
    if (network.label) {
        g.labelRect = QRectF(kLeft, y, 300, kHeaderLine);
        g.spots.push_back({FbdCursor::atNetwork(int(index)), g.labelRect});
        y += kHeaderLine;
    }
    if (const Element *comment = network.comment ? document.element(network.comment) : nullptr) {
        const int lines = int(std::get<Comment>(*comment).content.text.count(QLatin1Char('\n'))) + 1;
        g.commentRect = QRectF(kLeft, y, 600, lines * kHeaderLine);
        y += lines * kHeaderLine;
    }
    if (network.label || network.comment)
        y += 6;
    const double treeTop = y + 16; // room for an instance name above the first row
    double treeHeight = kRow;
    if (network.freehand) {
        treeHeight = layoutFreehand(document, network, int(index), g, treeTop);
        g.end = QPointF(g.width + 16, treeTop + kRow / 2);
    } else if (network.root) {
        Layouter layouter(document, network, g, treeTop);
        layouter.setIndex(int(index));
        treeHeight = layouter.run() * kRow;
        layouter.shiftToLeft();
    } else {
        g.end = QPointF(kLeft + 6, treeTop + kRow / 2);
        g.spots.push_back({FbdCursor::at(FbdCursor::Kind::End, int(index)), QRectF(kLeft, treeTop + 4, 12, 12)});
    }
    for (const auto &[id, rect] : g.rects)
        g.width = std::max(g.width, rect.right());
    g.width = std::max({g.width + 40, g.end.x() + 20, kMinWidth});
    g.height = treeTop - top + treeHeight + kNetworkPad;
    g.spots.push_back({FbdCursor::atNetwork(int(index)), QRectF(0, top, 44, 20)});
    return g;
}

std::vector<FbdGeometry> layoutFbd(const FbdDocument &document)
{
    std::vector<FbdGeometry> layout;
    layout.reserve(document.networks.size());
    double top = 0;
    for (std::size_t n = 0; n < document.networks.size(); ++n) {
        layout.push_back(layoutNetwork(document, n, top));
        top += layout.back().height;
    }
    return layout;
}

FbdGeometry shifted(FbdGeometry g, double dy)
{
    if (dy == 0)
        return g;
    g.top += dy;
    for (auto &[id, rect] : g.rects)
        rect.translate(0, dy);
    for (FbdWire &wire : g.wires)
        for (QPointF &p : wire.points)
            p.ry() += dy;
    for (CursorSpot &spot : g.spots)
        spot.rect.translate(0, dy);
    g.labelRect.translate(0, dy);
    g.commentRect.translate(0, dy);
    g.end.ry() += dy;
    return g;
}

void renumber(FbdGeometry &g, int index)
{
    for (CursorSpot &spot : g.spots)
        spot.cursor.network = index;
}

} // namespace iec::editors::fbd
