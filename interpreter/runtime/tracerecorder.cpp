#include "interpreter/runtime/tracerecorder.h"

#include "interpreter/runtime/conditionexpression.h"
#include "interpreter/runtime/runtime.h"

#include <QCoreApplication>

#include <algorithm>

namespace iec::interp {

QStringList TraceRecorder::configure(const TraceSettings &settings, const Runtime &runtime)
{
    QStringList problems;
    m_settings = settings;
    m_settings.everyCycles = std::max(1, settings.everyCycles);
    m_settings.capacity = std::max(2, settings.capacity);
    m_settings.samplesAfterTrigger = std::max(0, settings.samplesAfterTrigger);
    m_variables.clear();
    for (const QString &name : settings.variables) {
        const std::optional<VariableRef> ref = runtime.find(name);
        if (!ref) {
            problems << QCoreApplication::translate("iec::interp::TraceRecorder", "There is no variable called %1.")
                            .arg(name);
            continue;
        }
        const TraceVariable variable{name, *ref};
        if (!isTraceable(*ref)) {
            problems << notTraceableReason(variable);
            continue;
        }
        m_variables.push_back(variable);
    }
    m_triggerRef.reset();
    if (m_settings.trigger != TraceSettings::Trigger::None) {
        m_triggerRef = runtime.find(settings.triggerVariable);
        if (!m_triggerRef || !isTraceable(*m_triggerRef)) {
            problems << QCoreApplication::translate("iec::interp::TraceRecorder",
                                                    "The trigger variable %1 is not a BOOL or number of the program; "
                                                    "the trace records without a trigger.")
                            .arg(settings.triggerVariable);
            m_triggerRef.reset();
        }
    }
    if (!settings.recordCondition.trimmed().isEmpty()) {
        const QString syntax = conditionSyntaxError(settings.recordCondition);
        if (!syntax.isEmpty())
            problems << QCoreApplication::translate("iec::interp::TraceRecorder",
                                                    "The record condition is not an expression: %1")
                            .arg(syntax);
    }
    restart();
    return problems;
}

void TraceRecorder::restart()
{
    m_rows.clear();
    m_lastTriggerValue.reset();
    m_triggerCycle.reset();
    m_afterTrigger = 0;
    m_conditionProblem.clear();
    ++m_generation;
    m_appended = 0;
}

void TraceRecorder::setPaused(bool paused)
{
    m_paused = paused;
}

void TraceRecorder::truncateAfter(int cycle)
{
    while (!m_rows.empty() && m_rows.back().cycle > cycle)
        m_rows.pop_back();
    if (m_triggerCycle && *m_triggerCycle > cycle) {
        m_triggerCycle.reset();
        m_afterTrigger = 0;
    } else if (m_triggerCycle) {
        // The samples after the trigger that are left; the rest are recorded again.
        m_afterTrigger = int(std::count_if(m_rows.begin(), m_rows.end(),
                                           [this](const TraceRow &row) { return row.cycle > *m_triggerCycle; }));
    }
    m_lastTriggerValue.reset(); // an edge across the cut is not seen
    ++m_generation;
    m_appended = 0;
}

TraceRecorder::Status TraceRecorder::status() const
{
    if (m_variables.empty())
        return Status::NoVariables;
    if (m_triggerCycle)
        return m_afterTrigger >= m_settings.samplesAfterTrigger ? Status::Done : Status::Triggered;
    if (m_paused)
        return Status::Paused;
    return m_triggerRef ? Status::WaitingForTrigger : Status::Recording;
}

bool TraceRecorder::conditionHolds(const Runtime &runtime)
{
    if (m_settings.recordCondition.trimmed().isEmpty())
        return true;
    ConditionScope scope{runtime.module(), runtime.vm().memory().data(),
                         {runtime.image('I').data(), runtime.image('Q').data(), runtime.image('M').data()},
                         QString()};
    const ConditionResult result = evaluateCondition(m_settings.recordCondition, scope);
    m_conditionProblem = result.error;
    return result.value.value_or(false);
}

void TraceRecorder::append(TraceRow row)
{
    m_rows.push_back(std::move(row));
    while (int(m_rows.size()) > m_settings.capacity)
        m_rows.pop_front();
    ++m_appended;
}

void TraceRecorder::sample(const Runtime &runtime)
{
    if (m_variables.empty() || m_paused || status() == Status::Done)
        return;
    if (runtime.cycle() % m_settings.everyCycles != 0)
        return;
    if (!conditionHolds(runtime))
        return;
    append(captureRow(runtime, m_variables));
    if (m_triggerCycle) {
        ++m_afterTrigger;
        return;
    }
    if (!m_triggerRef)
        return;
    const TraceRow triggerRow = captureRow(runtime, {TraceVariable{QString(), *m_triggerRef}});
    const double now = rowNumber(triggerRow, 0, *m_triggerRef);
    const double level = m_settings.triggerLevel;
    const std::optional<double> before = m_lastTriggerValue;
    m_lastTriggerValue = now;
    bool fires = false;
    switch (m_settings.trigger) {
    case TraceSettings::Trigger::Rising:
        fires = before && *before < level && now >= level;
        break;
    case TraceSettings::Trigger::Falling:
        fires = before && *before >= level && now < level;
        break;
    case TraceSettings::Trigger::Level:
        fires = now >= level;
        break;
    case TraceSettings::Trigger::None:
        break;
    }
    if (fires)
        m_triggerCycle = runtime.cycle();
}

} // namespace iec::interp
