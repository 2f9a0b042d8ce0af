#pragma once

#include "interpreter/compiler/ast.h"
#include "interpreter/compiler/diagnostics.h"

#include "model/pou.h"

#include <QStringList>

#include <optional>

// The textual SFC form (IEC 61131-3: INITIAL_STEP, STEP, TRANSITION FROM .. TO .., ACTION) as
// the model's graphical SFC body, so `iecstudio-cli run chart.st` and the SFC editor see the same
// chart as a PLCopen file would give: a step with several transitions after it gets a selection
// divergence, a transition from several steps a simultaneous convergence, and so on. The layout
// is generated (model/layout.h). The chart's ACTIONs stay POU actions (the caller adds them).
namespace iec::interp::sfc {

model::Body chartToModel(const ast::SfcChart &chart, const QString &pou, Diagnostics &diagnostics);

// The chart of an SFC POU as textual SFC (steps with their action associations, then the
// transitions), or nullopt with `problem` set when the chart uses what the text form cannot say
// (macro steps, inline action bodies, conditions drawn as networks, structure errors). Step
// options (entry/exit/active actions, times) have no text form and are dropped (`dropped`).
std::optional<QString> printChart(const model::Pou &pou, QString *problem, QStringList *dropped = nullptr);
// The same for a chart that is `pou`'s body or one of its actions' (`where`: Pou.Action).
std::optional<QString> printChart(const model::Pou &pou, const model::Body &chart, const QString &where, QString *problem,
    QStringList *dropped = nullptr);

// IEC text of an expression (ast::sourceText).
QString expressionText(const ast::Expr &expr);

} // namespace iec::interp::sfc
