#pragma once

#include "model/elements_fbd.h"

#include <QString>

// Sizes of texts and boxes in the data-flow languages (LD, FBD, CFC), estimated from the
// characters so that the same body gets the same positions on every machine (the positions are
// written into the file).
namespace iec::editors {

// The width of a text in the diagrams' font (CJK characters count about twice).
double textWidth(const QString &text);
// `value` rounded up to a multiple of `step`.
double roundUp(double value, double step);
// The width of a box: its type name, and its input and output pin names side by side.
double boxWidth(const model::Block &block);

} // namespace iec::editors
