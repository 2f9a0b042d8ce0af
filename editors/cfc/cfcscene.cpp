#include "editors/cfc/cfcscene.h"

#include "editors/cfc/cfcitems.h"
#include "editors/common/blockitems.h"
#include "editors/common/networkitems.h"
#include "model/body.h"
#include "model/projectmodel.h"

namespace iec::editors::cfc {

using namespace model;

namespace {

// Whether a wire's corners pass near one of the rectangles (a segment's bounding box, grown by
// the clearance the router keeps, meets it).
bool passesThrough(const QList<QPointF> &points, const QList<QRectF> &rects)
{
    for (qsizetype i = 1; i < points.size(); ++i) {
        const QRectF segment = QRectF(points[i - 1], points[i]).normalized().adjusted(-kWireClearance, -kWireClearance,
            kWireClearance, kWireClearance);
        for (const QRectF &rect : rects)
            if (segment.intersects(rect))
                return true;
    }
    return false;
}

} // namespace

const std::vector<Element> *CfcPolicy::elements(const ProjectModel &model, const BodyRef &ref) const
{
    const Body *body = model.body(ref);
    m_storage = body ? cfcStorageOf(*body) : std::nullopt;
    m_readError.clear();
    if (!body)
        return nullptr;
    if (m_storage != CfcStorage::Codesys)
        return body->elements();
    const QString &content = body->addData[std::size_t(codesysCfcEntry(*body))].content;
    if (content != m_codesysContent || m_codesysElements.empty()) {
        CodesysCfcRead read = readCodesysCfc(content);
        m_codesysContent = content;
        m_codesysElements = std::move(read.elements);
        m_readError = read.error;
    }
    if (!m_readError.isEmpty()) {
        m_storage.reset();
        return nullptr;
    }
    return &m_codesysElements;
}

void CfcPolicy::populate(DiagramScene &scene, const std::vector<Element> &elements)
{
    m_wires.clear(); // the scene deleted their items with the others
    for (const Element &e : elements)
        addElementItem(scene, e);
    m_frames = cfcFrames(elements);
    refreshWires(scene, elements, {}, {}, true);
}

bool CfcPolicy::update(DiagramScene &scene, const std::vector<Element> &elements, const ElementChanges &changes)
{
    QList<QRectF> dirty;
    QSet<quint64> touched = changes.inserted;
    touched.unite(changes.changed).unite(changes.removed);
    for (const QSet<quint64> *gone : {&changes.removed, &changes.changed}) {
        for (quint64 id : *gone) {
            if (const auto frame = m_frames.constFind(id); frame != m_frames.cend())
                dirty << *frame;
            scene.removeElementItem(id);
        }
    }
    for (const Element &e : elements) {
        const quint64 id = header(e).localId;
        if (changes.inserted.contains(id) || changes.changed.contains(id))
            addElementItem(scene, e);
    }
    m_frames = cfcFrames(elements);
    for (quint64 id : changes.inserted + changes.changed)
        if (const auto frame = m_frames.constFind(id); frame != m_frames.cend())
            dirty << *frame;
    refreshWires(scene, elements, touched, dirty, false);
    return true;
}

void CfcPolicy::addElementItem(DiagramScene &scene, const Element &e)
{
    const QRectF rect = cfcRect(e);
    ElementItem *item = nullptr;
    if (std::holds_alternative<Block>(e))
        item = new BoxItem(e, rect, {}, {});
    else if (std::holds_alternative<InVariable>(e) || std::holds_alternative<OutVariable>(e)
             || std::holds_alternative<InOutVariable>(e))
        item = new VariableItem(e, rect, true);
    else if (std::holds_alternative<Jump>(e) || std::holds_alternative<Return>(e))
        item = new OutputMarkItem(e, rect);
    else if (std::holds_alternative<Label>(e) || std::holds_alternative<Connector>(e)
             || std::holds_alternative<Continuation>(e) || std::holds_alternative<Comment>(e)
             || std::holds_alternative<VendorElement>(e))
        item = new CfcMarkItem(e, rect);
    if (!item)
        return; // nothing of CFC (an LD or SFC element in a foreign file) is drawn
    if (const auto &order = header(e).executionOrderId)
        new OrderNumberItem(int(*order), item);
    scene.addElementItem(item);
}

void CfcPolicy::refreshWires(DiagramScene &scene, const std::vector<Element> &elements, const QSet<quint64> &touched,
    const QList<QRectF> &dirty, bool everything)
{
    QHash<quint64, const Element *> byId;
    byId.reserve(qsizetype(elements.size()));
    for (const Element &e : elements)
        byId.insert(header(e).localId, &e);
    std::map<WireKey, DrawnWire> next;
    for (const Element &target : elements) {
        const quint64 targetId = header(target).localId;
        const auto points = inputPoints(target);
        for (std::size_t pin = 0; pin < points.size(); ++pin) {
            for (const Connection &c : points[pin]->connections) {
                const WireKey key {c.refLocalId, c.formalParameter.value_or(QString()), targetId, int(pin)};
                const Element *source = byId.value(c.refLocalId);
                const auto from = source ? cfcOutputPin(*source, c.formalParameter) : std::nullopt;
                const auto to = cfcInputPin(target, int(pin));
                if (!from || !to || next.count(key))
                    continue;
                auto old = m_wires.find(key);
                const bool keep = !everything && old != m_wires.end() && !old->second.wire.broken
                    && !touched.contains(c.refLocalId) && !touched.contains(targetId)
                    && old->second.wire.points.front() == *from && old->second.wire.points.back() == *to
                    && !passesThrough(old->second.wire.points, dirty);
                if (keep) {
                    next.emplace(key, old->second);
                    m_wires.erase(old);
                    continue;
                }
                CfcWire wire = routeCfcWire(*from, *to, m_frames);
                wire.source = c.refLocalId;
                wire.formalParameter = c.formalParameter;
                wire.target = targetId;
                wire.pin = int(pin);
                WireItem *item = nullptr;
                if (old != m_wires.end()) {
                    item = old->second.item;
                    m_wires.erase(old);
                    item->setPoints(wire.points);
                } else {
                    item = new WireItem(wire.source, wire.target, wire.points);
                    scene.addItem(item);
                }
                item->setBroken(wire.broken);
                next.emplace(key, DrawnWire {std::move(wire), item});
            }
        }
    }
    for (auto &[key, gone] : m_wires)
        delete gone.item;
    m_wires = std::move(next);
}

bool CfcPolicy::isMovable(const Element &) const
{
    return true;
}

bool CfcPolicy::canStartWire(const DiagramItem &, const Pin &) const
{
    return true;
}

bool CfcPolicy::canConnect(const DiagramItem &, const Pin &output, const DiagramItem &, const Pin &input) const
{
    return output.direction == Pin::Direction::Out && input.direction == Pin::Direction::In;
}

void CfcPolicy::itemsDragged(DiagramScene &, const QList<quint64> &localIds, QPointF delta)
{
    const QSet<quint64> moved(localIds.begin(), localIds.end());
    CfcFrames frames = m_frames;
    for (quint64 id : localIds)
        if (auto frame = frames.find(id); frame != frames.end())
            frame->translate(delta);
    for (auto &[key, drawn] : m_wires) {
        const bool sourceMoved = moved.contains(drawn.wire.source);
        const bool targetMoved = moved.contains(drawn.wire.target);
        if (!sourceMoved && !targetMoved)
            continue;
        const QPointF from = drawn.wire.points.front() + (sourceMoved ? delta : QPointF());
        const QPointF to = drawn.wire.points.back() + (targetMoved ? delta : QPointF());
        const CfcWire wire = routeCfcWire(from, to, frames);
        drawn.item->setPoints(wire.points);
        drawn.item->setBroken(wire.broken);
    }
}

void CfcPolicy::forEachWire(const std::function<void(const CfcWire &, WireItem &)> &visit) const
{
    for (const auto &[key, drawn] : m_wires)
        visit(drawn.wire, *drawn.item);
}

std::vector<CfcWire> CfcPolicy::wires() const
{
    std::vector<CfcWire> wires;
    wires.reserve(m_wires.size());
    for (const auto &[key, drawn] : m_wires)
        wires.push_back(drawn.wire);
    return wires;
}

} // namespace iec::editors::cfc
