#include "editors/common/diagramscene.h"

#include "editors/common/grid.h"
#include "model/projectmodel.h"

#include <QGraphicsLineItem>
#include <QGraphicsSceneMouseEvent>
#include <QPen>
#include <QTimer>

#include <numeric>

namespace iec::editors {

// ---- policy defaults

const std::vector<model::Element> *DiagramPolicy::elements(const model::ProjectModel &model, const model::BodyRef &ref) const
{
    const model::Body *body = model.body(ref);
    return body ? body->elements() : nullptr;
}

bool DiagramPolicy::update(DiagramScene &, const std::vector<model::Element> &, const ElementChanges &)
{
    return false;
}

bool DiagramPolicy::isMovable(const model::Element &) const
{
    return false;
}

bool DiagramPolicy::canStartWire(const DiagramItem &, const Pin &) const
{
    return false;
}

bool DiagramPolicy::canConnect(const DiagramItem &, const Pin &, const DiagramItem &, const Pin &) const
{
    return false;
}

void DiagramPolicy::itemsDragged(DiagramScene &, const QList<quint64> &, QPointF)
{
}

// ---- scene

DiagramScene::DiagramScene(model::ProjectModel &model, model::BodyRef ref, DiagramPolicy &policy, QObject *parent)
    : QGraphicsScene(parent)
    , m_model(model)
    , m_ref(std::move(ref))
    , m_policy(policy)
{
    using model::ProjectModel;
    connect(&model, &ProjectModel::elementsInserted, this, &DiagramScene::noteInserted);
    connect(&model, &ProjectModel::elementsRemoved, this, &DiagramScene::noteRemoved);
    connect(&model, &ProjectModel::elementsChanged, this, &DiagramScene::noteChanged);
    connect(&model, &ProjectModel::connectionsChanged, this,
        [this](const model::BodyRef &r, quint64 target) { noteChanged(r, {target}); });
    connect(&model, &ProjectModel::projectReset, this, &DiagramScene::noteEverything);
    // A diagram kept in addData (CODESYS's CFC) is drawn again as a whole when it changes.
    connect(&model, &ProjectModel::bodyAddDataChanged, this, [this](const model::BodyRef &r) {
        if (r == m_ref)
            noteEverything();
    });
    // Actions and transitions appear in the drawing (SFC action blocks, conditions by name).
    connect(&model, &ProjectModel::pouPartsChanged, this, [this](model::PouId pou) {
        if (pou == m_ref.pou)
            noteEverything();
    });
}

DiagramScene::~DiagramScene()
{
    // (The model may be gone already: its connections to this scene went with it.)
    // The items go while this is still a DiagramScene, so that they forget themselves here.
    m_index.clear();
    m_draft.reset();
    clear();
}

const std::vector<model::Element> *DiagramScene::shownElements() const
{
    return m_policy.elements(m_model, m_ref);
}

// ---- index

void DiagramScene::addElementItem(DiagramItem *item)
{
    if (!item)
        return;
    if (!item->parentItem() && item->scene() != this)
        addItem(item);
    m_index.insert(item->localId(), item);
}

void DiagramScene::removeElementItem(quint64 localId)
{
    delete m_index.value(localId);
}

void DiagramScene::forget(DiagramItem *item)
{
    const auto it = m_index.find(item->localId());
    if (it != m_index.end() && it.value() == item)
        m_index.erase(it);
}

QList<DiagramItem *> DiagramScene::diagramItems() const
{
    QList<DiagramItem *> result;
    for (QGraphicsItem *item : items(Qt::AscendingOrder)) {
        if (auto *diagramItem = item->type() == DiagramItem::Type ? static_cast<DiagramItem *>(item)
                                                                  : dynamic_cast<DiagramItem *>(item))
            result << diagramItem;
    }
    return result;
}

// ---- selection

QList<quint64> DiagramScene::selectedLocalIds() const
{
    QList<quint64> ids;
    for (QGraphicsItem *item : selectedItems()) {
        if (auto *diagramItem = dynamic_cast<DiagramItem *>(item); diagramItem && !ids.contains(diagramItem->localId()))
            ids << diagramItem->localId();
    }
    std::sort(ids.begin(), ids.end());
    return ids;
}

void DiagramScene::selectLocalIds(const QList<quint64> &localIds)
{
    QSignalBlocker blocker(this);
    clearSelection();
    for (quint64 id : localIds) {
        if (DiagramItem *item = itemFor(id))
            item->setSelected(true);
    }
    blocker.unblock();
    Q_EMIT selectionChanged();
}

// ---- pins

std::optional<PinHit> DiagramScene::pinAt(QPointF scenePoint, double radius) const
{
    std::optional<PinHit> best;
    double bestDistance = radius * radius;
    QSet<DiagramItem *> seen;
    const QRectF around(scenePoint - QPointF(radius, radius), QSizeF(2 * radius, 2 * radius));
    for (QGraphicsItem *candidate : items(around)) {
        DiagramItem *item = diagramItemOf(candidate);
        if (!item || seen.contains(item))
            continue;
        seen.insert(item);
        for (const Pin &pin : item->pins()) {
            const QPointF d = pin.scenePos - scenePoint;
            const double distance = d.x() * d.x() + d.y() * d.y();
            if (distance <= bestDistance) {
                bestDistance = distance;
                best = PinHit {item, pin};
            }
        }
    }
    return best;
}

// ---- following the model

void DiagramScene::noteInserted(const model::BodyRef &ref, const QList<quint64> &localIds)
{
    if (!(ref == m_ref))
        return;
    for (quint64 id : localIds) {
        if (m_pending.removed.remove(id))
            m_pending.changed.insert(id); // removed and back: the item stands for another value
        else
            m_pending.inserted.insert(id);
    }
    schedule();
}

void DiagramScene::noteRemoved(const model::BodyRef &ref, const QList<quint64> &localIds)
{
    if (!(ref == m_ref))
        return;
    for (quint64 id : localIds) {
        if (m_pending.inserted.remove(id))
            continue; // came and went within one command: no item was ever made
        m_pending.changed.remove(id);
        m_pending.removed.insert(id);
    }
    schedule();
}

void DiagramScene::noteChanged(const model::BodyRef &ref, const QList<quint64> &localIds)
{
    if (!(ref == m_ref))
        return;
    for (quint64 id : localIds) {
        if (!m_pending.inserted.contains(id))
            m_pending.changed.insert(id);
    }
    schedule();
}

void DiagramScene::noteEverything()
{
    m_needsRebuild = true;
    schedule();
}

void DiagramScene::schedule()
{
    if (m_scheduled)
        return;
    m_scheduled = true;
    // After the command that sent the signals: one update for all of them.
    QTimer::singleShot(0, this, &DiagramScene::rebuildIfDirty);
}

void DiagramScene::rebuildIfDirty()
{
    m_scheduled = false;
    if (m_needsRebuild) {
        rebuild();
        return;
    }
    if (m_pending.isEmpty())
        return;
    const ElementChanges changes = std::exchange(m_pending, {});
    const QList<quint64> selected = selectedLocalIds();
    const std::vector<model::Element> *elements = shownElements();
    if (!elements || !m_policy.update(*this, *elements, changes)) {
        rebuild();
        return;
    }
    if (selectedLocalIds() != selected)
        selectLocalIds(selected);
    growSceneRect(changes);
    Q_EMIT updated(changes);
}

void DiagramScene::rebuild()
{
    m_needsRebuild = false;
    m_pending = {};
    m_drag.reset();
    m_draft.reset();
    const QList<quint64> selected = selectedLocalIds();
    m_index.clear();
    clear();
    if (const std::vector<model::Element> *elements = shownElements())
        m_policy.populate(*this, *elements);
    selectLocalIds(selected);
    // Room around the drawing, so a chart never sticks to the view's border.
    setSceneRect(itemsBoundingRect().adjusted(-20, -20, 40, 40) | QRectF(0, 0, 200, 150));
    Q_EMIT rebuilt();
}

void DiagramScene::growSceneRect(const ElementChanges &changes)
{
    // Only what changed is measured (a large body's other items stay where they were); the
    // rectangle never shrinks between rebuilds, which only leaves some room.
    QRectF rect = sceneRect();
    for (const QSet<quint64> *ids : {&changes.inserted, &changes.changed}) {
        for (quint64 id : *ids) {
            if (const DiagramItem *item = itemFor(id))
                rect |= item->sceneBoundingRect().adjusted(-20, -20, 40, 40);
        }
    }
    if (rect != sceneRect())
        setSceneRect(rect);
}

// ---- mouse

DiagramItem *DiagramScene::diagramItemAt(QPointF scenePos) const
{
    for (QGraphicsItem *item : items(scenePos, Qt::IntersectsItemShape, Qt::DescendingOrder, QTransform())) {
        if (item->acceptedMouseButtons() != Qt::NoButton)
            return diagramItemOf(item);
    }
    return nullptr;
}

void DiagramScene::mouseDoubleClickEvent(QGraphicsSceneMouseEvent *event)
{
    if (DiagramItem *item = diagramItemAt(event->scenePos())) {
        Q_EMIT elementDoubleClicked(item->localId(), event->scenePos());
        event->accept();
        return;
    }
    QGraphicsScene::mouseDoubleClickEvent(event);
}

void DiagramScene::mousePressEvent(QGraphicsSceneMouseEvent *event)
{
    DiagramItem *item = diagramItemAt(event->scenePos());
    if (event->button() == Qt::RightButton) {
        // The context menu acts on what was clicked: the element under the cursor becomes the
        // selection unless it is part of it already; elsewhere the selection stays (paste there).
        if (item && !item->isSelected())
            selectLocalIds({item->localId()});
        event->accept();
        return;
    }
    if (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier) && item) {
        Q_EMIT elementShiftClicked(item->localId());
        event->accept();
        return;
    }
    if (event->button() == Qt::LeftButton && m_editable && beginWire(event))
        return;
    QGraphicsScene::mousePressEvent(event);
    if (event->button() == Qt::LeftButton && m_editable && item && item->isSelected())
        beginMove(event);
}

