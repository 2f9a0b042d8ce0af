#pragma once

#include "model/elements_fbd.h"

#include "model/element.h"

#include <QSizeF>
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
// The size of a variable, jump or return: one row high, as wide as its text.
QSizeF sinkOrVariableSize(const model::Element &element);

} // namespace iec::editors
