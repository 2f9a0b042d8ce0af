#pragma once

#include "interpreter/runtime/runtime.h"
#include "interpreter/runtime/tracerecorder.h"
#include "interpreter/sfc/sfcstatus.h"

#include <QHash>
#include <QSet>
#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace iec::interp {

// The scans the runtime keeps to go back to (ScanHistory), as the history bar shows them.
struct HistoryInfo {
    int firstCycle = 0;
    int lastCycle = 0;
    int scanLimit = 0;
    std::size_t bytes = 0;
};

// What the trace recorder added since the last snapshot: its new samples, or all of them when
// `reset` (the recording started again, was cut back, or more came than were sent).
struct TraceUpdate {
    std::shared_ptr<const Module> module; // keeps the variables' types alive for the pane
    std::vector<TraceVariable> variables;
    bool reset = false;
    std::vector<TraceRow> rows;
    TraceRecorder::Status status = TraceRecorder::Status::NoVariables;
    std::optional<int> triggerCycle;
    QString conditionProblem;
    int capacity = TraceSettings::kDefaultCapacity;
};

// What the online mode shows, copied from the runtime after a cycle: immutable once published,
// so the UI thread reads it while the runtime thread runs on. Values are IEC literals as
// Runtime::read gives them ("TRUE", "42", "T#1s500ms").
struct RuntimeSnapshot {
    quint64 modelRevision = 0; // the model revision the running program was compiled from
    int cycle = 0;
    std::int64_t timeNs = 0;
    std::int64_t cycleNs = 0;  // the cycle time the runtime runs with
    bool running = false;      // cycles run on their own (Run), not single-stepped
    std::optional<RuntimeFault> fault;
    std::optional<HaltInfo> halt;   // halted mid-cycle by a breakpoint or a step
    QHash<QString, QString> values; // name as requested ("Main.Count") -> value
    QSet<QString> forced;           // names held by a force, in upper case (IEC names ignore case)
    std::vector<sfc::ChartState> charts; // every chart an open editor asked for
    // Set when values and charts are those after an earlier scan (going back in time), not
    // the program's present; cycle and timeNs are then that scan's too.
    std::optional<int> historyCycle;
    int presentCycle = 0; // the cycle the program is at, also while showing the past
    HistoryInfo history;
    std::shared_ptr<const TraceUpdate> trace; // nullptr: nothing new

    [[nodiscard]] QString value(const QString &name) const { return values.value(name); }
    [[nodiscard]] bool isForced(const QString &name) const
    {
        return forced.contains(name.toUpper());
    }
    // The chart of `instance`'s POU, or with `action` the chart of that action.
    [[nodiscard]] const sfc::ChartState *chart(const QString &instance, const QString &action = {}) const
    {
        for (const sfc::ChartState &state : charts)
            if (state.instance.compare(instance, Qt::CaseInsensitive) == 0 && state.action.compare(action, Qt::CaseInsensitive) == 0)
                return &state;
        return nullptr;
    }
};

} // namespace iec::interp
