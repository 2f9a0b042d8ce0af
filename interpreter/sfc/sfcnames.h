#pragma once

#include "interpreter/sfc/sfcgraph.h"

#include <QString>
#include <QStringList>

// The names of a chart's implicit and hidden variables, shared by the lowering (which declares
// them) and the chart state (which reads them through the symbol table).
namespace iec::interp::sfc {

// IEC step S: S.x, S._x, S.t (a structure). Simplified step S (CoDeSys): S, _S, _timeS.
inline QString stepActive(const ChartStep &step)
{
    return step.options.simplified ? step.name : QString(step.name + QStringLiteral(".x"));
}
inline QString stepNext(const ChartStep &step)
{
    return step.options.simplified ? QString(QLatin1Char('_') + step.name) : QString(step.name + QStringLiteral("._x"));
}
inline QString stepTime(const ChartStep &step)
{
    return step.options.simplified ? QString(QStringLiteral("_time") + step.name) : QString(step.name + QStringLiteral(".t"));
}

// Where a chart's hidden variables start: "__sfc_" for the POU's own chart, "__sfc_A_" for the
// chart that is action A's body, however deep the lowering reached it (each is lowered once).
inline QString hiddenPrefix(const QString &action = {})
{
    return action.isEmpty() ? QStringLiteral("__sfc_") : QStringLiteral("__sfc_") + action + QLatin1Char('_');
}

// Hidden per-element variables are numbered by their index in the Chart (steps, transitions) or in
// chartActions() (actions), so the chart state finds them again by building the same Chart.
inline QString hidden(const char *kind, int index, const char *what)
{
    return QStringLiteral("__sfc_%1%2_%3").arg(QLatin1String(kind)).arg(index).arg(QLatin1String(what));
}

// The actions the chart controls (POU actions, Boolean variables, inline bodies), each once, in
// the order CoDeSys runs them: alphabetical (case-insensitive), ties in order of appearance.
QStringList chartActions(const Chart &chart);

} // namespace iec::interp::sfc
