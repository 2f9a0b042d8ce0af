#pragma once

#include "editors/text/textlanguage.h"

#include <QString>
#include <QStringView>

namespace iec::editors {

// Block structure of ST and IL as pure functions: what Enter inserts (auto-indent and block
// completion), how a closing keyword re-indents its line, and which keywords open and close
// blocks (shared with the folding regions).

inline constexpr int kIndentWidth = 4;

// The keyword that closes a block opened by `word` (upper case), or an empty string. IF, CASE,
// FOR, WHILE, REPEAT are ST only; VAR..., STRUCT, TYPE and the POU headers belong to both.
[[nodiscard]] QString blockCloserFor(QStringView word, TextLanguage language);

// What pressing Enter does at `column` of `line`:
// delete `removeAfter` characters after the cursor (blanks), insert `text`, put the cursor
// `cursorOffset` characters into `text`.
struct EnterEdit {
    QString text;
    int cursorOffset = 0;
    int removeAfter = 0;

    bool operator==(const EnterEdit &) const = default;
};

// `followingText` is the text after `line` (the rest of the document); it decides whether a block
// is already closed, so that Enter inside an existing IF does not add a second END_IF.
[[nodiscard]] EnterEdit enterEdit(QStringView line, int column, QStringView followingText, TextLanguage language);

// When `line` starts with END_IF, ELSE, ELSIF, UNTIL, END_CASE ... : the indentation (in spaces)
// it should have after `previousLine` (the nearest non-blank line above it), or -1 to leave it.
// Only ever moves a line left.
[[nodiscard]] int closingKeywordIndent(QStringView line, QStringView previousLine, TextLanguage language);

// Number of columns of leading whitespace (a tab counts kIndentWidth).
[[nodiscard]] int indentationOf(QStringView line);

} // namespace iec::editors
