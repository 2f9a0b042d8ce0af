#pragma once

#include "interpreter/compiler/diagnostics.h"

#include "model/diagnostic.h"

#include <QTextStream>

#include <vector>

namespace iec::cli {

// Reader diagnostics (positions in the file):
// FILE:LINE:COLUMN: error|warning|note: MESSAGE [pou NAME] [localId N], one per line
// ("FILE: error: ..." when the position is unknown).
void printDiagnostics(const QString &file, const std::vector<model::Diagnostic> &diagnostics, QTextStream &stream);

// Compiler diagnostics (positions in a POU): FILE:POU:LINE:COLUMN: error|warning: MESSAGE
// (hint: HINT); without a POU FILE:LINE:COLUMN: ...; without a position FILE:POU: ...
QString formatDiagnostic(const QString &file, const interp::Diagnostic &diagnostic);
void printDiagnostics(const QString &file, const interp::Diagnostics &diagnostics, QTextStream &stream);

} // namespace iec::cli
