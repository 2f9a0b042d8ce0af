#pragma once

#include "editors/text/textlanguage.h"

#include <QList>
#include <QStringView>

namespace iec::editors {

// The foldable line ranges of a text: IF ... END_IF and the other control blocks (ST), VAR ...
// END_VAR, STRUCT, TYPE, the POU headers, and comments that span lines. Sorted by first line;
// ranges nest. Keywords inside comments and strings do not count (the interpreter's lexer reads
// the text). An unclosed block has no range.
[[nodiscard]] QList<FoldRange> foldingRanges(QStringView text, TextLanguage language);

} // namespace iec::editors
