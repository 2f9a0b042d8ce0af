#pragma once

#include "editors/common/diagrameditor.h"
#include "editors/sfc/sfcedits.h"
#include "editors/sfc/sfcscene.h"

#include <functional>

class QLabel;

namespace iec::editors::sfc {

// The body a new SFC POU or action starts with, as in CODESYS: the initial step "Init", a
// transition TRUE and a jump back to Init, wired and laid out (valid PLCopen that compiles).
[[nodiscard]] model::Body newChartBody();

// The SFC editor: the chart of one body on the shared diagram framework, edited with the
// structured commands of CoDeSys 2.3 / RunPro. Every command is a pure edit of sfcedits.h run
// through edit() (which keeps the chart valid, places what it adds without moving the rest more
// than needed, and pushes one undo step); the commands are rows of the action table
// (sfcactions.cpp), triggered by the tool bar, the menus, the keys or trigger("sfcStepAfter").
class SfcEditor : public DiagramEditor
{
    Q_OBJECT

public:
    SfcEditor(model::ProjectModel &model, model::BodyRef ref, QUndoStack *undoStack, QWidget *parent = nullptr);
    ~SfcEditor() override;

    // The structure of the level shown, read from the model.
    [[nodiscard]] ChartDocument document() const;
    // The localId of the step with that name on the level shown (0 when none).
    [[nodiscard]] quint64 stepId(const QString &name) const;
    // "step Fill", "the transition after Fill", "the actions of Fill" for the status bar.
    QString placeName(qint64 localId) const override;

    // The one path of every chart command: `change` edits a copy of the level shown (with the
    // selection at the time of the call); the result is wired, placed and pushed as one undo
    // step named `undoText`. Refused while online; a refusal is shown. Returns whether it was done.
    using ChartEdit = std::function<EditResult(ChartDocument &document, const std::vector<quint64> &selection)>;
    bool edit(const QString &undoText, const ChartEdit &change);

    // Lays the level shown out again automatically (one undo step). Edits otherwise keep the
    // positions the chart has and place only what they add.
    bool arrangeChart();
    // Double-click on a step's "E"/"X"/triangle corner: names the action (<Step>_entry, ...) when
    // the step has none, creates the POU action when it does not exist (one undo step), and asks
    // to open it.
    bool openStepAction(quint64 stepId, const QString &which); // "entry", "exit", "active"
    // Gives a step `changed` properties as one undo step named `undoText`; the POU actions they
    // name (entry, exit, active) that the POU does not have are created in ST in the same step.
    // A refusal is shown. Returns whether it was done (also when there was nothing to do).
    bool changeStep(quint64 stepId, const StepProperties &changed, const QString &undoText);
    // Why changeStep would refuse `changed` (setStepProperties' rule), or empty.
    [[nodiscard]] QString stepChangeProblem(quint64 stepId, const StepProperties &changed) const;

    // ---- macro steps: which level is shown
    bool enterMacro(quint64 macroId);
    bool leaveMacro();
    [[nodiscard]] const std::vector<quint64> &macroPath() const { return sfcPolicy().macroPath(); }

protected:
    void activateElement(quint64 localId, QPointF scenePos) override;
    void extendSelection(quint64 localId) override;
    [[nodiscard]] std::vector<model::Element> bodyElementsFor(std::vector<model::Element> shown) const override;
    void retranslate() override;

private:
    [[nodiscard]] SfcPolicy &sfcPolicy() const { return static_cast<SfcPolicy &>(policy()); }
    void createActions(); // sfcactions.cpp
    // The ChartEdit as an edit of the shown elements (wired and placed afterwards).
    [[nodiscard]] ElementEdit chartEdit(const ChartEdit &change, std::vector<quint64> selection) const;
    void placeLevel(const ChartDocument &before, ChartDocument &edited) const;
    [[nodiscard]] quint64 selectedOfKind(bool steps) const;
    [[nodiscard]] bool selectionHas(bool (*kind)(const model::Element &)) const;
    void copySelection();
    void cutSelection();
    void paste();
    void editConditionInPlace(quint64 transitionId);
    void editStepDialog(quint64 stepId);
    void editActionsDialog(quint64 stepId);
    void editPriorityDialog(quint64 transitionId);
    void chooseJumpTarget(bool withTransition);
    void updateLevelLabel();

    QLabel *m_levelLabel = nullptr;
    quint64 m_shiftAnchor = 0;
};

} // namespace iec::editors::sfc
