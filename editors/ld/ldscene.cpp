#include "editors/ld/ldscene.h"

#include "editors/ld/lditems.h"
#include "editors/ld/ldwrite.h"
#include "model/body.h"
#include "model/projectmodel.h"

#include <QGraphicsRectItem>

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
        if (framedVariables)
            return boxItemAsDrawn(*e, rect);
        std::vector<int> inputRows;
        std::vector<int> outputRows;
        for (int p = 0; p < int(block->inputVariables.size() + block->inOutVariables.size()); ++p)
            inputRows.push_back(boxInputRow(*block, p, pins));
        for (int p = 0; p < int(block->outputVariables.size()); ++p)
            outputRows.push_back(boxOutputRow(*block, p, pins));
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

namespace {

// The network of the old document that a new network is (by its left rail, else its first element).
quint64 identityOf(const LdNetwork &network)
{
    return network.leftRail ? network.leftRail : (network.members.empty() ? 0 : network.members.front());
}

} // namespace

const std::vector<Element> *LdPolicy::elements(const ProjectModel &model, const BodyRef &ref) const
{
    const Body *body = model.body(ref);
    m_layoutGenerated = body && body->layoutGenerated;
    return body ? body->elements() : nullptr;
}

void LdPolicy::populate(DiagramScene &scene, const std::vector<Element> &elements)
{
    m_previous.reset();
    m_document = readLadder(elements, m_layoutGenerated);
    m_layout = layoutLadder(m_document);
    m_items.clear();
    for (std::size_t n = 0; n < m_document.networks.size(); ++n)
        m_items.push_back(addNetwork(scene, n));
    m_rebuilt = int(m_document.networks.size());
}

LadderDocument LdPolicy::read(const std::vector<Element> &elements)
{
    // Undo and redo bring back the elements of the document before: reading is deterministic, so
    // that document is the one reading them again would give (a large body reads in milliseconds).
    if (m_previous && m_previousLayoutGenerated == m_layoutGenerated && m_previous->elements == elements)
        return *std::exchange(m_previous, std::nullopt);
    return readLadder(elements, m_layoutGenerated);
}

bool LdPolicy::update(DiagramScene &scene, const std::vector<Element> &elements, const ElementChanges &changes)
{
    LadderDocument document = read(elements);
    std::unordered_map<quint64, std::size_t> oldByIdentity;
    for (std::size_t n = 0; n < m_document.networks.size(); ++n)
        oldByIdentity.emplace(identityOf(m_document.networks[n]), n);
    // A network is the same as before when it has the same elements, none inserted or removed,
    // and the changed ones differ only in their places (a rung drawn by the editor ignores
    // those); a freehand network is drawn where its elements are, so any change counts.
    const auto unchanged = [&](const LdNetwork &now, const LdNetwork &before) {
        if (now.members != before.members || now.freehand != before.freehand || !(now.rung == before.rung)
            || now.label != before.label || now.comment != before.comment)
            return false;
        for (quint64 id : now.members) {
            if (changes.inserted.contains(id) || changes.removed.contains(id))
                return false;
            if (changes.changed.contains(id)
                && (now.freehand || !sameButPlace(*document.element(id), *m_document.element(id))
                    || document.pinsOf(id) != m_document.pinsOf(id)))
                return false;
        }
        return true;
    };
    std::vector<NetworkGeometry> layout;
    std::vector<NetworkItems> items(document.networks.size());
    std::vector<bool> reused(m_document.networks.size(), false);
    std::vector<std::size_t> fresh;
    double top = 0;
    std::swap(m_document, document); // layoutNetwork and addNetwork read m_document
    for (std::size_t n = 0; n < m_document.networks.size(); ++n) {
        const auto old = oldByIdentity.find(identityOf(m_document.networks[n]));
        if (old != oldByIdentity.end() && !reused[old->second] && unchanged(m_document.networks[n], document.networks[old->second])) {
            reused[old->second] = true;
            const double dy = top - m_layout[old->second].top;
            layout.push_back(shifted(std::move(m_layout[old->second]), dy)); // m_layout is replaced below
            items[n] = std::move(m_items[old->second]);
            moveItems(scene, items[n], dy);
        } else {
            layout.push_back(layoutNetwork(m_document, n, top));
            fresh.push_back(n);
        }
        top += layout.back().height;
    }
    for (std::size_t o = 0; o < reused.size(); ++o)
        if (!reused[o])
            removeItems(scene, m_items[o]);
    m_layout = std::move(layout);
    for (std::size_t n : fresh)
        items[n] = addNetwork(scene, n);
    for (std::size_t n = 0; n < items.size(); ++n)
        items[n].band->setNumber(int(n) + 1);
    m_items = std::move(items);
    m_rebuilt = int(fresh.size());
    m_previous = std::move(document);
    m_previousLayoutGenerated = m_layoutGenerated;
    return true;
}

