#pragma once

#include "editors/common/onlineview.h"
#include "editors/sfc/sfcedits.h"
#include "editors/sfc/sfcscene.h"
#include "model/ids.h"

#include <QWidget>

#include <functional>
#include <optional>

class QAction;
class QLabel;
class QLineEdit;
class QToolBar;
class QUndoStack;

namespace iec::model {
class ProjectModel;
}

namespace iec::editors {
class DiagramScene;
class DiagramView;
}

namespace iec::editors::sfc {

// The SFC editor: the chart of one body on the shared diagram framework, edited with the
// structured commands of CoDeSys 2.3 / RunPro (every command keeps the chart valid, places what
// it adds without moving the rest more than needed, and goes on the undo stack as one step). The
// public functions are the commands the toolbar, the context menu and the keys trigger; they
// return false (and show why) when refused.
class SfcEditor : public QWidget, public OnlineView
{
    Q_OBJECT

public:
    SfcEditor(model::ProjectModel &model, model::BodyRef ref, QUndoStack *undoStack, QWidget *parent = nullptr);
    ~SfcEditor() override;

    [[nodiscard]] DiagramScene *scene() const { return m_scene; }
    [[nodiscard]] DiagramView *view() const { return m_view; }
    [[nodiscard]] const model::BodyRef &bodyRef() const { return m_ref; }
    [[nodiscard]] QString lastMessage() const;
    [[nodiscard]] QAction *action(const QString &objectName) const; // toolbar and menu actions
    [[nodiscard]] QList<QAction *> insertActions() const; // for the window's Insert menu

    // The structure of the level shown, read from the model.
    [[nodiscard]] ChartDocument document() const;
    [[nodiscard]] QList<quint64> selection() const;
    void select(const QList<quint64> &localIds);
    // The localId of the step or transition with that name/condition text (for tests and Find).
    [[nodiscard]] quint64 stepId(const QString &name) const;

    // ---- structured commands on the selection
    bool createChart();
    bool insertStepTransitionAfter();
    bool insertStepTransitionBefore();
    bool insertAlternativeBranch(bool right);
    bool insertParallelBranch(bool right);
    bool insertJump(const QString &target);
    bool insertTransitionJump(const QString &target);
    bool insertMacroStep();
    bool deleteSelection();
    bool copySelection();
    bool cutSelection();
    bool paste();
    // Lays the whole chart (the level shown) out again automatically: one undo step. Edits
    // otherwise keep the positions the chart has and place only what they add.
    bool arrangeChart();

    // ---- properties
    bool setStepProperties(quint64 stepId, const StepProperties &properties);
    bool addActionAssociation(quint64 stepId, const model::ActionBlockAction &action, int index = -1);
    bool changeActionAssociation(quint64 stepId, int index, const model::ActionBlockAction &action);
    bool removeActionAssociation(quint64 stepId, int index);
    bool moveActionAssociation(quint64 stepId, int from, int to);
    bool setTransitionCondition(quint64 transitionId, const QString &stText);
    bool setTransitionReference(quint64 transitionId, const QString &transitionName);
    bool setTransitionPriority(quint64 transitionId, std::optional<quint64> priority);
    // Double-click on a step's "E"/"X"/triangle corner: names the action (<Step>_entry, ...) when
    // the step has none, creates the POU action when it does not exist, and asks to open it.
    bool openStepAction(quint64 stepId, const QString &which); // "entry", "exit", "active"

    // ---- macro steps
    bool enterMacro(quint64 macroId);
    bool leaveMacro();
    [[nodiscard]] const std::vector<quint64> &macroPath() const { return m_policy.macroPath(); }

    // ---- view
    void moveSelection(Qt::Key key); // arrow keys: the nearest element in that direction
    void fitToWindow();
    QString exportTo(const QString &path); // .svg .png .pdf; empty or a message
    void print();

    // ---- OnlineView
    QString onlineInstance() const override;
    QStringList onlineNames() const override;
    void setOnlineSnapshot(const interp::RuntimeSnapshot *snapshot) override;
    void setOnlineInstance(const QString &instance) { m_onlineInstance = instance; }
    [[nodiscard]] bool isOnline() const { return m_online; }

Q_SIGNALS:
    // The app opens the body: (POU, part kind, name) of an action or a transition.
    void openPartRequested(iec::model::PouId pou, iec::model::BodyRef::Part part, const QString &name);
    void messageChanged(const QString &message);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;

private:
    bool refuseWhenOnline();
    [[nodiscard]] std::vector<quint64> selectedIds() const;
    // One chart command: `change` edits a copy of the current level, which is committed as one
    // undo step named `text` (refused while online, the error shown when it fails).
    bool edit(const QString &text, const std::function<EditResult(ChartDocument &)> &change);
    bool commit(ChartDocument document, const EditResult &result, const QString &text);
    void placeLevel(const ChartDocument &before, ChartDocument &edited) const;
    bool pushLevel(std::vector<model::Element> level, const QString &text);
    void showMessage(const QString &message);
    void createActions();
    void onDoubleClicked(quint64 localId, QPointF scenePos);
    void onShiftClicked(quint64 localId);
    void editConditionInPlace(quint64 transitionId);
    void editStepDialog(quint64 stepId);
    void editActionsDialog(quint64 stepId);
    void chooseJumpTarget(bool withTransition);
    void applyOnlineState();
    void updateLevelLabel();
    [[nodiscard]] quint64 selectedOfKind(bool steps) const;

    model::ProjectModel &m_model;
    model::BodyRef m_ref;
    QUndoStack *m_undoStack;
    SfcPolicy m_policy;
    DiagramScene *m_scene = nullptr;
    DiagramView *m_view = nullptr;
    QToolBar *m_toolBar = nullptr;
    QLabel *m_levelLabel = nullptr;
    QLabel *m_messageLabel = nullptr;
    QLineEdit *m_inlineEditor = nullptr;
    quint64 m_shiftAnchor = 0;
    QString m_onlineInstance;
    bool m_online = false;
    std::optional<interp::sfc::ChartState> m_chartState;
};

} // namespace iec::editors::sfc
