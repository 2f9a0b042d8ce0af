#include "editors/common/diagramitem.h"

#include "editors/common/diagramscene.h"

#include <QPen>

namespace iec::editors {

DiagramItem::DiagramItem(quint64 localId, QGraphicsItem *parent)
    : QGraphicsItem(parent)
    , m_localId(localId)
{
    setFlag(ItemIsSelectable);
}

DiagramItem::~DiagramItem()
{
    // While the scene is being destroyed it is no DiagramScene any more, and forgets nothing.
    if (auto *diagram = dynamic_cast<DiagramScene *>(scene()))
        diagram->forget(this);
}

QRectF DiagramItem::frame() const
{
    return sceneBoundingRect();
}

QList<Pin> DiagramItem::pins() const
{
    return {};
}

void DiagramItem::setActive(bool active)
{
    if (m_active == active)
        return;
    m_active = active;
    update();
}

void DiagramItem::setOnlineText(const QString &text)
{
    if (m_onlineText == text)
        return;
    prepareGeometryChange();
    m_onlineText = text;
    update();
}

void DiagramItem::setDiagnostic(ElementDiagnostic::Severity severity, const QString &message)
{
    if (message.isEmpty()) {
        clearDiagnostic();
        return;
    }
    if (m_diagnostic.isEmpty())
        m_toolTipBefore = toolTip();
    m_diagnostic = message;
    delete m_diagnosticMark;
    // A child item: it follows the element and goes with it; clicks on it select the element.
    auto *mark = new QGraphicsRectItem(mapRectFromScene(frame()).adjusted(-3, -3, 3, 3), this);
    QPen pen(severity == ElementDiagnostic::Severity::Error ? QColor(0xd0, 0x10, 0x10) : QColor(0xe0, 0x80, 0x00), 1.5);
    pen.setStyle(Qt::DashLine);
    pen.setCosmetic(true);
    mark->setPen(pen);
    mark->setBrush(Qt::NoBrush);
    mark->setToolTip(message);
    m_diagnosticMark = mark;
    setToolTip(m_toolTipBefore.isEmpty() ? message : message + QLatin1Char('\n') + m_toolTipBefore);
}

void DiagramItem::clearDiagnostic()
{
    if (m_diagnostic.isEmpty())
        return;
    delete m_diagnosticMark;
    m_diagnosticMark = nullptr;
    m_diagnostic.clear();
    setToolTip(m_toolTipBefore);
}

DiagramItem *diagramItemOf(QGraphicsItem *item)
{
    for (; item; item = item->parentItem()) {
        if (item->type() == DiagramItem::Type)
            return static_cast<DiagramItem *>(item);
        if (auto *diagramItem = dynamic_cast<DiagramItem *>(item))
            return diagramItem;
    }
    return nullptr;
}

} // namespace iec::editors
