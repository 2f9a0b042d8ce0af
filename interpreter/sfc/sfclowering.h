#pragma once

#include "interpreter/compiler/ast.h"
#include "interpreter/compiler/diagnostics.h"

#include "model/pou.h"

// Lowering of an SFC chart (model::SfcBody of a POU, with its actions and transitions) to the
// compiler's statements: steps, transitions, action control and the implicit variables become
// variables and statements of the POU, so a chart runs on the same VM as ST and its state is
// readable by name (Main.Step1.X, Main.Step1.T). docs/sfc.md describes the cycle order.
namespace iec::interp::sfc {

// Appends the chart's statements to `result.body.statements` and its hidden variables to
// `result.sections`. Structural errors are reported on the element (POU, localId).
// `parsedActions`: action bodies already parsed (a textual SFC chart compiled straight from
// text); they take the place of the POU actions of the same name.
void lowerChart(const model::Pou &pou, ast::Pou &result, Diagnostics &diagnostics,
    const std::vector<ast::SfcAction> *parsedActions = nullptr);

// An action of `pou` whose body is itself a chart (in a POU of any language): its statements go
// to `out`, its hidden variables (named apart from the POU's own chart) to `result.sections`, and
// the IL actions it calls to `result.actions`. False after an error.
bool lowerActionChart(const model::Pou &pou, const model::PouAction &action, ast::Pou &result, std::vector<ast::Stmt> &out,
    Diagnostics &diagnostics, const std::vector<ast::SfcAction> *parsedActions = nullptr);

// Lowers every textual SFC chart of `unit` (parsed straight from .st text) in place.
void lowerTextualCharts(ast::CompilationUnit &unit, Diagnostics &diagnostics);

} // namespace iec::interp::sfc
