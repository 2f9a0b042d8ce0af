#pragma once

#include "interpreter/compiler/diagnostics.h"

#include "model/pou.h"
#include "model/sfcoptions.h"

#include <QString>

#include <optional>
#include <vector>

// The chart of an SFC POU as the engine sees it: steps, transitions (each with the steps it
// leaves and the steps it activates) and action associations. Divergences, convergences, jumps
// and macro steps are resolved here, so the lowering only sees "transition T goes from steps
// {A, B} to steps {C}". Structural errors are reported here, located on the element.
namespace iec::interp::sfc {

struct ChartStep {
    QString name;
    quint64 localId = 0;
    bool initial = false;
    model::StepOptions options;
    int macro = -1; // index of the macro step (in `macros`) whose body holds this step; -1: top level
};

// A macro step with a body: it is active while one of its inner steps is.
struct ChartMacro {
    QString name;
    quint64 localId = 0;
    std::vector<int> inner; // step indices
};

struct ChartTransition {
    quint64 localId = 0;
    std::vector<int> sources; // steps that must all be active
    std::vector<int> targets; // steps activated when it fires
    const model::Condition *condition = nullptr;
    const model::Body *scope = nullptr; // the body that holds the transition (for wired conditions)
    std::optional<quint64> priority;
    double x = 0;
    int order = 0; // in the file
};

// One action block entry: step `step` controls action `action` with `qualifier`.
struct ChartAssociation {
    int step = 0;
    quint64 localId = 0;
    QString qualifier; // upper case; N when the file has none
    QString duration;  // TIME literal or variable; empty when none
    QString indicator;
    QString action;    // POU action or Boolean variable; "__sfc_inline<localId>" for an inline body
    const model::Body *inlineBody = nullptr;
};

struct Chart {
    std::vector<ChartStep> steps;
    std::vector<ChartMacro> macros;
    std::vector<ChartTransition> transitions; // in firing order (priority, left to right, file)
    std::vector<ChartAssociation> associations;
    int initialStep = -1;
};

// Resolves the chart of `body` (an SFC body of POU `pouName`). Every structural problem is an
// error in `diagnostics`; the chart returned holds what could be understood.
Chart buildChart(const model::Body &body, const QString &pouName, Diagnostics &diagnostics);

// Whether `qualifier` needs a duration (L, D, SD, DS, SL).
bool isTimedQualifier(const QString &qualifier);
bool isKnownQualifier(const QString &qualifier);

} // namespace iec::interp::sfc