void DiagramScene::mouseMoveEvent(QGraphicsSceneMouseEvent *event)
{
    if (m_draft) {
        m_draft->line->setLine(QLineF(m_draft->from.pin.scenePos, event->scenePos()));
        event->accept();
        return;
    }
    QGraphicsScene::mouseMoveEvent(event);
    if (!m_drag)
        return;
    const QPointF anchorAt = m_drag->modelPositions.value(m_drag->anchor);
    const QPointF snapped = snapToGrid(anchorAt + event->scenePos() - m_drag->pressedAt, m_gridSize);
    m_drag->delta = snapped - anchorAt;
    for (auto it = m_drag->itemPositions.cbegin(); it != m_drag->itemPositions.cend(); ++it) {
        if (DiagramItem *moved = itemFor(it.key()))
            moved->setPos(it.value() + m_drag->delta);
    }
    m_policy.itemsDragged(*this, m_drag->itemPositions.keys(), m_drag->delta);
}

void DiagramScene::mouseReleaseEvent(QGraphicsSceneMouseEvent *event)
{
    if (m_draft && event->button() == Qt::LeftButton) {
        finishWire(event->scenePos());
        event->accept();
        return;
    }
    if (m_drag && event->button() == Qt::LeftButton && !m_drag->delta.isNull()) {
        // A drag, not a click: the selection stays as it is (a click would keep only this item).
        const QList<quint64> selected = selectedLocalIds();
        QGraphicsScene::mouseReleaseEvent(event);
        selectLocalIds(selected);
        finishMove();
        return;
    }
    m_drag.reset();
    QGraphicsScene::mouseReleaseEvent(event);
}

