#pragma once

#include "editors/fbd/fbddocument.h"

#include <QHash>
#include <QString>

#include <functional>
#include <map>

// The values on an FBD network's wires for the online view, as CODESYS shows them: a variable's
// value from the running program, a function block's outputs from its instance, and what the
// common operators and functions give from their inputs (logic, comparison, arithmetic, MOVE,
// SEL, MAX, MIN, LIMIT). Pure: the variables' values come from the caller.
namespace iec::editors::fbd {

// Every output's value (IEC literal) in the network by (element, output pin); absent when it is
// not known (a function the view does not compute, an input without a value).
std::map<std::pair<quint64, int>, QString> networkValues(const FbdDocument &document, const FbdNetwork &network,
    const std::function<QString(quint64 element, const QString &path)> &valueOf,
    const std::function<QString(quint64 box, const QString &pin)> &instancePin);

// The result of a function or operator from its input values ("TRUE", "12", "1.5"); empty when
// the view cannot tell.
QString evaluateFunction(const QString &typeName, const QStringList &inputs);

} // namespace iec::editors::fbd
