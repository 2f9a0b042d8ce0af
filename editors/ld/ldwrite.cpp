#include "editors/ld/ldwrite.h"

#include "editors/common/placement.h"

#include <algorithm>
#include <map>
#include <set>

namespace iec::editors::ld {

using namespace model;
using namespace geometry;

namespace {

// The connection point of an element's input pin (created when missing).
ConnectionPointIn &inputPoint(Element &element, int pin)
{
    if (auto *block = std::get_if<Block>(&element)) {
        const int inputs = int(block->inputVariables.size());
        BlockVariable &variable = pin < inputs ? block->inputVariables[std::size_t(pin)]
                                               : block->inOutVariables[std::size_t(pin - inputs)];
        if (!variable.connectionPointIn)
            variable.connectionPointIn.emplace();
        return *variable.connectionPointIn;
    }
    return std::visit(
        [](auto &e) -> ConnectionPointIn & {
            if constexpr (requires { e.connectionPointIn; }) {
                if (!e.connectionPointIn)
                    e.connectionPointIn.emplace();
                return *e.connectionPointIn;
            } else {
                static ConnectionPointIn none; // never reached: rung targets all have an input
                return none;
            }
        },
        element);
}

std::optional<QString> outputName(const Element &source, int pin)
{
    const auto *block = std::get_if<Block>(&source);
    if (!block || pin < 0 || pin >= int(block->outputVariables.size()))
        return std::nullopt;
    return block->outputVariables[std::size_t(pin)].formalParameter;
}

// Position, size and pin positions of a placed element.
void place(Element &element, const QRectF &rect, const RungPins &pins)
{
    ElementHeader &h = header(element);
    h.position = toPosition(rect.topLeft());
    h.width = rect.width();
    h.height = rect.height();
    const QPointF in(0, rect.height() / 2);
    const QPointF out(rect.width(), rect.height() / 2);
    std::visit(
        [&](auto &e) {
            using T = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<T, Block>) {
                for (std::size_t p = 0; p < e.inputVariables.size(); ++p)
                    setRelPosition(e.inputVariables[p].connectionPointIn, inputPinOffset(element, int(p), pins));
                for (std::size_t p = 0; p < e.outputVariables.size(); ++p)
                    setRelPosition(e.outputVariables[p].connectionPointOut, outputPinOffset(element, int(p), pins));
            } else if constexpr (std::is_same_v<T, Contact> || std::is_same_v<T, Coil>) {
                setRelPosition(e.connectionPointIn, in);
                setRelPosition(e.connectionPointOut, out);
            } else if constexpr (std::is_same_v<T, Jump> || std::is_same_v<T, Return> || std::is_same_v<T, OutVariable>) {
                setRelPosition(e.connectionPointIn, in);
            } else if constexpr (std::is_same_v<T, InVariable>) {
                setRelPosition(e.connectionPointOut, out);
            }
        },
        element);
}

class NetworkWriter
{
public:
    NetworkWriter(LadderDocument &document, std::size_t index)
        : m_document(document)
        , m_network(document.networks[index])
        , m_index(index)
    { }

    NetworkGeometry write(double top, std::set<quint64> &railsTaken)
    {
        if (m_network.freehand) {
            NetworkGeometry g = layoutNetwork(m_document, m_index, top);
            shiftFreehand(g.freehandShift);
            placeHeader(g);
            return g;
        }
        ensureRails(railsTaken);
        NetworkGeometry g = layoutNetwork(m_document, m_index, top);
        rewire(g);
        for (const auto &[id, rect] : g.rects)
            if (Element *e = m_document.element(id))
                place(*e, rect, m_document.pinsOf(id));
        placeRails(g);
        placeHeader(g);
        return g;
    }

private:
    // Each rung network has rails of its own (CODESYS writes one pair for the body, Beremiz
    // often one left rail for all): a rail another network took already is replaced.
    void ensureRails(std::set<quint64> &railsTaken)
    {
        const auto firstIndex = [&] {
            int first = int(m_document.elements.size());
            for (quint64 id : m_network.members)
                first = std::min(first, m_document.indexOf(id));
            return first;
        };
        // A rail is made anew when the network has none, shares one with a network before it,
        // or names one that is no longer in the body (the monkey found a stale id).
        const auto needsRail = [&](quint64 rail) { return !rail || railsTaken.contains(rail) || !m_document.element(rail); };
        if (needsRail(m_network.leftRail)) {
            m_network.leftRail = m_document.add(LeftPowerRail {}, firstIndex());
            m_network.members.push_back(m_network.leftRail);
        }
        if (needsRail(m_network.rightRail)) {
            int last = -1;
            for (quint64 id : m_network.members)
                last = std::max(last, m_document.indexOf(id));
            m_network.rightRail = m_document.add(RightPowerRail {}, last + 1);
            m_network.members.push_back(m_network.rightRail);
        }
        railsTaken.insert(m_network.leftRail);
        railsTaken.insert(m_network.rightRail);
        // From now on these rails are this network's alone.
        markNetworkRail(*m_document.element(m_network.leftRail));
        markNetworkRail(*m_document.element(m_network.rightRail));
    }