void DiagramScene::beginMove(QGraphicsSceneMouseEvent *event)
{
    const std::vector<model::Element> *elements = shownElements();
    DiagramItem *pressed = diagramItemAt(event->scenePos());
    if (!elements || !pressed)
        return;
    const QList<quint64> selected = selectedLocalIds();
    const QSet<quint64> wanted(selected.begin(), selected.end());
    Drag drag;
    drag.pressedAt = event->scenePos();
    drag.anchor = pressed->localId();
    for (const model::Element &element : *elements) {
        const quint64 id = model::header(element).localId;
        if (!wanted.contains(id) || !m_policy.isMovable(element))
            continue;
        const model::Position &at = model::header(element).position;
        drag.modelPositions.insert(id, QPointF(at.x, at.y));
        if (const DiagramItem *item = itemFor(id))
            drag.itemPositions.insert(id, item->pos());
    }
    if (drag.modelPositions.contains(drag.anchor))
        m_drag = std::move(drag);
}

void DiagramScene::finishMove()
{
    const Drag drag = std::move(*m_drag);
    m_drag.reset();
    QList<quint64> ids;
    QList<QPointF> positions;
    for (auto it = drag.modelPositions.cbegin(); it != drag.modelPositions.cend(); ++it) {
        ids << it.key();
        positions << it.value() + drag.delta;
    }
    // In localId order, so that the command (and a test) sees the same list every time.
    QList<int> order(ids.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return ids[a] < ids[b]; });
    QList<quint64> sortedIds;
    QList<QPointF> sortedPositions;
    for (int i : order) {
        sortedIds << ids[i];
        sortedPositions << positions[i];
    }
    Q_EMIT elementsMoved(sortedIds, sortedPositions);
}

bool DiagramScene::beginWire(QGraphicsSceneMouseEvent *event)
{
    const std::optional<PinHit> hit = pinAt(event->scenePos());
    if (!hit || !m_policy.canStartWire(*hit->item, hit->pin))
        return false;
    Draft draft {*hit, new QGraphicsLineItem(QLineF(hit->pin.scenePos, event->scenePos()))};
    QPen pen(QColor(0x30, 0x60, 0xc0), 1, Qt::DashLine);
    pen.setCosmetic(true);
    draft.line->setPen(pen);
    draft.line->setZValue(10);
    addItem(draft.line);
    m_draft = draft;
    event->accept();
    return true;
}

void DiagramScene::finishWire(QPointF scenePos)
{
    const Draft draft = *m_draft;
    m_draft.reset();
    delete draft.line;
    const std::optional<PinHit> end = pinAt(scenePos);
    if (!end || end->item == draft.from.item || end->pin.direction == draft.from.pin.direction)
        return;
    const bool fromOutput = draft.from.pin.direction == Pin::Direction::Out;
    const PinHit &output = fromOutput ? draft.from : *end;
    const PinHit &input = fromOutput ? *end : draft.from;
    if (!m_policy.canConnect(*output.item, output.pin, *input.item, input.pin))
        return;
    Q_EMIT wireDrawn(output.item->localId(), output.pin.formalParameter, input.item->localId(), input.pin.inputIndex);
}

} // namespace iec::editors
