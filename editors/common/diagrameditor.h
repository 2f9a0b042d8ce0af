#pragma once

#include "editors/common/diagramitem.h"
#include "editors/common/editoutcome.h"
#include "editors/common/inplaceeditor.h"
#include "editors/common/onlineview.h"
#include "model/body.h"
#include "model/element.h"
#include "model/ids.h"

#include <QHash>
#include <QPointer>
#include <QWidget>

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

class QAction;
class QDropEvent;
class QLabel;
class QToolBar;
class QUndoCommand;
class QUndoStack;
class QVBoxLayout;

namespace iec::model {
class ProjectModel;
}

namespace iec::editors {

class CompletionProvider;
class DiagramPolicy;
class DiagramScene;
class DiagramView;
class OverlayMapper;

// An Insert command dragged from an editor's tool bar onto its sheet: the action's id (UTF-8).
inline constexpr const char *kInsertActionMimeType = "application/x-iecstudio-insert-action";

// An edit of the elements shown (a copy): changes them and says what to select, or refuses.
using ElementEdit = std::function<EditOutcome(std::vector<model::Element> &elements)>;
// An edit that builds the body's elements after the gesture itself from the shown ones (an
// editor that keeps its own structure of them, as LD its networks, would only throw a copy away).
using ElementRewrite = std::function<EditOutcome(const std::vector<model::Element> &shown, std::vector<model::Element> &after)>;

// The base of every graphical editor (LD, FBD, CFC, SFC): the scene and view of one body, a tool
// bar, a message line, and everything the languages share, so that a language only adds its
// policy, its items, its pure edits and its action table.
//
// - Actions are data (ActionSpec): addActionTable() makes the QActions (objectName = id, the
//   shortcut with WidgetWithChildrenShortcut, texts translated in the subclass's class context
//   and again on LanguageChange). While online every action that changes the model is off, and
//   when its shortcut is pressed anyway it is refused with one message for all editors. Actions
//   whose `enabled` predicate says "not now" are greyed; their shortcut still runs them, so the
//   command can say why it does nothing.
// - One path from a command to one undo command: applyEdit() runs a pure edit on a copy of the
//   shown elements and pushes one SetBodyElementsCommand (refused while online, errors shown on
//   the message line, the result selected); pushCommand() for a gesture prepared by hand.
// - Keyboard: arrows navigate(), Enter activates (as a double-click), the Menu key and
//   Shift+F10 open the context menu at the selection; a right-click selects what it is on first.
// - View: zoom steps with a percentage, fit to window, export (SVG/PNG/PDF), print.
// - Online through an OverlayMapper; compiler messages on elements through setDiagnostics().
class DiagramEditor : public QWidget, public OnlineView
{
    Q_OBJECT

public:
    enum class ActionGroup { Insert, Edit, Element, View };

    struct ActionSpec {
        const char *id;         // the QAction's objectName; stable, tests and menus use it
        const char *text;       // QT_TR_NOOP in the subclass: translated in its class's context
        const char *shortcut;   // PortableText ("Ctrl+T", "Del"); "" for none
        ActionGroup group;      // Insert joins the window's Insert menu; Edit its Edit menu ...
        bool changesModel;      // refused while online
        bool onToolBar;
        std::function<void()> run;
        std::function<bool()> enabled = {}; // applies to the selection now; empty: always
        // The tool bar's shorter label (QT_TR_NOOP; the full text becomes its tool tip), so that
        // the bar fits beside the docks; nullptr: the text.
        const char *toolBarText = nullptr;
    };

    ~DiagramEditor() override;

    [[nodiscard]] DiagramScene *scene() const { return m_scene; }
    [[nodiscard]] DiagramView *view() const { return m_view; }
    [[nodiscard]] const model::BodyRef &bodyRef() const { return m_ref; }
    [[nodiscard]] model::ProjectModel &projectModel() const { return m_model; }
    [[nodiscard]] QUndoStack *undoStack() const { return m_undoStack; }

