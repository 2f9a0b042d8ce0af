#pragma once

#include <QStringList>

// Where a breakpoint's line goes when the text around it is edited, so that it stays on its
// statement as in CODESYS (DebugController follows every change of a text body with it).
namespace iec::app {

// The 1-based `line` of `before` in `after`: lines above the edited part keep their number,
// lines below it move with it, and a line inside it stays where the edited part still has a line
// (an edited statement keeps its breakpoint). 0: the line was deleted.
[[nodiscard]] int lineAfterEdit(int line, const QStringList &before, const QStringList &after);

} // namespace iec::app