    // The rung's wires come from the tree; the wires an element had keep their extras (addData,
    // globalId) when they still join the same two elements.
    void rewire(const NetworkGeometry &g)
    {
        std::map<std::tuple<quint64, int, quint64>, Connection> old;
        const std::vector<quint64> rung = rungElements(m_network.rung);
        for (quint64 id : rung) {
            Element *e = m_document.element(id);
            const int pin = std::holds_alternative<Block>(*e) ? m_document.pinsOf(id).input : 0;
            if (pin < 0)
                continue;
            ConnectionPointIn &point = inputPoint(*e, pin);
            for (Connection &c : point.connections)
                old.emplace(std::tuple(id, pin, c.refLocalId), std::move(c));
            point.connections.clear();
        }
        auto &rightRail = std::get<RightPowerRail>(*m_document.element(m_network.rightRail));
        for (ConnectionPointIn &point : rightRail.connectionPointIns)
            for (Connection &c : point.connections)
                old.emplace(std::tuple(m_network.rightRail, 0, c.refLocalId), std::move(c));
        rightRail.connectionPointIns.clear();
        const std::set<quint64> inRung(rung.begin(), rung.end());
        for (const WireRun &run : g.wires) {
            const Element *source = m_document.element(run.source);
            if (!source)
                continue;
            Connection connection;
            if (const auto it = old.find(std::tuple(run.target, run.target == m_network.rightRail ? 0 : run.targetPin, run.source)); it != old.end())
                connection = it->second;
            connection.refLocalId = run.source;
            if (!std::holds_alternative<LeftPowerRail>(*source))
                connection.formalParameter = outputName(*source, run.sourcePin);
            connection.waypoints = waypointsFrom(run.points);
            if (run.target == m_network.rightRail) {
                auto &rail = std::get<RightPowerRail>(*m_document.element(m_network.rightRail));
                ConnectionPointIn point;
                point.connections.push_back(std::move(connection));
                rail.connectionPointIns.push_back(std::move(point));
            } else if (inRung.contains(run.target) && isRungPin(run.target, run.targetPin)) {
                inputPoint(*m_document.element(run.target), run.targetPin).connections.push_back(std::move(connection));
            } else if (Element *target = m_document.element(run.target)) {
                // A side wire: its source stays, its corners follow the layout.
                for (Connection &c : inputPoint(*target, run.targetPin).connections)
                    if (c.refLocalId == run.source)
                        c.waypoints = connection.waypoints;
            }
        }
    }

    bool isRungPin(quint64 id, int pin) const
    {
        const Element *e = m_document.element(id);
        return !std::holds_alternative<Block>(*e) || m_document.pinsOf(id).input == pin;
    }

    void placeRails(const NetworkGeometry &g)
    {
        auto &left = std::get<LeftPowerRail>(*m_document.element(m_network.leftRail));
        left.position = {kRailX - kRailWidth, g.rungTop};
        left.width = kRailWidth;
        left.height = g.rungHeight;
        // The rail's outputs keep the name they had; "" is no name (what the reader gives back).
        std::optional<QString> formal = left.connectionPointOuts.empty() ? std::nullopt : left.connectionPointOuts.front().formalParameter;
        if (formal && formal->isEmpty())
            formal.reset();
        std::set<double> ys;
        for (const WireRun &run : g.wires)
            if (run.source == m_network.leftRail)
                ys.insert(run.points.front().y());
        if (ys.empty())
            ys.insert(g.lineY);
        left.connectionPointOuts.clear();
        for (double y : ys) {
            ConnectionPointOut out;
            out.relPosition = Position {kRailWidth, y - g.rungTop};
            out.formalParameter = formal;
            left.connectionPointOuts.push_back(std::move(out));
        }
        auto &right = std::get<RightPowerRail>(*m_document.element(m_network.rightRail));
        right.position = {g.rightRailX, g.rungTop};
        right.width = kRailWidth;
        right.height = g.rungHeight;
        std::size_t pin = 0;
        for (const WireRun &run : g.wires) {
            if (run.target != m_network.rightRail || pin >= right.connectionPointIns.size())
                continue;
            right.connectionPointIns[pin++].relPosition = Position {0, run.points.back().y() - g.rungTop};
        }
    }