    // ---- actions
    [[nodiscard]] QAction *action(const QString &id) const;
    [[nodiscard]] QList<QAction *> actionsIn(ActionGroup group) const;
    [[nodiscard]] QList<QAction *> insertActions() const { return actionsIn(ActionGroup::Insert); }
    // Insert, Element and Edit actions with separators between the groups, enabled as they
    // apply to the selection now.
    [[nodiscard]] QList<QAction *> contextMenuActions();
    // Runs an action as its menu entry or shortcut would (refused while online when it changes
    // the model), also when it is greyed. Returns false when the command refused or failed
    // (lastMessage() says why) or when there is no such action.
    bool trigger(const QString &id);
    // The greyed/enabled state of every action, from the online state and the predicates.
    void updateActionStates();

    // ---- the message line
    [[nodiscard]] QString lastMessage() const;
    void showMessage(const QString &message);

    // ---- selection (localIds)
    [[nodiscard]] QList<quint64> selection() const;
    [[nodiscard]] std::vector<quint64> selectedIds() const;
    void select(const QList<quint64> &localIds);

    // ---- the edit path
    // Runs `edit` on a copy of the shown elements; when it succeeds and changed something, pushes
    // one SetBodyElementsCommand named `undoText` and selects what the edit says. Refused while
    // online; a refusal of the edit is shown. Returns whether the edit was done.
    bool applyEdit(const QString &undoText, const ElementEdit &edit);
    // The same path for an edit that writes the elements after it without a copy of the shown ones.
    bool applyRewrite(const QString &undoText, const ElementRewrite &rewrite);
    // The same edit, prepared without pushing: the body's elements after it (for a gesture that
    // also does something else, e.g. adds an action). The outcome's error is not shown.
    EditOutcome prepareEdit(const ElementEdit &edit, std::vector<model::Element> &bodyElements) const;
    // Pushes a prepared gesture (refused while online: the command is deleted) and selects.
    bool pushCommand(QUndoCommand *command, const QList<quint64> &selectAfter = {});
    // True (and the one refusal message shown) while online.
    bool refuseWhileOnline();

    // ---- in-place text editing
    // Opens a line over `sceneRect` (at least 160 x 24 pixels) with `text` selected, completion
    // from the completion provider as one types, F2 for the input assistant. Enter or leaving the
    // line calls `commit` with the trimmed text (the caller pushes the edit); Escape cancels.
    // Refused while online (nullptr). Going online cancels an open one.
    InPlaceEditor *editTextInPlace(const QRectF &sceneRect, const QString &text, InPlaceEditor::Completion completion,
        const std::function<void(const QString &)> &commit);
    [[nodiscard]] InPlaceEditor *inPlaceEditor() const { return m_inPlace; }

    // ---- view
    void zoomIn();
    void zoomOut();
    void resetZoom(); // 100 %
    [[nodiscard]] int zoomPercent() const;
    void fitToWindow();
    QString exportTo(const QString &path); // .svg .png .pdf; empty or a message
    void print();
    void setGridSize(int size); // the settings' grid: drawn dots and the snapping of moves

    // ---- what the app gives
    // Declared names for completion in the in-place editors (the app's model-backed provider).
    void setCompletionProvider(const CompletionProvider *provider) { m_completion = provider; }
    [[nodiscard]] const CompletionProvider *completionProvider() const { return m_completion; }
    // Compiler messages on elements of this body (by localId): marked until replaced.
    void setDiagnostics(const QList<ElementDiagnostic> &diagnostics);
    [[nodiscard]] QList<ElementDiagnostic> diagnostics() const { return m_diagnostics; }

