#pragma once

#include <QKeySequence>
#include <QObject>

#include <array>

class QAction;
class QMenu;
class QWidget;

namespace iec::app {

class DocumentArea;

// Edit → Cut, Copy, Paste, Delete, Select All, Find and Replace, routed to the part of the
// window that has the focus, without knowing any particular editor:
// - a text field or text editor with the focus (an ST/IL body, the declaration text, a table
//   cell being edited, a line edit) gets the command directly;
// - otherwise the widgets are asked by convention, the focus widget and its ancestors first (so
//   the project tree deletes its item), then the current document's tab and everything in it:
//   the first enabled QAction whose shortcut is the command's standard key sequence
//   (QKeySequence::Cut, ...) or whose objectName ends with the command's name ("sfcCut",
//   "editCopy", "diagramPaste", "editSelectAll", "editFind"). Graphical editors get the Edit
//   menu by giving their edit actions such names or shortcuts.
//
// The menu shows each command's keys, but the keys stay with the editors (each handles its own
// Ctrl+C, or owns an action with that shortcut): the menu's actions are Qt::WidgetShortcut, so
// they never make a key ambiguous.
class EditActions : public QObject
{
    Q_OBJECT

public:
    enum class Command { Cut, Copy, Paste, Delete, SelectAll, Find, Replace };
    static constexpr int kCommandCount = 7;

    EditActions(DocumentArea &documents, QWidget *window);

    [[nodiscard]] QAction *action(Command command) const { return m_actions[size_t(command)]; }
    void addTo(QMenu *menu) const;
    void retranslate();

    // Runs the command where the focus is (see above); false when nothing there takes it.
    bool run(Command command);

    [[nodiscard]] static QKeySequence::StandardKey standardKey(Command command);
    // The suffix of the object names that the convention looks for ("Cut", "SelectAll", ...).
    [[nodiscard]] static QString objectNameSuffix(Command command);
    // The document's action for `command` by the convention, or nullptr.
    [[nodiscard]] static QAction *documentAction(QWidget *document, Command command);

private:
    DocumentArea &m_documents;
    QWidget *m_window;
    std::array<QAction *, kCommandCount> m_actions {};
};

} // namespace iec::app