    void placeHeader(const NetworkGeometry &g)
    {
        const auto placeAt = [&](quint64 id, const QRectF &rect) {
            if (!id || rect.isNull())
                return;
            ElementHeader &h = header(*m_document.element(id));
            h.position = toPosition(rect.topLeft());
            h.width = rect.width();
            h.height = rect.height();
        };
        placeAt(m_network.label, g.labelRect);
        placeAt(m_network.comment, g.commentRect);
        if (m_network.title)
            header(*m_document.element(m_network.title)).position = {kRailX, g.top};
    }

    void shiftFreehand(double dy)
    {
        if (dy == 0)
            return;
        for (quint64 id : m_network.members) {
            if (id == m_network.label || id == m_network.comment || id == m_network.title)
                continue;
            Element &e = *m_document.element(id);
            header(e).position.y += dy;
            for (ConnectionPointIn *point : inputPoints(e))
                for (Connection &c : point->connections)
                    for (Position &p : c.waypoints)
                        p.y += dy;
        }
    }

    LadderDocument &m_document;
    LdNetwork &m_network;
    std::size_t m_index;
};

} // namespace

NetworkGeometry shifted(NetworkGeometry g, double dy)
{
    if (dy == 0)
        return g;
    g.top += dy;
    g.rungTop += dy;
    g.lineY += dy;
    for (auto &[id, rect] : g.rects)
        rect.translate(0, dy);
    for (WireRun &wire : g.wires)
        for (QPointF &p : wire.points)
            p.ry() += dy;
    for (WirePoint &point : g.wirePoints)
        point.position.ry() += dy;
    if (!g.labelRect.isNull())
        g.labelRect.translate(0, dy);
    if (!g.commentRect.isNull())
        g.commentRect.translate(0, dy);
    return g;
}

namespace {

// The network of `before` that `network` is (by its left rail, else its first element).
quint64 identityOf(const LdNetwork &network)
{
    return network.leftRail ? network.leftRail : (network.members.empty() ? 0 : network.members.front());
}

// Whether the network is as the edit found it (same elements, same values) and its elements sit
// where its layout says (it was written before): then only its place may change.
bool untouchedAndWritten(const LadderDocument &document, const LdNetwork &now, const LadderDocument &before,
    const LdNetwork &then, const NetworkGeometry &layout)
{
    if (now.freehand || then.freehand || now.members != then.members || !(now.rung == then.rung) || now.label != then.label
        || now.comment != then.comment || !now.leftRail || !now.rightRail)
        return false;
    for (quint64 id : now.members) {
        const model::Element *e = document.element(id);
        const model::Element *old = before.element(id);
        if (!e || !old || !(*e == *old))
            return false;
    }
    for (const auto &[id, rect] : layout.rects) {
        const model::Position &p = header(*document.element(id)).position;
        if (p.x != rect.left() || p.y != rect.top())
            return false;
    }
    const model::Position &rail = header(*document.element(now.leftRail)).position;
    return rail.y == layout.rungTop && isNetworkRail(*document.element(now.leftRail));
}

void moveNetwork(LadderDocument &document, const LdNetwork &network, double dy)
{
    for (quint64 id : network.members) {
        model::Element &e = *document.element(id);
        header(e).position.y += dy;
        for (ConnectionPointIn *point : inputPoints(e))
            for (Connection &c : point->connections)
                for (Position &p : c.waypoints)
                    p.y += dy;
    }
}

} // namespace

std::vector<NetworkGeometry> writeLadder(LadderDocument &document)
{
    std::vector<NetworkGeometry> result;
    result.reserve(document.networks.size());
    std::set<quint64> railsTaken;
    double top = 0;
    for (std::size_t n = 0; n < document.networks.size(); ++n) {
        result.push_back(NetworkWriter(document, n).write(top, railsTaken));
        top += result.back().height;
    }
    return result;
}

void writeLadder(LadderDocument &document, const LadderDocument &before, const std::vector<NetworkGeometry> &beforeLayout)
{
    std::unordered_map<quint64, std::size_t> beforeByIdentity;
    for (std::size_t n = 0; n < before.networks.size() && n < beforeLayout.size(); ++n)
        beforeByIdentity.emplace(identityOf(before.networks[n]), n);
    std::set<quint64> railsTaken;
    double top = 0;
    for (std::size_t n = 0; n < document.networks.size(); ++n) {
        const LdNetwork &network = document.networks[n];
        const auto then = beforeByIdentity.find(identityOf(network));
        if (then != beforeByIdentity.end() && !railsTaken.contains(network.leftRail) && !railsTaken.contains(network.rightRail)
            && untouchedAndWritten(document, network, before, before.networks[then->second], beforeLayout[then->second])) {
            const double dy = top - beforeLayout[then->second].top;
            if (dy != 0)
                moveNetwork(document, network, dy);
            railsTaken.insert(network.leftRail);
            railsTaken.insert(network.rightRail);
            top += beforeLayout[then->second].height;
        } else
            top += NetworkWriter(document, n).write(top, railsTaken).height;
    }
}

} // namespace iec::editors::ld
