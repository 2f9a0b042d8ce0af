#include "editors/common/diagramscene.h"

#include "editors/common/diagramitem.h"
#include "model/projectmodel.h"

#include <QGraphicsSceneMouseEvent>
#include <QTimer>

namespace iec::editors {

const std::vector<model::Element> *DiagramPolicy::elements(const model::ProjectModel &model, const model::BodyRef &ref) const
{
    const model::Body *body = model.body(ref);
    return body ? body->elements() : nullptr;
}

DiagramScene::DiagramScene(model::ProjectModel &model, model::BodyRef ref, DiagramPolicy &policy, QObject *parent)
    : QGraphicsScene(parent)
    , m_model(model)
    , m_ref(std::move(ref))
    , m_policy(policy)
{
    using model::ProjectModel;
    connect(&model, &ProjectModel::elementsInserted, this, [this](const model::BodyRef &r) { scheduleRebuild(r); });
    connect(&model, &ProjectModel::elementsRemoved, this, [this](const model::BodyRef &r) { scheduleRebuild(r); });
    connect(&model, &ProjectModel::elementsChanged, this, [this](const model::BodyRef &r) { scheduleRebuild(r); });
    connect(&model, &ProjectModel::connectionsChanged, this, [this](const model::BodyRef &r) { scheduleRebuild(r); });
    connect(&model, &ProjectModel::projectReset, this, [this] { scheduleRebuild(m_ref); });
    connect(&model, &ProjectModel::pouPartsChanged, this, [this] { scheduleRebuild(m_ref); });
}

void DiagramScene::scheduleRebuild(const model::BodyRef &ref)
{
    if (!(ref == m_ref) || m_dirty)
        return;
    m_dirty = true;
    QTimer::singleShot(0, this, &DiagramScene::rebuildIfDirty);
}

void DiagramScene::rebuildIfDirty()
{
    if (m_dirty)
        rebuild();
}

void DiagramScene::rebuild()
{
    m_dirty = false;
    const QList<quint64> selected = selectedLocalIds();
    clear();
    if (const std::vector<model::Element> *elements = m_policy.elements(m_model, m_ref))
        m_policy.populate(*this, *elements);
    selectLocalIds(selected);
    // Room around the drawing, so a chart never sticks to the view's border.
    setSceneRect(itemsBoundingRect().adjusted(-20, -20, 40, 40) | QRectF(0, 0, 200, 150));
    Q_EMIT rebuilt();
}

QList<DiagramItem *> DiagramScene::diagramItems() const
{
    QList<DiagramItem *> result;
    for (QGraphicsItem *item : items(Qt::AscendingOrder)) {
        if (auto *diagramItem = dynamic_cast<DiagramItem *>(item))
            result << diagramItem;
    }
    return result;
}

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
    for (DiagramItem *item : diagramItems())
        item->setSelected(localIds.contains(item->localId()));
    blocker.unblock();
    Q_EMIT selectionChanged();
}

void DiagramScene::mouseDoubleClickEvent(QGraphicsSceneMouseEvent *event)
{
    if (DiagramItem *item = diagramItemOf(itemAt(event->scenePos(), QTransform()))) {
        Q_EMIT elementDoubleClicked(item->localId(), event->scenePos());
        event->accept();
        return;
    }
    QGraphicsScene::mouseDoubleClickEvent(event);
}

void DiagramScene::mousePressEvent(QGraphicsSceneMouseEvent *event)
{
    if (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier)) {
        if (DiagramItem *item = diagramItemOf(itemAt(event->scenePos(), QTransform()))) {
            Q_EMIT elementShiftClicked(item->localId());
            event->accept();
            return;
        }
    }
    QGraphicsScene::mousePressEvent(event);
}

DiagramItem *DiagramScene::itemFor(quint64 localId) const
{
    for (DiagramItem *item : diagramItems()) {
        if (item->localId() == localId)
            return item;
    }
    return nullptr;
}

} // namespace iec::editors
