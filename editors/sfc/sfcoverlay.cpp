#include "editors/sfc/sfcoverlay.h"

#include "editors/common/diagramscene.h"
#include "editors/sfc/sfcitems.h"
#include "editors/sfc/sfcscene.h"
#include "interpreter/runtime/snapshot.h"

#include <unordered_map>

namespace iec::editors::sfc {

using namespace model;

QString formatElapsed(std::int64_t ns)
{
    qint64 ms = ns / 1000000;
    const qint64 h = ms / 3600000;
    ms %= 3600000;
    const qint64 m = ms / 60000;
    ms %= 60000;
    const qint64 s = ms / 1000;
    ms %= 1000;
    QString text = QStringLiteral("T#");
    if (h)
        text += QString::number(h) + QStringLiteral("h");
    if (m)
        text += QString::number(m) + QStringLiteral("m");
    if (s || (!h && !m && !ms))
        text += QString::number(s) + QStringLiteral("s");
    if (ms)
        text += QString::number(ms) + QStringLiteral("ms");
    return text;
}

namespace {

// The chart state looked up the ways the items need it.
struct ChartLookup {
    std::unordered_map<quint64, const interp::sfc::StepState *> stepsById;
    QHash<QString, const interp::sfc::StepState *> stepsByName; // lower case
    std::unordered_map<quint64, bool> transitions;
    QSet<QString> activeActions; // lower case

    ChartLookup(const interp::sfc::ChartState *chart, bool topLevel)
    {
        if (!chart)
            return;
        for (const auto &step : chart->steps) {
            if (topLevel)
                stepsById[step.localId] = &step;
            stepsByName.insert(step.name.toLower(), &step);
        }
        for (const auto &action : chart->actions) {
            if (action.active)
                activeActions.insert(action.name.toLower());
        }
        if (topLevel) {
            for (const auto &transition : chart->transitions)
                transitions[transition.localId] = transition.condition;
        }
    }

    [[nodiscard]] const interp::sfc::StepState *step(quint64 localId, const QString &name) const
    {
        if (const auto it = stepsById.find(localId); it != stepsById.end())
            return it->second;
        return stepsByName.value(name.toLower());
    }
};

QString stepNameOf(const Element &e)
{
    if (const auto *step = std::get_if<Step>(&e))
        return step->name;
    if (const auto *macro = std::get_if<MacroStep>(&e))
        return macro->name.value_or(QString());
    return {};
}

} // namespace

void SfcOverlayMapper::apply(DiagramScene &scene, const interp::RuntimeSnapshot &snapshot, const QString &instance)
{
    const ChartLookup chart(snapshot.chart(instance, m_action), m_policy.macroPath().empty());
    const auto stepActive = [&](quint64 localId, const Element &e) {
        const interp::sfc::StepState *state = chart.step(localId, stepNameOf(e));
        return state && state->active ? state : nullptr;
    };
    for (DiagramItem *item : scene.diagramItems()) {
        auto *sfcItem = dynamic_cast<SfcItem *>(item);
        if (!sfcItem)
            continue; // an FBD box wired into a transition
        const Element &e = sfcItem->element();
        if (std::holds_alternative<Step>(e) || std::holds_alternative<MacroStep>(e)) {
            const interp::sfc::StepState *state = stepActive(item->localId(), e);
            item->setActive(state != nullptr);
            item->setOnlineText(state ? formatElapsed(state->elapsedNs) : QString());
        } else if (std::holds_alternative<Transition>(e)) {
            const auto it = chart.transitions.find(item->localId());
            item->setActive(it != chart.transitions.end() && it->second);
        } else if (auto *block = dynamic_cast<ActionBlockItem *>(item)) {
            // An association is coloured while its own step is active (and its action runs): an
            // action set by one step and reset by a later one must not colour the later step's row.
            const auto &in = std::get<ActionBlock>(e).connectionPointIn;
            const bool connected = in && !in->connections.empty();
            const quint64 stepId = connected ? in->connections.front().refLocalId : 0;
            const auto *step = connected ? dynamic_cast<SfcItem *>(scene.itemFor(stepId)) : nullptr;
            const bool ownStepActive = step && stepActive(stepId, step->element());
            block->setActiveActions(ownStepActive ? chart.activeActions : QSet<QString> {});
        }
    }
}

void SfcOverlayMapper::clear(DiagramScene &scene)
{
    for (DiagramItem *item : scene.diagramItems()) {
        item->setActive(false);
        item->setOnlineText(QString());
        if (auto *block = dynamic_cast<ActionBlockItem *>(item))
            block->setActiveActions({});
    }
}

} // namespace iec::editors::sfc
