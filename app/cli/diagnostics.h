#pragma once

#include "model/diagnostic.h"

#include <QTextStream>

#include <vector>

namespace iec::cli {

// FILE:LINE:COLUMN: error|warning|note: MESSAGE [pou NAME] [localId N], one per line
// ("FILE: error: ..." when the position is unknown).
void printDiagnostics(const QString &file, const std::vector<model::Diagnostic> &diagnostics, QTextStream &stream);

} // namespace iec::cli
