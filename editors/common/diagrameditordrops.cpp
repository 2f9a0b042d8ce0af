// The diagram editor's drag and drop: the tool bar's Insert buttons dragged onto the sheet, and
// what the sheet accepts (Insert commands, POUs from the library).
#include "editors/common/diagrameditor.h"

#include "editors/common/diagramview.h"
#include "editors/text/calltext.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QDrag>
#include <QDropEvent>
#include <QMimeData>
#include <QMouseEvent>

namespace iec::editors {

// A press and a move beyond the drag distance on an Insert button drags its command onto the
// sheet; a plain click still runs it.
bool DiagramEditor::dragInsertButton(QObject *button, QEvent *event)
{
    if (event->type() == QEvent::MouseButtonPress) {
        m_buttonPressedAt = static_cast<QMouseEvent *>(event)->position().toPoint();
        return false;
    }
    if (event->type() != QEvent::MouseMove)
        return false;
    const auto *mouse = static_cast<QMouseEvent *>(event);
    if (!(mouse->buttons() & Qt::LeftButton)
        || (mouse->position().toPoint() - m_buttonPressedAt).manhattanLength() < QApplication::startDragDistance())
        return false;
    auto *widget = static_cast<QWidget *>(button);
    auto *mime = new QMimeData;
    mime->setData(QString::fromLatin1(kInsertActionMimeType), m_insertButtons.value(button).toUtf8());
    auto *drag = new QDrag(widget);
    drag->setMimeData(mime);
    drag->setPixmap(widget->grab());
    if (auto *tool = qobject_cast<QAbstractButton *>(widget))
        tool->setDown(false); // the drag took the press: no click afterwards
    drag->exec(Qt::CopyAction);
    return true;
}

bool DiagramEditor::handleDrop(QEvent *event)
{
    const QEvent::Type type = event->type();
    if (type != QEvent::DragEnter && type != QEvent::DragMove && type != QEvent::Drop)
        return false;
    auto *drop = static_cast<QDropEvent *>(event);
    const QString insertType = QString::fromLatin1(kInsertActionMimeType);
    if (drop->mimeData()->hasFormat(insertType)) {
        // Only this editor's Insert commands land; anything else is refused (the no-drop cursor).
        const QString insertId = QString::fromUtf8(drop->mimeData()->data(insertType));
        if (!acceptsInsertDrops() || !insertActions().contains(action(insertId))) {
            drop->ignore();
            return true;
        }
        if (m_online) {
            if (type == QEvent::Drop)
                refuseWhileOnline();
            drop->ignore();
            return true;
        }
        drop->setDropAction(Qt::CopyAction);
        drop->accept();
        if (type == QEvent::Drop) {
            setFocus();
            dropInsertAction(insertId, m_view->mapToScene(drop->position().toPoint()));
        }
        return true;
    }
    const QString mimeType = QString::fromLatin1(kPouMimeType);
    if (!acceptsPouDrops() || !drop->mimeData()->hasFormat(mimeType))
        return false;
    if (m_online) { // refused with the message every edit gives while online
        if (type == QEvent::Drop)
            refuseWhileOnline();
        drop->ignore();
        return true;
    }
    drop->setDropAction(Qt::CopyAction);
    drop->accept();
    if (type == QEvent::Drop) {
        const QString typeName = QString::fromUtf8(drop->mimeData()->data(mimeType));
        setFocus();
        dropPou(typeName, m_view->mapToScene(drop->position().toPoint()));
    }
    return true;
}

bool DiagramEditor::dropPou(const QString &, QPointF)
{
    return false;
}

bool DiagramEditor::dropInsertAction(const QString &, QPointF)
{
    return false;
}

} // namespace iec::editors