    // ---- OnlineView
    std::optional<Place> breakpointPlace() const override;
    QString placeName(qint64 localId) const override;
    void setBreakpointMarks(const std::vector<Place> &breakpoints, std::optional<Place> halted) override;
    QString onlineInstance() const override { return m_onlineInstance; }
    QStringList onlineNames() const override;
    bool wantsChartState() const override;
    void setOnlineSnapshot(const interp::RuntimeSnapshot *snapshot) override;
    void setOnlineInstance(const QString &instance) { m_onlineInstance = instance; }
    [[nodiscard]] bool isOnline() const { return m_online; }

Q_SIGNALS:
    // The app opens that body: (POU, part kind, name) of an action or a transition.
    void openPartRequested(iec::model::PouId pou, iec::model::BodyRef::Part part, const QString &name);
    // A name used in the body is not declared: the app offers its Declare Variable dialog.
    void declareVariableRequested(const iec::model::BodyRef &body, const QString &name);
    void messageChanged(const QString &message);
    void zoomChanged(int percent);
    // Online: the user asked to give a variable a new value (double-click on a contact); the app
    // prepares it in the watch pane, where Ctrl+F7 writes and F7 forces it.
    void prepareValueRequested(const QString &name, const QString &literal);

protected:
    // `policy` draws the body; the editor owns it. The scene is built before this returns.
    DiagramEditor(model::ProjectModel &model, model::BodyRef ref, QUndoStack *undoStack,
        std::unique_ptr<DiagramPolicy> policy, QWidget *parent = nullptr);

    [[nodiscard]] DiagramPolicy &policy() const { return *m_policy; }
    // Adds the subclass's actions (in table order; onToolBar ones before the view actions).
    void addActionTable(std::span<const ActionSpec> specs);
    // A widget between the tool bar and the view (SFC: the macro level being shown).
    void addHeaderWidget(QWidget *widget);
    void setOverlayMapper(std::unique_ptr<OverlayMapper> mapper);
    // Shows a refusal or an error: trigger() then reports failure.
    void showError(const QString &message);
    // Online: the value to prepare for a variable that is `now`: the other BOOL, or one the user
    // types (nullopt when cancelled).
    std::optional<QString> askValueToPrepare(const QString &name, const QString &now);
    // Online: asks the app to prepare it (prepareValueRequested) and says how to write it; the
    // message goes once a snapshot shows the variable at that value (written or forced).
    void announcePrepared(const QString &name, const QString &literal);

    // Arrow keys: by default the nearest element in that direction (frames' centres).
    virtual void navigate(Qt::Key key);
    // A double-click on an element, or Enter with it selected (at its frame's centre).
    virtual void activateElement(quint64 localId, QPointF scenePos);
    // A shift-click: by default adds the element to the selection.
    virtual void extendSelection(quint64 localId);
    // The body's elements once the shown ones are `shown` (SFC: a macro step's inside put back
    // into the top level). Default: the shown ones are the body's.
    [[nodiscard]] virtual std::vector<model::Element> bodyElementsFor(std::vector<model::Element> shown) const;
    // A function or function block dragged from the library pane (kPouMimeType) and dropped at
    // `scenePos`: the language inserts its box there. Default: such drops are not accepted.
    [[nodiscard]] virtual bool acceptsPouDrops() const { return false; }
    virtual bool dropPou(const QString &typeName, QPointF scenePos);
    // An Insert command dragged from the tool bar (kInsertActionMimeType) and dropped at
    // `scenePos`: the language places its element there (CFC). Default: not accepted, and the
    // tool bar's buttons only click.
    [[nodiscard]] virtual bool acceptsInsertDrops() const { return false; }
    virtual bool dropInsertAction(const QString &actionId, QPointF scenePos);
    // The one command that makes the body's elements `after`: a SetBodyElementsCommand (nullptr
    // when the body keeps no elements). A language that keeps its diagram elsewhere (CODESYS's
    // CFC in addData) writes it there.
    [[nodiscard]] virtual QUndoCommand *elementsCommand(std::vector<model::Element> after, const QString &undoText);
    // A drag of movable items ended (elementsMoved) and a wire was drawn (wireDrawn): by default
    // a MoveElementsCommand and a ConnectCommand on the body's elements.
    virtual void moveElements(const QList<quint64> &localIds, const QList<QPointF> &positions);
    virtual void connectWire(quint64 source, const QString &formalParameter, quint64 target, int inputIndex);
    // Texts the subclass set itself (labels), on LanguageChange; the actions are done already.
    virtual void retranslate() { }
    // Breakpoints: the elements a breakpoint at the cursor stands for, the first naming it (by
    // default the first selected element; LD and FBD: the elements of the cursor's network).
    [[nodiscard]] virtual std::vector<quint64> breakpointElementsAtCursor() const;
    // Where the mark of the place named by `localId` goes, in scene coordinates: the band of its
    // network, else the item of that element. Empty: not shown.
    [[nodiscard]] QRectF breakpointAnchor(qint64 localId) const;
    // LD and FBD: the network (0-based) an element belongs to and the band drawn for it; a place
    // there is the whole network, "network N". -1 / empty: the language has no networks.
    [[nodiscard]] virtual int networkOfElement(qint64 localId) const
    {
        (void)localId;
        return -1;
    }
    [[nodiscard]] virtual QRectF networkBand(int network) const
    {
        (void)network;
        return {};
    }
    // Draws the marks again (after the scene changed).
    void refreshBreakpointMarks();
    // After the scene was rebuilt or updated: online styles and diagnostics are applied again by
    // the base first.
    virtual void sceneRefreshed() { }

