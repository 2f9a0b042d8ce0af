#pragma once

#include "app/documentarea.h"
#include "editors/common/onlineview.h"
#include "interpreter/runtime/debugging.h"
#include "model/ids.h"
#include "model/project.h"

#include <QObject>

#include <optional>
#include <vector>

class QAction;
class QMenu;
class QStatusBar;
class QToolBar;

namespace iec::model {
class ProjectModel;
}

namespace iec::app {

class MessagesPane;
class OnlineController;

// Breakpoints and stepping in the window (docs/debugging.md): Toggle Breakpoint (F9) on the
// place at the cursor of the current editor, or a click in a text editor's margin; Step Over
// (F10), Step Into (F8), Step Out (Shift+F10). Breakpoints belong to bodies (ids, so a rename
// keeps them) and are shown in every open editor, offline and online. When the program halts,
// the body it halted in is opened and the place shown, the status bar says where, and the call
// stack is listed in the messages pane (an entry opens its place).
class DebugController : public QObject
{
    Q_OBJECT

public:
    struct StoredBreakpoint {
        model::BodyRef body;
        editors::OnlineView::Place place;
        interp::Breakpoint settings; // hit rule, condition, enabled; `at` is filled in when sent
    };

    DebugController(model::ProjectModel &projectModel, DocumentArea &documents, OnlineController &online,
                    MessagesPane &messages, QStatusBar &statusBar, QObject *parent = nullptr);

    void addTo(QMenu *menu, QToolBar *toolBar);
    void retranslate();

    [[nodiscard]] const std::vector<StoredBreakpoint> &breakpoints() const { return m_breakpoints; }
    // The project as it is to be saved: with the breakpoints in our own addData (the model
    // itself is not changed; breakpoints are no edit of the program).
    [[nodiscard]] model::Project projectToSave() const;
    [[nodiscard]] QAction *toggleBreakpointAction() const { return m_toggle; }
    [[nodiscard]] QAction *stepOverAction() const { return m_stepOver; }
    [[nodiscard]] QAction *stepIntoAction() const { return m_stepInto; }
    [[nodiscard]] QAction *stepOutAction() const { return m_stepOut; }
    [[nodiscard]] QAction *runToCursorAction() const { return m_runToCursor; }

public Q_SLOTS:
    // F9: on the place at the cursor of the current editor.
    void toggleBreakpointAtCursor();
    void toggleBreakpoint(const model::BodyRef &body, const editors::OnlineView::Place &place);
    void removeAllBreakpoints();
    // Breakpoint Properties… for the place at the cursor (a new breakpoint when there is none).
    void editBreakpointAtCursor();
    // Run to Cursor (Ctrl+F10): runs (logging in when needed) until the place at the cursor is
    // reached, as if a breakpoint were there, which goes once the program halts anywhere.
    void runToCursor();
    // Sets (or creates) the breakpoint at a place with the given hit rule, condition and state.
    void setBreakpointSettings(const model::BodyRef &body, const editors::OnlineView::Place &place,
                               const interp::Breakpoint &settings);

Q_SIGNALS:
    void breakpointsChanged();

private:
    void loadFromProject();
    void sendBreakpoints();
    void breakpointsEdited();
    // A text body changed: its breakpoints move with their lines (breakpointlines.h).
    void followTextEdit(const model::BodyRef &body);
    // The texts of the bodies that have line breakpoints, to compare the next edit with.
    void rememberTexts();
    void refreshMarks();
    void showHalt(const interp::RuntimeSnapshot &snapshot);
    void listCallStack();
    void updateActions();
    [[nodiscard]] QString ownerName(const model::BodyRef &body) const;
    [[nodiscard]] std::optional<std::pair<model::BodyRef, editors::OnlineView::Place>> placeAtCursor() const;
    [[nodiscard]] std::optional<model::BodyRef> bodyOfOwner(const QString &owner) const;

    model::ProjectModel &m_projectModel;
    DocumentArea &m_documents;
    OnlineController &m_online;
    MessagesPane &m_messages;
    QStatusBar &m_statusBar;
    std::vector<StoredBreakpoint> m_breakpoints;
    std::vector<std::pair<model::BodyRef, QString>> m_textsUnderBreakpoints;
    std::optional<interp::HaltInfo> m_halt;
    QString m_haltMessage; // the status bar's "Halted in …", cleared when the program goes on
    QAction *m_toggle = nullptr;
    QAction *m_removeAll = nullptr;
    QAction *m_properties = nullptr;
    QAction *m_stepOver = nullptr;
    QAction *m_stepInto = nullptr;
    QAction *m_stepOut = nullptr;
    QAction *m_runToCursor = nullptr;
    std::optional<StoredBreakpoint> m_cursorTarget; // Run to Cursor's breakpoint until a halt
};

} // namespace iec::app
