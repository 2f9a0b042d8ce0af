#include "interpreter/sfc/sfcstatus.h"

#include "interpreter/frontend/duration.h"
#include "interpreter/runtime/runtime.h"
#include "interpreter/sfc/sfcgraph.h"
#include "interpreter/sfc/sfcnames.h"

namespace iec::interp::sfc {

namespace {

bool readBool(const Runtime &runtime, const QString &name)
{
    return runtime.read(name).value_or(QString()) == QLatin1String("TRUE");
}

std::int64_t readTime(const Runtime &runtime, const QString &name)
{
    const auto text = runtime.read(name);
    if (!text)
        return 0;
    return frontend::parseDuration(*text).value_or(0);
}

// The POU's body, or with `action` that action's.
const model::Body *chartBody(const model::Pou &pou, const QString &action)
{
    if (action.isEmpty())
        return pou.body();
    for (const model::PouAction &a : pou.actions) {
        if (a.name.compare(action, Qt::CaseInsensitive) == 0)
            return &a.body;
    }
    return nullptr;
}

// A hidden variable's name in the chart's own namespace (hidden() names it for a POU's chart).
QString hiddenName(const ChartLayout &layout, const QString &name)
{
    return layout.hiddenPrefix + name.mid(hiddenPrefix().size());
}

} // namespace

std::optional<ChartLayout> chartLayout(const model::Pou &pou, const QString &action)
{
    const model::Body *body = chartBody(pou, action);
    if (!body || body->language() != model::BodyLanguage::SFC)
        return std::nullopt;
    Diagnostics ignored; // the compiler reported them
    const Chart chart = buildChart(*body, pou.name, ignored);
    ChartLayout layout;
    layout.pou = pou.name;
    layout.action = action;
    layout.hiddenPrefix = hiddenPrefix(action);
    for (const ChartStep &step : chart.steps)
        layout.steps.push_back({step.name, step.localId, stepActive(step), stepTime(step)});
    layout.actions = chartActions(chart);
    for (const ChartTransition &transition : chart.transitions)
        layout.transitions.push_back(transition.localId);
    return layout;
}

std::optional<ChartState> chartState(const Runtime &runtime, const model::Pou &pou, const QString &instancePath,
    const QString &action)
{
    const model::Body *body = chartBody(pou, action);
    if (!body || body->language() != model::BodyLanguage::SFC
        || !runtime.find(instancePath + QLatin1Char('.') + hiddenPrefix(action) + QStringLiteral("now")))
        return std::nullopt; // cheap checks first: no chart to build
    return chartState(runtime, *chartLayout(pou, action), instancePath);
}

std::optional<ChartState> chartState(const Runtime &runtime, const ChartLayout &layout, const QString &instancePath)
{
    const QString prefix = instancePath + QLatin1Char('.');
    if (!runtime.find(prefix + layout.hiddenPrefix + QStringLiteral("now")))
        return std::nullopt; // no such instance, or the chart did not compile
    ChartState state;
    state.instance = instancePath;
    state.pou = layout.pou;
    state.action = layout.action;
    for (const ChartLayout::Step &step : layout.steps) {
        StepState s;
        s.name = step.name;
        s.localId = step.localId;
        s.active = readBool(runtime, prefix + step.active);
        s.elapsedNs = s.active ? readTime(runtime, prefix + step.time) : 0;
        state.steps.push_back(s);
    }
    for (int j = 0; j < layout.actions.size(); ++j)
        state.actions.push_back({layout.actions[j], readBool(runtime, prefix + hiddenName(layout, hidden("a", j, "q")))});
    for (int k = 0; k < int(layout.transitions.size()); ++k)
        state.transitions.push_back({layout.transitions[size_t(k)], readBool(runtime, prefix + hiddenName(layout, hidden("t", k, "c")))});
    return state;
}

std::vector<ChartState> programChartStates(const Runtime &runtime, const model::Project &project)
{
    std::vector<ChartState> states;
    for (const model::Pou &pou : project.types.pous) {
        if (pou.kind != model::PouKind::Program || pou.language() != model::BodyLanguage::SFC)
            continue;
        QStringList instances;
        for (const model::Configuration &configuration : project.instances.configurations) {
            for (const model::Resource &resource : configuration.resources) {
                for (const model::Task &task : resource.tasks) {
                    for (const model::PouInstance &instance : task.pouInstances) {
                        if (instance.typeName.compare(pou.name, Qt::CaseInsensitive) == 0)
                            instances << instance.name;
                    }
                }
                for (const model::PouInstance &instance : resource.pouInstances) {
                    if (instance.typeName.compare(pou.name, Qt::CaseInsensitive) == 0)
                        instances << instance.name;
                }
            }
        }
        if (instances.isEmpty())
            instances << pou.name; // run alone (no configuration): the POU name finds its one instance
        const std::optional<ChartLayout> layout = chartLayout(pou); // once for all its instances
        if (!layout)
            continue;
        for (const QString &instance : std::as_const(instances)) {
            if (auto state = chartState(runtime, *layout, instance))
                states.push_back(std::move(*state));
        }
    }
    return states;
}

} // namespace iec::interp::sfc
