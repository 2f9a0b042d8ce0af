#pragma once
// The mixing-tank chart of seed 001 drawn with SFC editor commands only, shared by the editor
// test (tst_sfceditor, every command undone and redone) and the online test in the main window
// (tst_sfconline). Each test says how one command is run and checked.
#include "editors/sfc/sfcedits.h"
#include "editors/sfc/sfceditor.h"
#include "model/body.h"

#include <QTest>

#include <functional>

namespace iec::tests {

// The transition right below a step (its input wire comes from the step); 0 when none.
inline quint64 transitionAfter(const editors::sfc::SfcEditor &editor, quint64 stepId)
{
    for (const model::Element &e : editor.document().elements) {
        if (const auto *t = std::get_if<model::Transition>(&e); t && t->connectionPointIn) {
            for (const auto &c : t->connectionPointIn->connections)
                if (c.refLocalId == stepId)
                    return t->localId;
        }
    }
    return 0;
}

// Runs one editor command named `what` (for the failure message) and checks it.
using SfcCommandRunner = std::function<void(const char *what, const std::function<bool()> &command)>;

// Draws the mixing tank: Init -SB1-> Fill_A (Y1) -L2-> Fill_B (Y2) -L1-> Mix (M) -mixCondition->
// Drain (Y3) -> [NOT L3 AND NOT SB2 -> Fill_A | NOT L3 AND SB2 -> Init].
inline void buildMixingTank(editors::sfc::SfcEditor &e, const char *mixCondition, const SfcCommandRunner &run)
{
    run("new chart", [&] { return e.trigger(QStringLiteral("sfcNewChart")); });
    const quint64 init = e.stepId(QStringLiteral("Init"));
    QVERIFY(init);
    quint64 last = transitionAfter(e, init);
    run("start condition", [&] { return e.edit(QStringLiteral("Change condition"), [&](editors::sfc::ChartDocument &d, const auto &) { return editors::sfc::setInlineCondition(d, last, QStringLiteral("SB1")); }); });
    struct Stage {
        const char *name;
        const char *action;
        const char *condition;
    };
    const Stage stages[] = {
        {"Fill_A", "Y1", "L2"}, {"Fill_B", "Y2", "L1"}, {"Mix", "M", mixCondition}, {"Drain", "Y3", "NOT L3 AND NOT SB2"}};
    for (const Stage &stage : stages) {
        e.select({last});
        run("insert step-transition", [&] { return e.trigger(QStringLiteral("sfcStepAfter")); });
        const quint64 step = e.selection().front();
        editors::sfc::StepProperties properties = *editors::sfc::stepProperties(e.document(), step);
        properties.name = QLatin1String(stage.name);
        run("rename step", [&] { return e.edit(QStringLiteral("Change step"), [&](editors::sfc::ChartDocument &d, const auto &) { return editors::sfc::setStepProperties(d, step, properties); }); });
        run("add action", [&] {
            return e.edit(QStringLiteral("Add action"), [&](editors::sfc::ChartDocument &d, const auto &) { return editors::sfc::addAction(d, step, editors::sfc::actionAssociation(QStringLiteral("N"), QLatin1String(stage.action))); });
        });
        last = transitionAfter(e, step);
        run("condition", [&] { return e.edit(QStringLiteral("Change condition"), [&](editors::sfc::ChartDocument &d, const auto &) { return editors::sfc::setInlineCondition(d, last, QLatin1String(stage.condition)); }); });
    }
    // The chain ends in the jump of the new chart: back to Fill_A for the next batch ...
    quint64 jump = 0;
    for (const model::Element &element : e.document().elements)
        if (std::holds_alternative<model::JumpStep>(element))
            jump = model::header(element).localId;
    e.select({jump});
    run("retarget jump", [&] { return e.edit(QStringLiteral("Insert jump"), [&](editors::sfc::ChartDocument &d, const auto &s) { return editors::sfc::insertJump(d, s, QStringLiteral("Fill_A")); }); });
    // ... or, when SB2 asked to stop, to Init at the end of the batch.
    e.select({last, jump});
    run("alternative branch", [&] { return e.trigger(QStringLiteral("sfcAltRight")); });
    const quint64 stopTransition = e.selection().front();
    run("stop condition", [&] { return e.edit(QStringLiteral("Change condition"), [&](editors::sfc::ChartDocument &d, const auto &) { return editors::sfc::setInlineCondition(d, stopTransition, QStringLiteral("NOT L3 AND SB2")); }); });
    e.select({stopTransition});
    run("jump to Init", [&] { return e.edit(QStringLiteral("Insert jump"), [&](editors::sfc::ChartDocument &d, const auto &s) { return editors::sfc::insertJump(d, s, QStringLiteral("Init")); }); });
}

} // namespace iec::tests
