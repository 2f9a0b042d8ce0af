#include "app/undoactions.h"

#include <QAction>
#include <QApplication>
#include <QPlainTextEdit>
#include <QStyle>
#include <QUndoGroup>
#include <QUndoStack>

namespace iec::app {

UndoActions::UndoActions(QUndoGroup &group, QObject *parent)
    : QObject(parent)
    , m_group(group)
    , m_undo(new QAction(this))
    , m_redo(new QAction(this))
{
    m_undo->setObjectName(QStringLiteral("undoAction"));
    m_redo->setObjectName(QStringLiteral("redoAction"));
    m_undo->setShortcut(QKeySequence::Undo);
    // Ctrl+Y redoes too wherever the platform's Redo is another key (CODESYS, Windows habits).
    QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
    if (const QKeySequence ctrlY(Qt::CTRL | Qt::Key_Y); !redoKeys.contains(ctrlY))
        redoKeys << ctrlY;
    m_redo->setShortcuts(redoKeys);
    // The desktop's icons where there is a theme, the style's arrows everywhere else.
    const QStyle *style = QApplication::style();
    m_undo->setIcon(QIcon::fromTheme(QStringLiteral("edit-undo"), style->standardIcon(QStyle::SP_ArrowBack)));
    m_redo->setIcon(QIcon::fromTheme(QStringLiteral("edit-redo"), style->standardIcon(QStyle::SP_ArrowForward)));
    connect(m_undo, &QAction::triggered, this, &UndoActions::undo);
    connect(m_redo, &QAction::triggered, this, &UndoActions::redo);
    connect(&group, &QUndoGroup::canUndoChanged, this, &UndoActions::update);
    connect(&group, &QUndoGroup::canRedoChanged, this, &UndoActions::update);
    connect(&group, &QUndoGroup::undoTextChanged, this, &UndoActions::update);
    connect(&group, &QUndoGroup::redoTextChanged, this, &UndoActions::update);
    connect(&group, &QUndoGroup::activeStackChanged, this, &UndoActions::update);
    retranslate();
}

void UndoActions::setTextEditor(QPlainTextEdit *editor)
{
    if (m_editor == editor)
        return;
    if (m_editor)
        m_editor->document()->disconnect(this);
    m_editor = editor;
    if (m_editor) {
        connect(m_editor->document(), &QTextDocument::undoAvailable, this, &UndoActions::update);
        connect(m_editor->document(), &QTextDocument::redoAvailable, this, &UndoActions::update);
    }
    update();
}

void UndoActions::setLocked(bool locked)
{
    m_locked = locked;
    update();
}

void UndoActions::undo()
{
    if (m_locked)
        return;
    if (m_editor)
        m_editor->undo();
    else
        m_group.undo();
}

void UndoActions::redo()
{
    if (m_locked)
        return;
    if (m_editor)
        m_editor->redo();
    else
        m_group.redo();
}

void UndoActions::retranslate()
{
    update();
}

void UndoActions::update()
{
    if (m_editor) {
        m_undo->setEnabled(m_editor->document()->isUndoAvailable());
        m_redo->setEnabled(m_editor->document()->isRedoAvailable());
        m_undo->setText(tr("&Undo Typing"));
        m_redo->setText(tr("&Redo Typing"));
    } else {
        m_undo->setEnabled(m_group.canUndo());
        m_redo->setEnabled(m_group.canRedo());
        // The command's own text tells what will be undone, as in every Qt application.
        m_undo->setText(m_group.canUndo() ? tr("&Undo %1").arg(m_group.undoText()) : tr("&Undo"));
        m_redo->setText(m_group.canRedo() ? tr("&Redo %1").arg(m_group.redoText()) : tr("&Redo"));
    }
    if (m_locked) {
        m_undo->setEnabled(false);
        m_redo->setEnabled(false);
    }
}

} // namespace iec::app