void LdPolicy::setCurrentNetwork(int index)
{
    // Every band, not only the last current one: a rebuild or update made new bands.
    for (std::size_t n = 0; n < m_items.size(); ++n)
        if (m_items[n].band)
            m_items[n].band->setCurrent(int(n) == index);
}

void LdPolicy::removeItems(DiagramScene &scene, NetworkItems &items)
{
    for (quint64 id : items.elements)
        scene.removeElementItem(id);
    for (QGraphicsItem *wire : items.wires)
        delete wire;
    delete items.band;
    items = {};
}

void LdPolicy::moveItems(DiagramScene &scene, NetworkItems &items, double dy)
{
    if (dy == 0)
        return;
    for (quint64 id : items.elements)
        if (DiagramItem *item = scene.itemFor(id))
            item->moveBy(0, dy);
    for (QGraphicsItem *wire : items.wires)
        wire->moveBy(0, dy);
    items.band->moveBy(0, dy);
}

LdPolicy::NetworkItems LdPolicy::addNetwork(DiagramScene &scene, std::size_t index)
{
    const LdNetwork &network = m_document.networks[index];
    const NetworkGeometry &g = m_layout[index];
    NetworkItems items;
    const auto textOf = [&](quint64 id) -> QString {
        const Element *e = id ? m_document.element(id) : nullptr;
        if (const auto *label = e ? std::get_if<Label>(e) : nullptr)
            return label->label;
        if (const auto *comment = e ? std::get_if<Comment>(e) : nullptr)
            return comment->content.text;
        return {};
    };
    const QRectF band(0, g.top, g.rightRailX + 40, g.height);
    items.band = new NetworkItem(int(index) + 1, band, textOf(network.label), g.labelRect, textOf(network.comment),
        g.commentRect, network.freehand);
    scene.addItem(items.band);
    const auto addElement = [&](quint64 id, const QRectF &rect, bool framed) {
        if (DiagramItem *item = createLadderItem(m_document, id, rect, framed)) {
            scene.addElementItem(item);
            items.elements.push_back(id);
        }
    };
    for (const auto &[id, rect] : g.rects)
        addElement(id, rect, network.freehand);
    if (network.freehand) {
        addFreehandWires(scene, network, g, items);
        return items;
    }
    if (network.leftRail)
        addElement(network.leftRail, QRectF(kRailX - kRailWidth, g.rungTop, kRailWidth, g.rungHeight), false);
    const QRectF rightRail(g.rightRailX, g.rungTop, kRailWidth, g.rungHeight);
    if (network.rightRail) {
        addElement(network.rightRail, rightRail, false);
    } else {
        // Another tool's file may end a network without a rail (Beremiz shares one right rail
        // among the networks with coils): the rung still ends at a drawn rail, as in CODESYS.
        // Drawn only, part of the band; the file is not touched until the network is edited.
        auto *rail = new QGraphicsRectItem(rightRail, items.band);
        rail->setPen(Qt::NoPen);
        rail->setBrush(kInk);
    }
    for (const WireRun &wire : g.wires) {
        auto *item = new WireItem(wire.source, wire.target, wire.points);
        scene.addItem(item);
        items.wires.push_back(item);
    }
    return items;
}

void LdPolicy::addFreehandWires(DiagramScene &scene, const LdNetwork &network, const NetworkGeometry &g, NetworkItems &items)
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
                auto *item = new WireItem(c.refLocalId, id, points);
                scene.addItem(item);
                items.wires.push_back(item);
            }
        }
    }
}

} // namespace iec::editors::ld
