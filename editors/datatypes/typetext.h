#pragma once

#include "model/datatypes.h"

#include <QString>

#include <optional>

// Type expressions and initial values as the user types them (INT, ARRAY[1..3] OF REAL, [1, 2, 3])
// turned into model values by the compiler's own parser, so the editor accepts exactly what the
// rest of IEC Studio understands.
namespace iec::editors {

template<typename T> struct Parsed {
    bool ok = false;
    T value {};
};

// When `text` is what `previous` prints as, `previous` itself is the result: an untouched field
// keeps everything the model holds beyond the text (vendor data, kinds the parser cannot read).
Parsed<model::DataType> parseTypeText(const QString &text, const model::DataType *previous = nullptr);
// An empty text is a valid "no initial value".
Parsed<std::optional<model::Value>> parseValueText(
    const QString &text, const std::optional<model::Value> *previous = nullptr);

QString typeText(const model::DataType &type);
QString valueText(const std::optional<model::Value> &value);

// SINT, INT, DINT, LINT and their unsigned forms: what a subrange or an enumeration may be based on.
bool isIntegerTypeName(const QString &name);

// A whole number as IEC writes it: -5, 1_000, 16#FF, 2#1010, 8#17 (no type prefix).
std::optional<qint64> integerLiteral(const QString &text);

} // namespace iec::editors