    void changeEvent(QEvent *event) override;
    void showEvent(QShowEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;

private:
    struct ActionEntry {
        ActionSpec spec;
        QByteArray context; // translation context of spec.text
        QAction *action = nullptr;
    };

    void addActionEntries(std::span<const ActionSpec> specs, const QByteArray &context, QAction *before);
    void addViewActions();
    void runAction(const ActionEntry &entry);
    static void translateAction(const ActionEntry &entry);
    const ActionEntry *entryFor(const QString &id) const;
    bool handleKey(QKeyEvent *event);
    bool handleDrop(QEvent *event);
    bool takeDrop(QDropEvent *drop, bool takes, const std::function<void(QPointF)> &place);
    bool dragInsertButton(QObject *button, QEvent *event);
    void openContextMenu(QPoint globalPos);
    [[nodiscard]] QPoint selectionMenuPosition() const;
    void onSceneRefreshed();
    void forgetPreparedOnceWritten();
    void applyDiagnostics();
    void exportInteractive();

    model::ProjectModel &m_model;
    model::BodyRef m_ref;
    QUndoStack *m_undoStack;
    std::unique_ptr<DiagramPolicy> m_policy;
    std::unique_ptr<OverlayMapper> m_overlay;
    std::vector<Place> m_breakpointPlaces;
    std::optional<Place> m_haltedPlace;
    DiagramScene *m_scene = nullptr;
    DiagramView *m_view = nullptr;
    QToolBar *m_toolBar = nullptr;
    QAction *m_viewActionsStart = nullptr; // the tool bar's separator before the view actions
    QVBoxLayout *m_layout = nullptr;
    QLabel *m_messageLabel = nullptr;
    std::vector<std::unique_ptr<ActionEntry>> m_actions;
    QList<QAction *> m_separators;
    const CompletionProvider *m_completion = nullptr;
    QList<ElementDiagnostic> m_diagnostics;
    QString m_onlineInstance;
    bool m_online = false;
    bool m_shownOnce = false;
    std::optional<interp::RuntimeSnapshot> m_snapshot;
    struct Prepared
    {
        QString name, literal, message;
    };
    std::optional<Prepared> m_prepared; // while its message is shown
    bool m_lastCommandOk = true;
    QPointer<InPlaceEditor> m_inPlace;
    QHash<QObject *, QString> m_insertButtons; // tool bar buttons that drag their Insert command
    QPoint m_buttonPressedAt;
};

} // namespace iec::editors
