// The SFC editor's commands as one table (DiagramEditor::ActionSpec): what the tool bar, the
// context menu, the window's Insert and Edit menus and the keys trigger. Each row runs a pure
// edit of sfcedits.h through SfcEditor::edit, or opens the dialog that asks for its argument.
#include "editors/sfc/sfceditor.h"

#include "editors/common/diagramclipboard.h"
#include "editors/common/diagramscene.h"
#include "model/projectmodel.h"

namespace iec::editors::sfc {

using namespace model;

namespace {

bool isStepLike(const Element &e)
{
    return std::holds_alternative<Step>(e) || std::holds_alternative<MacroStep>(e);
}

bool isTransition(const Element &e)
{
    return std::holds_alternative<Transition>(e);
}

} // namespace

void SfcEditor::createActions()
{
    using G = ActionGroup;
    const auto any = [this] { return !selection().isEmpty(); };
    const auto step = [this] { return selectedOfKind(true) != 0; };
    const auto transition = [this] { return selectedOfKind(false) != 0; };
    const auto hasTransition = [this] { return selectionHas(&isTransition); };
    const auto hasStep = [this] { return selectionHas(&isStepLike); };
    // The tool bar carries the everyday commands with short labels, so that it fits beside the
    // window's docks at 1600 px (issue 13); every command is in the menus with its full name.
    const ActionSpec specs[] = {
        {"sfcNewChart", QT_TR_NOOP("Initial Step"), "", G::Insert, true, false,
            [this] { edit(tr("New chart"), [](ChartDocument &d, const auto &) { return createDefaultChart(d); }); },
            [this] { return document().chart.isEmpty(); }},
        {"sfcStepAfter", QT_TR_NOOP("Step-Transition (after)"), "Ctrl+T", G::Insert, true, true,
            [this] { edit(tr("Insert step-transition"), [](ChartDocument &d, const auto &s) { return insertStepTransition(d, s, true); }); },
            [this] { return !selection().isEmpty() || document().chart.isEmpty(); }, QT_TR_NOOP("Step")},
        {"sfcStepBefore", QT_TR_NOOP("Step-Transition (before)"), "Ctrl+Shift+T", G::Insert, true, false,
            [this] { edit(tr("Insert step-transition"), [](ChartDocument &d, const auto &s) { return insertStepTransition(d, s, false); }); },
            any},
        {"sfcAltRight", QT_TR_NOOP("Alternative Branch (right)"), "Ctrl+A", G::Insert, true, true,
            [this] { edit(tr("Insert alternative branch"), [](ChartDocument &d, const auto &s) { return insertAlternativeBranch(d, s, true); }); },
            hasTransition, QT_TR_NOOP("Alternative")},
        {"sfcAltLeft", QT_TR_NOOP("Alternative Branch (left)"), "", G::Insert, true, false,
            [this] { edit(tr("Insert alternative branch"), [](ChartDocument &d, const auto &s) { return insertAlternativeBranch(d, s, false); }); },
            hasTransition},
        {"sfcParRight", QT_TR_NOOP("Parallel Branch (right)"), "Ctrl+L", G::Insert, true, true,
            [this] { edit(tr("Insert parallel branch"), [](ChartDocument &d, const auto &s) { return insertParallelBranch(d, s, true); }); },
            hasStep, QT_TR_NOOP("Parallel")},
        {"sfcParLeft", QT_TR_NOOP("Parallel Branch (left)"), "", G::Insert, true, false,
            [this] { edit(tr("Insert parallel branch"), [](ChartDocument &d, const auto &s) { return insertParallelBranch(d, s, false); }); },
            hasStep},
        {"sfcJump", QT_TR_NOOP("Jump…"), "", G::Insert, true, true, [this] { chooseJumpTarget(false); }, any},
        {"sfcTransitionJump", QT_TR_NOOP("Transition-Jump…"), "", G::Insert, true, false, [this] { chooseJumpTarget(true); }, any},
        {"sfcMacro", QT_TR_NOOP("Macro Step"), "", G::Insert, true, true,
            [this] { edit(tr("Insert macro step"), [](ChartDocument &d, const auto &s) { return insertMacroStep(d, s, true); }); },
            any, QT_TR_NOOP("Macro")},
        {"sfcProperties", QT_TR_NOOP("Step Properties…"), "", G::Element, true, true,
            [this] {
                if (const quint64 id = selectedOfKind(true))
                    editStepDialog(id);
                else
                    showError(tr("Select a step first."));
            },
            step, QT_TR_NOOP("Properties…")},
        {"sfcActions", QT_TR_NOOP("IEC Actions…"), "", G::Element, true, true,
            [this] {
                if (const quint64 id = selectedOfKind(true))
                    editActionsDialog(id);
                else
                    showError(tr("Select a step first."));
            },
            step, QT_TR_NOOP("Actions…")},
        {"sfcCondition", QT_TR_NOOP("Edit Condition"), "", G::Element, true, false,
            [this] {
                if (const quint64 id = selectedOfKind(false))
                    editConditionInPlace(id);
                else
                    showError(tr("Select a transition first."));
            },
            transition},
        {"sfcPriority", QT_TR_NOOP("Transition Priority…"), "", G::Element, true, false,
            [this] {
                if (const quint64 id = selectedOfKind(false))
                    editPriorityDialog(id);
                else
                    showError(tr("Select a transition first."));
            },
            transition},
        {"sfcZoomOutOfMacro", QT_TR_NOOP("Leave Macro"), "", G::Element, false, true, [this] { leaveMacro(); },
            [this] { return !macroPath().empty(); }, QT_TR_NOOP("Leave")},
        {"sfcArrange", QT_TR_NOOP("Arrange Chart"), "", G::Element, true, true, [this] { arrangeChart(); },
            [this] { return !document().chart.isEmpty(); }, QT_TR_NOOP("Arrange")},
        {"sfcCut", QT_TR_NOOP("Cut"), "Ctrl+X", G::Edit, true, false, [this] { cutSelection(); }, any},
        {"sfcCopy", QT_TR_NOOP("Copy"), "Ctrl+C", G::Edit, false, false, [this] { copySelection(); }, any},
        {"sfcPaste", QT_TR_NOOP("Paste"), "Ctrl+V", G::Edit, true, false, [this] { paste(); },
            [] { return clipboardHasElements(); }},
        {"sfcDelete", QT_TR_NOOP("Delete"), "Del", G::Edit, true, true,
            [this] { edit(tr("Delete"), [](ChartDocument &d, const auto &s) { return deleteSelection(d, s); }); }, any},
    };
    addActionTable(specs);
}

quint64 SfcEditor::selectedOfKind(bool steps) const
{
    const ChartDocument doc = document();
    for (quint64 id : selection()) {
        const Element *e = doc.element(id);
        if (!e)
            continue;
        if (steps && isStepLike(*e))
            return id;
        // An action block stands for its step.
        if (steps && std::holds_alternative<ActionBlock>(*e)) {
            const auto &block = std::get<ActionBlock>(*e);
            if (block.connectionPointIn && !block.connectionPointIn->connections.empty())
                return block.connectionPointIn->connections.front().refLocalId;
        }
        if (!steps && isTransition(*e))
            return id;
    }
    return 0;
}

bool SfcEditor::selectionHas(bool (*kind)(const Element &)) const
{
    const QList<quint64> ids = selection();
    if (ids.isEmpty())
        return false;
    const ChartDocument doc = document();
    return std::ranges::any_of(ids, [&](quint64 id) { return doc.element(id) && kind(*doc.element(id)); });
}

void SfcEditor::copySelection()
{
    ChartDocument doc = document();
    QString error;
    const std::optional<Fragment> fragment = copyFragment(doc, selectedIds(), &error);
    if (!fragment) {
        showError(error);
        return;
    }
    copyElementsToClipboard(EditorLanguage::SFC, fragment->elements);
    updateActionStates();
}

void SfcEditor::cutSelection()
{
    if (trigger(QStringLiteral("sfcCopy")))
        edit(tr("Cut"), [](ChartDocument &d, const auto &s) { return deleteSelection(d, s); });
}

void SfcEditor::paste()
{
    PastedElements pasted = elementsFromClipboard(EditorLanguage::SFC, projectModel().nextLocalId(bodyRef()));
    if (!pasted.ok()) {
        showError(pasted.error);
        return;
    }
    QString error;
    const std::optional<Fragment> fragment = fragmentFromElements(std::move(pasted.elements), &error);
    if (!fragment) {
        showError(error);
        return;
    }
    // Where it goes is the chart's business: after the selection, if the alternation allows.
    edit(tr("Paste"), [&](ChartDocument &d, const auto &s) { return pasteFragment(d, s, *fragment); });
}

} // namespace iec::editors::sfc
