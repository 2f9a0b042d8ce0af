#pragma once

#include "interpreter/compiler/lexer.h"

#include <QStringView>

namespace iec::editors {

inline constexpr int kUnmatchedBracket = -1; // a bracket without a partner
inline constexpr int kNoBracket = -2; // no bracket at the position (or only one inside a comment or string)

// The position of the bracket that matches the one at `position` in `text` (round or square),
// kUnmatchedBracket, or kNoBracket. Brackets inside comments, strings and pragmas do not count:
// the text is read with the interpreter's lexer, starting in `state` (the lexer state at the
// start of `text`).
[[nodiscard]] int matchingBracket(QStringView text, int position, interp::LexState state = {});

} // namespace iec::editors
