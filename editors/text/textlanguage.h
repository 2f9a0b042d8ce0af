#pragma once

#include <QList>
#include <QString>

namespace iec::editors {

// The two textual IEC 61131-3 languages the CodeEditor edits. Everything that differs between
// them is data (keyword tables, block rules), never a second copy of the editor.
enum class TextLanguage { ST, IL };

// A compiler diagnostic placed in a text body. `line` and `column` are 1-based, as the compiler
// reports them; `length` is in characters (0 underlines one character).
struct TextDiagnostic {
    enum class Severity { Error, Warning, Info };

    int line = 1;
    int column = 1;
    int length = 0;
    Severity severity = Severity::Error;
    QString message;

    bool operator==(const TextDiagnostic &) const = default;
};

// Lines are 0-based block numbers here, as QTextDocument counts them.
struct FoldRange {
    int firstLine = 0; // stays visible when folded
    int lastLine = 0; // the closing line (END_IF, END_VAR, the line with *))

    bool operator==(const FoldRange &) const = default;
};

} // namespace iec::editors
