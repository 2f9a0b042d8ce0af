#pragma once

#include "interpreter/runtime/tracedata.h"

#include <QString>
#include <QStringList>

#include <deque>
#include <optional>
#include <vector>

namespace iec::interp {

class Runtime;

// What the Trace pane records and when (kept with the project, model/savedtrace.h).
struct TraceSettings {
    enum class Trigger { None, Rising, Falling, Level };
    static constexpr int kDefaultCapacity = 10'000;

    QStringList variables;
    int everyCycles = 1;                 // a sample after every Nth cycle
    int capacity = kDefaultCapacity;     // samples kept; the oldest go
    Trigger trigger = Trigger::None;
    QString triggerVariable;
    double triggerLevel = 0.5;           // BOOL: 0.5, so TRUE is above it
    int samplesAfterTrigger = 100;       // then the recording stops
    QString recordCondition;             // a Boolean expression; empty: always

    bool operator==(const TraceSettings &) const = default;
};

// Samples chosen variables after cycles into a ring buffer (a logic analyser):
//  - without a trigger it records all the time, keeping the last `capacity` samples;
//  - with one it keeps recording until the trigger variable crosses the level (Rising: from
//    below to at or above; Falling: the other way; Level: the first sample at or above it),
//    then records `samplesAfterTrigger` more samples and stops, so the buffer holds what led
//    to the trigger and what followed.
// A record condition that is FALSE skips the cycle. Pausing keeps the samples and skips cycles.
class TraceRecorder
{
public:
    enum class Status { Recording, WaitingForTrigger, Triggered, Done, Paused, NoVariables };

    // Resolves the names against the running program; the problems, one sentence each (an
    // unknown or untraceable name is left out, the rest is recorded). Clears the samples.
    QStringList configure(const TraceSettings &settings, const Runtime &runtime);
    [[nodiscard]] const TraceSettings &settings() const { return m_settings; }
    [[nodiscard]] const std::vector<TraceVariable> &variables() const { return m_variables; }

    // Called after every cycle (and once before the first, for the initial values).
    void sample(const Runtime &runtime);
    void setPaused(bool paused);
    // Drops the samples and starts again (the trigger is armed again).
    void restart();
    // Drops the samples after `cycle` (going back in time makes a new branch).
    void truncateAfter(int cycle);

    [[nodiscard]] Status status() const;
    [[nodiscard]] const std::deque<TraceRow> &rows() const { return m_rows; }
    [[nodiscard]] std::optional<int> triggerCycle() const { return m_triggerCycle; }
    // The condition's problem when it could not be evaluated (nothing is recorded then).
    [[nodiscard]] const QString &conditionProblem() const { return m_conditionProblem; }
    // Counts every change that is not an append (restart, truncation, reconfiguration), so a
    // reader of rows() knows when to read them all again rather than the new ones only.
    [[nodiscard]] quint64 generation() const { return m_generation; }
    [[nodiscard]] quint64 appended() const { return m_appended; } // rows appended in this generation

private:
    bool conditionHolds(const Runtime &runtime);
    void append(TraceRow row);

    TraceSettings m_settings;
    std::vector<TraceVariable> m_variables;
    std::optional<VariableRef> m_triggerRef;
    std::deque<TraceRow> m_rows;
    std::optional<double> m_lastTriggerValue;
    std::optional<int> m_triggerCycle;
    int m_afterTrigger = 0;
    bool m_paused = false;
    QString m_conditionProblem;
    quint64 m_generation = 0;
    quint64 m_appended = 0;
};

} // namespace iec::interp
