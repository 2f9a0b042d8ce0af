#pragma once

#include <QObject>
#include <QPointer>

class QAction;
class QPlainTextEdit;
class QUndoGroup;

namespace iec::app {

// Edit → Undo and Redo. They act on the undo group's active stack, except while a text editor is
// the current document: typing lives in the QTextDocument's own undo history (DESIGN.md), so
// there the actions undo and redo the typing, as the editor's own Ctrl+Z does.
class UndoActions : public QObject
{
    Q_OBJECT

public:
    UndoActions(QUndoGroup &group, QObject *parent);

    [[nodiscard]] QAction *undoAction() const { return m_undo; }
    [[nodiscard]] QAction *redoAction() const { return m_redo; }
    // The editor whose typing the actions work on; nullptr: the group's active stack.
    void setTextEditor(QPlainTextEdit *editor);
    // Online nothing may change: both actions stay off until unlocked.
    void setLocked(bool locked);
    [[nodiscard]] bool isLocked() const { return m_locked; }
    void retranslate();

private:
    void undo();
    void redo();
    void update();

    QUndoGroup &m_group;
    QPointer<QPlainTextEdit> m_editor;
    QAction *m_undo;
    QAction *m_redo;
    bool m_locked = false;
};

} // namespace iec::app
