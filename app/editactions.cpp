#include "app/editactions.h"

#include "app/documentarea.h"
#include "editors/common/diagrameditor.h"
#include "editors/text/codeeditor.h"
#include "editors/text/findreplacebar.h"
#include "editors/text/texteditorwidget.h"

#include <QAction>
#include <QApplication>
#include <QLineEdit>
#include <QMenu>
#include <QPlainTextEdit>
#include <QTextEdit>

#include <algorithm>

namespace iec::app {

namespace {

using Command = EditActions::Command;

// The commands a text widget has slots for; deleting is the widget kind's own business.
template <typename Edit, typename Remove>
bool runTextCommand(Edit *edit, Command command, Remove remove)
{
    switch (command) {
    case Command::Cut:
        edit->cut();
        return true;
    case Command::Copy:
        edit->copy();
        return true;
    case Command::Paste:
        edit->paste();
        return true;
    case Command::Delete:
        remove();
        return true;
    case Command::SelectAll:
        edit->selectAll();
        return true;
    default:
        return false;
    }
}

// Deletes the selection, or the character after the cursor, as the Delete key does.
template <typename TextEdit>
void deleteInText(TextEdit *edit)
{
    if (edit->isReadOnly())
        return;
    QTextCursor cursor = edit->textCursor();
    if (cursor.hasSelection())
        cursor.removeSelectedText();
    else
        cursor.deleteChar();
}

// Cut, Copy, ... on a text widget; Find and Replace belong to the editor around it.
bool runOnTextWidget(QWidget *widget, Command command)
{
    if (auto *line = qobject_cast<QLineEdit *>(widget))
        return runTextCommand(line, command, [line] { line->del(); });
    if (auto *plain = qobject_cast<QPlainTextEdit *>(widget))
        return runTextCommand(plain, command, [plain] { deleteInText(plain); });
    if (auto *rich = qobject_cast<QTextEdit *>(widget))
        return runTextCommand(rich, command, [rich] { deleteInText(rich); });
    return false;
}

bool matchesCommand(const QAction *action, Command command, bool enabledOnly)
{
    if (enabledOnly && !action->isEnabled())
        return false;
    if (action->objectName().endsWith(EditActions::objectNameSuffix(command), Qt::CaseInsensitive))
        return true;
    const QList<QKeySequence> standard = QKeySequence::keyBindings(EditActions::standardKey(command));
    return std::ranges::any_of(action->shortcuts(), [&](const QKeySequence &keys) { return standard.contains(keys); });
}

QAction *findIn(const QList<QAction *> &actions, Command command, bool enabledOnly = true)
{
    const auto it = std::ranges::find_if(actions, [&](const QAction *a) { return matchesCommand(a, command, enabledOnly); });
    return it == actions.end() ? nullptr : *it;
}

} // namespace

EditActions::EditActions(DocumentArea &documents, QWidget *window)
    : QObject(window)
    , m_documents(documents)
    , m_window(window)
{
    static const char *const names[kCommandCount] {
        "cutAction", "copyAction", "pasteAction", "deleteEditAction", "selectAllAction", "findAction", "replaceAction"};
    for (int index = 0; index < kCommandCount; ++index) {
        auto *action = new QAction(this);
        const auto command = Command(index);
        action->setObjectName(QString::fromLatin1(names[index]));
        action->setShortcuts(standardKey(command));
        // Shown in the menu, handled by the editors (see the class comment).
        action->setShortcutContext(Qt::WidgetShortcut);
        connect(action, &QAction::triggered, this, [this, command] { run(command); });
        m_actions[size_t(index)] = action;
    }
    retranslate();
}

QKeySequence::StandardKey EditActions::standardKey(Command command)
{
    switch (command) {
    case Command::Cut:
        return QKeySequence::Cut;
    case Command::Copy:
        return QKeySequence::Copy;
    case Command::Paste:
        return QKeySequence::Paste;
    case Command::Delete:
        return QKeySequence::Delete;
    case Command::SelectAll:
        return QKeySequence::SelectAll;
    case Command::Find:
        return QKeySequence::Find;
    case Command::Replace:
        return QKeySequence::Replace;
    }
    return QKeySequence::UnknownKey;
}

QString EditActions::objectNameSuffix(Command command)
{
    static const char *const suffixes[kCommandCount] {"Cut", "Copy", "Paste", "Delete", "SelectAll", "Find", "Replace"};
    return QString::fromLatin1(suffixes[int(command)]);
}

void EditActions::retranslate()
{
    action(Command::Cut)->setText(tr("Cu&t"));
    action(Command::Copy)->setText(tr("&Copy"));
    action(Command::Paste)->setText(tr("&Paste"));
    action(Command::Delete)->setText(tr("&Delete"));
    action(Command::SelectAll)->setText(tr("Select &All"));
    action(Command::Find)->setText(tr("&Find..."));
    action(Command::Replace)->setText(tr("R&eplace..."));
}

void EditActions::addTo(QMenu *menu) const
{
    for (const Command command : {Command::Cut, Command::Copy, Command::Paste, Command::Delete})
        menu->addAction(action(command));
    menu->addSeparator();
    menu->addAction(action(Command::SelectAll));
    menu->addSeparator();
    menu->addAction(action(Command::Find));
    menu->addAction(action(Command::Replace));
}

QAction *EditActions::documentAction(QWidget *document, Command command)
{
    if (!document)
        return nullptr;
    if (QAction *found = findIn(document->actions(), command))
        return found;
    for (QWidget *widget : document->findChildren<QWidget *>()) {
        if (QAction *found = findIn(widget->actions(), command))
            return found;
    }
    return findIn(document->findChildren<QAction *>(), command);
}

bool EditActions::run(Command command)
{
    QWidget *focus = QApplication::focusWidget();
    const bool focusInWindow = focus && m_window->isAncestorOf(focus);
    const bool textCommand = command != Command::Find && command != Command::Replace;
    if (focusInWindow && textCommand && runOnTextWidget(focus, command))
        return true;
    // The part with the focus (an editor in a splitter, the project tree) owns its commands ...
    for (QWidget *widget = focusInWindow ? focus : nullptr; widget && widget != m_window; widget = widget->parentWidget()) {
        if (QAction *found = findIn(widget->actions(), command)) {
            found->trigger();
            return true;
        }
    }
    // ... else the current document does.
    if (QAction *found = documentAction(m_documents.currentWidget(), command)) {
        found->trigger();
        return true;
    }
    // A greyed command of the current diagram (online, or nothing selected it applies to) still
    // runs, so that it says why it does nothing, as its shortcut does.
    if (editors::DiagramEditor *diagram = m_documents.currentDiagramEditor(); diagram && textCommand) {
        if (QAction *greyed = findIn(diagram->actions(), command, false)) {
            diagram->trigger(greyed->objectName());
            return true;
        }
    }
    // A text body whose editor lost the focus to the menu bar or a pane.
    const std::optional<model::BodyRef> body = m_documents.currentBody();
    editors::CodeEditor *editor = body ? m_documents.textEditorFor(*body) : nullptr;
    return editor && textCommand && runOnTextWidget(editor, command);
}

} // namespace iec::app
