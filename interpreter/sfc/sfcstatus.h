#pragma once

#include "model/project.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <vector>

namespace iec::interp {
class Runtime;
}

// What the online mode shows of a running chart: which steps and actions are active and how long
// each active step has been active. Read from the runtime through the chart's implicit variables,
// so it needs nothing but the symbol table.
namespace iec::interp::sfc {

struct StepState {
    QString name;
    quint64 localId = 0;
    bool active = false;
    std::int64_t elapsedNs = 0; // <step>.T; 0 when inactive
};

struct ActionState {
    QString name;
    bool active = false; // <action>.x: the action's body ran (or its variable is TRUE) this cycle
};

struct TransitionState {
    quint64 localId = 0;
    bool condition = false; // the condition was TRUE when last evaluated
};

struct ChartState {
    QString instance; // "Main", "Main.Filler" (the instance path of the POU that holds the chart)
    QString pou;      // the POU type
    QString action;   // the action whose body the chart is; empty: the POU's own body
    std::vector<StepState> steps;
    std::vector<ActionState> actions;
    std::vector<TransitionState> transitions;
};

// What chartState reads for one SFC POU: its elements and the names of their variables inside
// an instance. Building it walks the whole chart, so a caller that reads the same chart every
// snapshot builds it once (per POU revision) and passes it on.
struct ChartLayout {
    struct Step {
        QString name;
        quint64 localId = 0;
        QString active; // the step's x, relative to the instance
        QString time;   // the step's t
    };
    QString pou;
    QString action;                     // as in ChartState
    QString hiddenPrefix = QStringLiteral("__sfc_"); // an action's chart: __sfc_ACTION_ (sfclowering)
    std::vector<Step> steps;
    QStringList actions;                // chartActions(): hidden variable a<j>_q
    std::vector<quint64> transitions;   // localIds: hidden variable t<k>_c
};

// nullopt when `pou` has no SFC body (with `action`: when that action's body is not a chart).
std::optional<ChartLayout> chartLayout(const model::Pou &pou, const QString &action = {});

// The state of the chart of SFC POU `pou` (or of its action `action`) in instance `instancePath`;
// nullopt when the runtime has no such instance or that body is not SFC.
std::optional<ChartState> chartState(const Runtime &runtime, const model::Pou &pou, const QString &instancePath,
    const QString &action = {});
std::optional<ChartState> chartState(const Runtime &runtime, const ChartLayout &layout, const QString &instancePath);

// Every SFC program instance the runtime runs (FB instances are reached by path with chartState).
std::vector<ChartState> programChartStates(const Runtime &runtime, const model::Project &project);

} // namespace iec::interp::sfc
