#pragma once

#include "interpreter/runtime/runtime.h"
#include "interpreter/sfc/sfcstatus.h"

#include <QHash>
#include <QSet>
#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace iec::interp {

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

    [[nodiscard]] QString value(const QString &name) const { return values.value(name); }
    [[nodiscard]] bool isForced(const QString &name) const
    {
        return forced.contains(name.toUpper());
    }
    [[nodiscard]] const sfc::ChartState *chart(const QString &instance) const
    {
        for (const sfc::ChartState &state : charts)
            if (state.instance.compare(instance, Qt::CaseInsensitive) == 0)
                return &state;
        return nullptr;
    }
};

} // namespace iec::interp
