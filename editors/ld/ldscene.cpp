#include "editors/ld/ldscene.h"

#include "editors/ld/lditems.h"
#include "model/body.h"
#include "model/projectmodel.h"

namespace iec::editors::ld {

using namespace model;
using namespace geometry;

namespace {

QList<QPointF> orthogonal(QPointF from, QPointF to)
{
    if (from.y() == to.y())
        return {from, to};
    const double middle = (from.x() + to.x()) / 2;
    return {from, QPointF(middle, from.y()), QPointF(middle, to.y()), to};
}

// A box drawn by another tool: its pins on the rows their relPositions say.
std::vector<int> rowsFromFile(const std::vector<BlockVariable> &pins, bool inputs)
{
    std::vector<int> rows;
    for (std::size_t p = 0; p < pins.size(); ++p) {
        const auto &rel = inputs ? (pins[p].connectionPointIn ? pins[p].connectionPointIn->relPosition : std::nullopt)
                                 : (pins[p].connectionPointOut ? pins[p].connectionPointOut->relPosition : std::nullopt);
        rows.push_back(rel ? std::max(0, int(std::lround((rel->y - kBoxTitle - kPinPitch / 2) / kPinPitch))) : int(p));
    }
    return rows;
}

} // namespace

DiagramItem *createLadderItem(const LadderDocument &document, quint64 localId, const QRectF &rect, bool framedVariables)
{
    const Element *e = document.element(localId);
    if (!e)
        return nullptr;
    if (std::holds_alternative<Contact>(*e))
        return new ContactItem(*e, rect);
    if (std::holds_alternative<Coil>(*e))
        return new CoilItem(*e, rect);
    if (const auto *block = std::get_if<Block>(e)) {
        const RungPins pins = document.pinsOf(localId);
        std::vector<int> inputRows;
        std::vector<int> outputRows;
        if (framedVariables) {
            inputRows = rowsFromFile(block->inputVariables, true);
            outputRows = rowsFromFile(block->outputVariables, false);
        } else {
            for (int p = 0; p < int(block->inputVariables.size() + block->inOutVariables.size()); ++p)
                inputRows.push_back(boxInputRow(*block, p, pins));
            for (int p = 0; p < int(block->outputVariables.size()); ++p)
                outputRows.push_back(boxOutputRow(*block, p, pins));
        }
        return new BoxItem(*e, rect, std::move(inputRows), std::move(outputRows));
    }
    if (std::holds_alternative<InVariable>(*e) || std::holds_alternative<InOutVariable>(*e))
        return new VariableItem(*e, rect, framedVariables);
    if (std::holds_alternative<OutVariable>(*e))
        return new VariableItem(*e, rect, true);
    if (std::holds_alternative<Jump>(*e) || std::holds_alternative<Return>(*e))
        return new OutputMarkItem(*e, rect);
    if (std::holds_alternative<LeftPowerRail>(*e) || std::holds_alternative<RightPowerRail>(*e))
        return new RailItem(*e, rect);
    if (std::holds_alternative<Label>(*e) || std::holds_alternative<Comment>(*e) || std::holds_alternative<VendorElement>(*e))
        return nullptr;
    return new OutputMarkItem(*e, rect);
}

const std::vector<Element> *LdPolicy::elements(const ProjectModel &model, const BodyRef &ref) const
{
    const Body *body = model.body(ref);
    m_layoutGenerated = body && body->layoutGenerated;
    return body ? body->elements() : nullptr;
}

void LdPolicy::populate(QGraphicsScene &scene, const std::vector<Element> &elements)
{
    m_document = readLadder(elements, m_layoutGenerated);
    m_layout = layoutLadder(m_document);
    for (std::size_t n = 0; n < m_document.networks.size(); ++n)
        addNetwork(scene, n);
}

void LdPolicy::addNetwork(QGraphicsScene &scene, std::size_t index)
{
    const LdNetwork &network = m_document.networks[index];
    const NetworkGeometry &g = m_layout[index];
    const auto textOf = [&](quint64 id) -> QString {
        const Element *e = id ? m_document.element(id) : nullptr;
        if (const auto *label = e ? std::get_if<Label>(e) : nullptr)
            return label->label;
        if (const auto *comment = e ? std::get_if<Comment>(e) : nullptr)
            return comment->content.text;
        return {};
    };
    const QRectF band(0, g.top, g.rightRailX + 40, g.height);
    scene.addItem(new NetworkItem(int(index) + 1, band, textOf(network.label), g.labelRect, textOf(network.comment),
        g.commentRect, network.freehand));
    for (const auto &[id, rect] : g.rects)
        if (DiagramItem *item = createLadderItem(m_document, id, rect, network.freehand))
            scene.addItem(item);
    if (network.freehand) {
        addFreehandWires(scene, network, g);
        return;
    }
    if (network.leftRail)
        if (DiagramItem *item = createLadderItem(m_document, network.leftRail, QRectF(kRailX - kRailWidth, g.rungTop, kRailWidth, g.rungHeight), false))
            scene.addItem(item);
    if (network.rightRail)
        if (DiagramItem *item = createLadderItem(m_document, network.rightRail, QRectF(g.rightRailX, g.rungTop, kRailWidth, g.rungHeight), false))
            scene.addItem(item);
    for (const WireRun &wire : g.wires)
        scene.addItem(new WireItem(wire.source, wire.target, wire.points));
}

void LdPolicy::addFreehandWires(QGraphicsScene &scene, const LdNetwork &network, const NetworkGeometry &g)
{
    for (quint64 id : network.members) {
        const Element *target = m_document.element(id);
        if (!target)
            continue;
        for (const ConnectionPointIn *point : inputPoints(*target)) {
            for (const Connection &c : point->connections) {
                // The wire as the other tool drew it (its corners), moved with the network.
                QList<QPointF> points;
                for (auto it = c.waypoints.rbegin(); it != c.waypoints.rend(); ++it)
                    points << QPointF(it->x, it->y + g.freehandShift);
                if (points.size() < 2) {
                    const auto from = g.rects.find(c.refLocalId);
                    const auto to = g.rects.find(id);
                    if (from == g.rects.end() || to == g.rects.end())
                        continue;
                    points = orthogonal(QPointF(from->second.right(), from->second.center().y()),
                        QPointF(to->second.left(), to->second.center().y()));
                }
                scene.addItem(new WireItem(c.refLocalId, id, points));
            }
        }
    }
}

} // namespace iec::editors::ld
