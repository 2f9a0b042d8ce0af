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
    const QMimeData *mime = drop->mimeData();
    const QString insertType = QString::fromLatin1(kInsertActionMimeType);
    const QString pouType = QString::fromLatin1(kPouMimeType);
    if (mime->hasFormat(insertType)) {
        // Only this editor's Insert commands land; anything else is refused (the no-drop cursor).
        const QString id = QString::fromUtf8(mime->data(insertType));
        const bool ours = acceptsInsertDrops() && insertActions().contains(action(id));
        return takeDrop(drop, ours, [this, id](QPointF at) { dropInsertAction(id, at); });
    }
    if (!acceptsPouDrops() || !mime->hasFormat(pouType))
        return false;
    const QString typeName = QString::fromUtf8(mime->data(pouType));
    return takeDrop(drop, true, [this, typeName](QPointF at) { dropPou(typeName, at); });
}

// Accepts a drag this editor takes (refused while online, with the message every edit gives
// there) and, on the drop, runs `place` at the drop's place on the sheet.
bool DiagramEditor::takeDrop(QDropEvent *drop, bool takes, const std::function<void(QPointF)> &place)
{
    if (!takes || m_online) {
        if (takes && drop->type() == QEvent::Drop)
            refuseWhileOnline();
        drop->ignore();
        return true;
    }
    drop->setDropAction(Qt::CopyAction);
    drop->accept();
    if (drop->type() == QEvent::Drop) {
        setFocus();
        place(m_view->mapToScene(drop->position().toPoint()));
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
