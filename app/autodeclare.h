#pragma once

#include "editors/declarations/declarationrows.h"
#include "model/ids.h"

#include <QString>
#include <QStringList>

class QUndoCommand;

namespace iec::model {
class ProjectModel;
struct Project;
} // namespace iec::model

namespace iec::app {

// Auto-declare (CODESYS: Edit → Auto Declare, Shift+F2): a name used in a body but declared
// nowhere gets a declaration row with a type guessed from how the body uses it.
//
// The guess, from the body's tokens: calls and member accesses (T1(IN := x, PT := T#1s), T1.Q)
// name a function block whose parameters they use (a standard FB or one of the project's);
// otherwise the neighbourhood of the name: a time literal beside it (x > T#5s, x := T#2s) gives
// TIME, a real literal REAL, a string STRING, arithmetic or an integer literal INT, a known
// variable across an assignment or comparison that variable's type; conditions, logic and IL
// coils (S, R, ST after a logic operator) give BOOL, which is also the default.
[[nodiscard]] QString guessVariableType(
    const model::Project &project, model::PouId pou, const QString &bodyText, const QString &name, bool il);

// The standard function blocks students use most, the most used first: the type box offers them,
// and where several fit a use the guess takes the first (T1.Q fits TON, TOF and TP alike).
[[nodiscard]] const QStringList &commonFunctionBlocks();

// The POU's declarations with `row` added after the last row of its class (the end when there
// is none). Fails with the table's own messages when the row is not valid there.
struct DeclareResult {
    QUndoCommand *command = nullptr; // one undo step; the caller pushes (and then owns) it
    QString error;
};
[[nodiscard]] DeclareResult createDeclareCommand(
    model::ProjectModel &model, model::PouId pou, const editors::DeclarationRow &row);

} // namespace iec::app
