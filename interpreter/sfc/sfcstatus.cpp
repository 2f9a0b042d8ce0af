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

} // namespace

std::optional<ChartState> chartState(const Runtime &runtime, const model::Pou &pou, const QString &instancePath)
{
    const model::Body *body = pou.body();
    if (!body || body->language() != model::BodyLanguage::SFC)
        return std::nullopt;
    Diagnostics ignored; // the compiler reported them
    const Chart chart = buildChart(*body, pou.name, ignored);
    const QString prefix = instancePath + QLatin1Char('.');
    if (!runtime.find(prefix + QStringLiteral("__sfc_now")))
        return std::nullopt; // no such instance, or the chart did not compile
    ChartState state;
    state.instance = instancePath;
    state.pou = pou.name;
    for (const ChartStep &step : chart.steps) {
        StepState s;
        s.name = step.name;
        s.localId = step.localId;
        s.active = readBool(runtime, prefix + stepActive(step));
        s.elapsedNs = s.active ? readTime(runtime, prefix + stepTime(step)) : 0;
        state.steps.push_back(s);
    }
    const QStringList actions = chartActions(chart);
    for (int j = 0; j < actions.size(); ++j)
        state.actions.push_back({actions[j], readBool(runtime, prefix + hidden("a", j, "q"))});
    for (int k = 0; k < int(chart.transitions.size()); ++k)
        state.transitions.push_back({chart.transitions[size_t(k)].localId, readBool(runtime, prefix + hidden("t", k, "c"))});
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
        for (const QString &instance : std::as_const(instances)) {
            if (auto state = chartState(runtime, pou, instance))
                states.push_back(std::move(*state));
        }
    }
    return states;
}

} // namespace iec::interp::sfc
