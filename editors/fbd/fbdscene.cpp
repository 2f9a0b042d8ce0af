#include "editors/fbd/fbdscene.h"

#include "editors/common/elementpool.h"
#include "model/body.h"
#include "model/projectmodel.h"

#include <QSet>


namespace iec::editors::fbd {

using namespace model;

namespace {

// The network of the old document that a new network is: its first element that is not a label
// or comment (ids are never reused within an editing session).
quint64 identityOf(const FbdNetwork &network)
{
    for (quint64 id : network.members)
        if (id != network.label && id != network.comment)
            return id;
    return network.members.empty() ? 0 : network.members.front();
}

} // namespace

DiagramItem *createFbdItem(const FbdDocument &document, const FbdGeometry &g, quint64 localId, bool freehand)
{
    const Element *e = document.element(localId);
    const auto rect = g.rects.find(localId);
    if (!e || rect == g.rects.end())
        return nullptr;
    if (std::holds_alternative<Block>(*e)) {
        if (freehand)
            return boxItemAsDrawn(*e, rect->second);
        std::vector<int> inputRows;
        std::vector<int> outputRows;
        if (const auto it = g.inputRows.find(localId); it != g.inputRows.end())
            inputRows = it->second;
        if (const auto it = g.outputRows.find(localId); it != g.outputRows.end())
            outputRows = it->second;
        return new BoxItem(*e, rect->second, std::move(inputRows), std::move(outputRows));
    }
    if (std::holds_alternative<InVariable>(*e))
        return new VariableItem(*e, rect->second, freehand);
    if (std::holds_alternative<InOutVariable>(*e))
        return new VariableItem(*e, rect->second, true); // the wire passes through it
    if (std::holds_alternative<OutVariable>(*e))
        return new VariableItem(*e, rect->second, freehand || g.onWire.contains(localId)); // the wire seems to pass it
    if (std::holds_alternative<Label>(*e) || std::holds_alternative<Comment>(*e))
        return nullptr;
    return new OutputMarkItem(*e, rect->second);
}

const std::vector<Element> *FbdPolicy::elements(const ProjectModel &model, const BodyRef &ref) const
{
    const Body *body = model.body(ref);
    m_layoutGenerated = body && body->layoutGenerated;
    return body ? body->elements() : nullptr;
}

void FbdPolicy::populate(DiagramScene &scene, const std::vector<Element> &elements)
{
    m_previous.reset();
    m_document = readFbd(elements, m_layoutGenerated);
    m_layout = layoutFbd(m_document);
    m_items.clear();
    for (std::size_t n = 0; n < m_document.networks.size(); ++n)
        m_items.push_back(addNetwork(scene, n));
    m_rebuilt = int(m_document.networks.size());
}

FbdDocument FbdPolicy::read(const std::vector<Element> &elements)
{
    // Undo and redo bring back the elements of the document before: reading is deterministic, so
    // that document is the one reading them again would give.
    if (m_previous && m_previousLayoutGenerated == m_layoutGenerated && m_previous->elements == elements)
        return *std::exchange(m_previous, std::nullopt);
    return readFbd(elements, m_layoutGenerated);
}

bool FbdPolicy::update(DiagramScene &scene, const std::vector<Element> &elements, const ElementChanges &changes)
{
    FbdDocument document = read(elements);
    std::unordered_map<quint64, std::size_t> oldByIdentity;
    for (std::size_t n = 0; n < m_document.networks.size(); ++n)
        oldByIdentity.emplace(identityOf(m_document.networks[n]), n);
    // A network is the same as before when it has the same elements and the changed ones differ
    // only in their places (a tree drawn by the editor ignores those); a freehand network is drawn
    // where its elements are, so any change counts.
    const auto unchanged = [&](const FbdNetwork &now, const FbdNetwork &before) {
        if (!(now == before))
            return false;
        for (quint64 id : now.members) {
            if (changes.inserted.contains(id) || changes.removed.contains(id))
                return false;
            if (changes.changed.contains(id) && (now.freehand || !sameButPlace(*document.element(id), *m_document.element(id))))
                return false;
        }
        return true;
    };
    std::vector<FbdGeometry> layout;
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
            layout.push_back(shifted(std::move(m_layout[old->second]), dy));
            renumber(layout.back(), int(n));
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

void FbdPolicy::setCurrentNetwork(int index)
{
    for (std::size_t n = 0; n < m_items.size(); ++n)
        if (m_items[n].band)
            m_items[n].band->setCurrent(int(n) == index);
}

void FbdPolicy::removeItems(DiagramScene &scene, NetworkItems &items)
{
    for (quint64 id : items.elements)
        scene.removeElementItem(id);
    for (QGraphicsItem *wire : items.wires)
        delete wire;
    delete items.band;
    items = {};
}

void FbdPolicy::moveItems(DiagramScene &scene, NetworkItems &items, double dy)
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

FbdPolicy::NetworkItems FbdPolicy::addNetwork(DiagramScene &scene, std::size_t index)
{
    const FbdNetwork &network = m_document.networks[index];
    const FbdGeometry &g = m_layout[index];
    NetworkItems items;
    const auto textOf = [&](quint64 id) -> QString {
        const Element *e = id ? m_document.element(id) : nullptr;
        if (const auto *label = e ? std::get_if<Label>(e) : nullptr)
            return label->label;
        if (const auto *comment = e ? std::get_if<Comment>(e) : nullptr)
            return comment->content.text;
        return {};
    };
    items.band = new NetworkItem(int(index) + 1, QRectF(0, g.top, g.width, g.height), textOf(network.label), g.labelRect,
        textOf(network.comment), g.commentRect, network.freehand);
    scene.addItem(items.band);
    for (const auto &[id, rect] : g.rects) {
        if (DiagramItem *item = createFbdItem(m_document, g, id, network.freehand)) {
            scene.addElementItem(item);
            items.elements.push_back(id);
        }
    }
    for (const FbdWire &wire : g.wires) {
        auto *item = new WireItem(wire.source, wire.target, wire.points);
        scene.addItem(item);
        items.wires.push_back(item);
    }
    return items;
}

} // namespace iec::editors::fbd
