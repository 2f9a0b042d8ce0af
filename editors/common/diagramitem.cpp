#include "editors/common/diagramitem.h"

namespace iec::editors {

DiagramItem::DiagramItem(quint64 localId, QGraphicsItem *parent)
    : QGraphicsItem(parent)
    , m_localId(localId)
{
    setFlag(ItemIsSelectable);
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

DiagramItem *diagramItemOf(QGraphicsItem *item)
{
    for (; item; item = item->parentItem()) {
        if (item->type() == DiagramItem::Type || dynamic_cast<DiagramItem *>(item))
            return dynamic_cast<DiagramItem *>(item);
    }
    return nullptr;
}

} // namespace iec::editors
