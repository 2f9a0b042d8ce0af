#include "editors/fbd/fbdwrite.h"

#include "editors/common/placement.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace iec::editors::fbd {

using namespace model;
using namespace layout;

namespace {

// Position, size and pin positions of a placed element.
void place(Element &element, const QRectF &rect, const FbdGeometry &g)
{
    ElementHeader &h = header(element);
    h.position = toPosition(rect.topLeft());
    h.width = rect.width();
    h.height = rect.height();
    const double middle = rect.height() / 2;
    std::visit(
        [&](auto &e) {
            using T = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<T, Block>) {
                const auto rowsIn = g.inputRows.find(h.localId);
                const auto rowsOut = g.outputRows.find(h.localId);
                int pin = 0;
                for (auto *list : {&e.inputVariables, &e.inOutVariables}) {
                    for (BlockVariable &v : *list) {
                        const int row = rowsIn != g.inputRows.end() && pin < int(rowsIn->second.size()) ? rowsIn->second[std::size_t(pin)] : pin;
                        setRelPosition(v.connectionPointIn, QPointF(0, kRow + row * kRow + kRow / 2));
                        ++pin;
                    }
                }
                for (std::size_t out = 0; out < e.outputVariables.size(); ++out) {
                    const int row = rowsOut != g.outputRows.end() && out < rowsOut->second.size() ? rowsOut->second[out] : int(out);
                    setRelPosition(e.outputVariables[out].connectionPointOut, QPointF(rect.width(), kRow + row * kRow + kRow / 2));
                }
            } else {
                if constexpr (requires { e.connectionPointIn; })
                    setRelPosition(e.connectionPointIn, QPointF(0, middle));
                if constexpr (requires { e.connectionPointOut; })
                    setRelPosition(e.connectionPointOut, QPointF(rect.width(), middle));
            }
        },
        element);
}

// The tree's elements from its inputs to its outputs: each node after the branches that feed it,
// the sinks on a node's outputs right after it.
void treeOrder(const FbdDocument &document, const FbdNetwork &network, std::vector<quint64> &order)
{
    std::unordered_map<quint64, std::vector<quint64>> sinksOf;
    for (quint64 id : network.members)
        if (const Element *e = document.element(id); e && isSink(*e))
            if (const auto source = sourceOf(document, id, 0))
                sinksOf[source->element].push_back(id);
    // An explicit stack instead of recursion (kMaxTreeDepth bounds it anyway).
    struct Frame {
        quint64 id;
        int pin;
    };
    std::vector<Frame> stack {{network.root, 0}};
    std::unordered_set<quint64> done;
    while (!stack.empty()) {
        Frame &frame = stack.back();
        const Element *e = document.element(frame.id);
        if (e && frame.pin < inputCount(*e)) {
            const auto source = sourceOf(document, frame.id, frame.pin++);
            if (source && !done.contains(source->element))
                stack.push_back({source->element, 0});
            continue;
        }
        const quint64 id = frame.id;
        stack.pop_back();
        if (!done.insert(id).second)
            continue;
        order.push_back(id);
        for (quint64 sink : sinksOf[id])
            order.push_back(sink);
    }
}

} // namespace

void writeFbd(FbdDocument &document)
{
    const std::vector<FbdGeometry> layout = layoutFbd(document);
    // The file order: elements no network draws first (where CODESYS keeps its attributes), then
    // the networks in order.
    std::vector<quint64> order = document.unshown;
    order.reserve(document.elements.size());
    for (std::size_t n = 0; n < document.networks.size(); ++n) {
        const FbdNetwork &network = document.networks[n];
        if (network.label)
            order.push_back(network.label);
        if (network.comment)
            order.push_back(network.comment);
        const std::size_t before = order.size();
        if (!network.freehand && network.root)
            treeOrder(document, network, order);
        // Whatever the tree walk did not reach (a freehand network: all) keeps its file order.
        const std::unordered_set<quint64> placed(order.begin() + qsizetype(before), order.end());
        for (quint64 id : network.members)
            if (id != network.label && id != network.comment && !placed.contains(id))
                order.push_back(id);
        const FbdGeometry &g = layout[n];
        for (const auto &[id, rect] : g.rects)
            if (Element *e = document.element(id); e && !network.freehand)
                place(*e, rect, g);
        if (network.freehand) {
            // Moved as a whole: its elements and the corners of its wires.
            const auto first = g.rects.empty() ? std::optional<double>() : std::optional<double>(g.rects.begin()->second.top());
            const Element *sample = g.rects.empty() ? nullptr : document.element(g.rects.begin()->first);
            const double dy = first && sample ? *first - header(*sample).position.y : 0;
            if (dy != 0)
                for (quint64 id : network.members) {
                    Element &e = *document.element(id);
                    header(e).position.y += dy;
                    for (ConnectionPointIn *point : inputPoints(e))
                        for (Connection &c : point->connections)
                            for (Position &p : c.waypoints)
                                p.y += dy;
                }
        } else {
            for (const FbdWire &wire : g.wires) {
                Element *target = document.element(wire.target);
                ConnectionPointIn *point = target ? inputPoint(*target, wire.targetPin) : nullptr;
                if (point && !point->connections.empty())
                    point->connections.front().waypoints = waypointsFrom(wire.points);
            }
        }
        if (network.label)
            if (Element *label = document.element(network.label))
                header(*label).position = toPosition(g.labelRect.topLeft());
        if (network.comment)
            if (Element *comment = document.element(network.comment)) {
                header(*comment).position = toPosition(g.commentRect.topLeft());
                header(*comment).width = g.commentRect.width();
                header(*comment).height = g.commentRect.height();
            }
    }
    // Reorder the pool; elements no network lists (if any) go to the end. By index, so that a
    // hostile file's two elements with one id both stay.
    std::vector<Element> elements;
    elements.reserve(document.elements.size());
    std::vector<bool> moved(document.elements.size(), false);
    for (quint64 id : order) {
        const int at = document.indexOf(id);
        if (at >= 0 && !moved[std::size_t(at)]) {
            moved[std::size_t(at)] = true;
            elements.push_back(std::move(document.elements[std::size_t(at)]));
        }
    }
    for (std::size_t i = 0; i < document.elements.size(); ++i)
        if (!moved[i])
            elements.push_back(std::move(document.elements[i]));
    document.elements = std::move(elements);
    document.reindex();
}

} // namespace iec::editors::fbd
