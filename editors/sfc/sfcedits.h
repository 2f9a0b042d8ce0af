#pragma once

#include "editors/common/editoutcome.h"
#include "editors/sfc/sfcstructure.h"

#include "model/sfcoptions.h"

#include <QString>

#include <optional>
#include <vector>

// The structured edits of the SFC editor (CoDeSys 2.3 / RunPro commands) as pure functions on a
// ChartDocument. Each takes the selection (localIds), changes the document so that the chart stays
// valid, and says what to select next, or refuses with a message the user reads. The editor then
// wires, lays out and pushes the result as one undo command.
namespace iec::editors::sfc {

using EditResult = EditOutcome; // the framework's: an error, or what to select

// A new chart (CODESYS: a new SFC POU): the initial step "Init", a transition TRUE, a jump to Init.
EditResult createDefaultChart(ChartDocument &document);

EditResult insertStepTransition(ChartDocument &document, const std::vector<quint64> &selection, bool after);
EditResult insertMacroStep(ChartDocument &document, const std::vector<quint64> &selection, bool after);
EditResult insertAlternativeBranch(ChartDocument &document, const std::vector<quint64> &selection, bool right);
EditResult insertParallelBranch(ChartDocument &document, const std::vector<quint64> &selection, bool right);
EditResult insertJump(ChartDocument &document, const std::vector<quint64> &selection, const QString &target);
EditResult insertTransitionJump(ChartDocument &document, const std::vector<quint64> &selection, const QString &target);
EditResult deleteSelection(ChartDocument &document, const std::vector<quint64> &selection);

// Step properties (the step dialog).
struct StepProperties {
    QString name;
    bool initial = false;
    model::StepOptions options;
    QString comment;

    bool operator==(const StepProperties &) const = default;
};
std::optional<StepProperties> stepProperties(const ChartDocument &document, quint64 stepId);
// The entry, exit and active action names a step's options give (the empty ones left out).
QStringList stepActionNames(const model::StepOptions &options);
// Renames jumps that pointed to the old name too. Refuses action names that are no identifiers.
EditResult setStepProperties(ChartDocument &document, quint64 stepId, const StepProperties &properties);

// IEC action associations of a step (its action block).
std::vector<model::ActionBlockAction> stepActions(const ChartDocument &document, quint64 stepId);
model::ActionBlockAction actionAssociation(const QString &qualifier, const QString &name, const QString &duration = {},
    const QString &indicator = {});
EditResult addAction(ChartDocument &document, quint64 stepId, model::ActionBlockAction action, int index = -1);
EditResult changeAction(ChartDocument &document, quint64 stepId, int index, model::ActionBlockAction action);
EditResult removeAction(ChartDocument &document, quint64 stepId, int index);
EditResult moveAction(ChartDocument &document, quint64 stepId, int from, int to);

// Transitions: an inline ST condition, or the name of a transition part of the POU.
EditResult setInlineCondition(ChartDocument &document, quint64 transitionId, const QString &stText);
EditResult setConditionReference(ChartDocument &document, quint64 transitionId, const QString &transitionName);
EditResult setPriority(ChartDocument &document, quint64 transitionId, std::optional<quint64> priority);

// A copied range of a chain: its nodes and every element they stand for.
struct Fragment {
    Sequence nodes;
    std::vector<model::Element> elements;

    [[nodiscard]] bool isEmpty() const { return nodes.empty(); }
};
std::optional<Fragment> copyFragment(ChartDocument &document, const std::vector<quint64> &selection, QString *error);
// The fragment that copyFragment made, read back from its elements alone (as they come from the
// clipboard, connections to the rest of the chart dropped): the chain they form. nullopt (and a
// message) when they are not one chain of steps and transitions.
std::optional<Fragment> fragmentFromElements(std::vector<model::Element> elements, QString *error);
// Pastes after the selection (new localIds; step names made unique).
EditResult pasteFragment(ChartDocument &document, const std::vector<quint64> &selection, const Fragment &fragment);

// Every element of the nodes from the selection's first to its last node in their chain (the
// "shift-click selects the connected range" rule), or just the selection when it spans chains.
std::vector<quint64> connectedRange(ChartDocument &document, quint64 anchor, quint64 clicked);

// Step names of the chart, for the jump target list.
QStringList stepNames(const ChartDocument &document);
QString uniqueStepName(const ChartDocument &document, const QString &base = QStringLiteral("Step"));

} // namespace iec::editors::sfc
