// The data type editor's fields: a type (ARRAY[1..3] OF REAL) and an initial value ([1, 2(0)]) as
// typed, read by the compiler's parser. Reading never crashes; what reads prints as text that
// reads back to the same value. The first line of the input is the type, the rest the value.
#include "fuzzsupport.h"

#include "editors/datatypes/typetext.h"

using namespace iec;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QString text = fuzzing::text(data, size);
    const qsizetype newline = text.indexOf(QLatin1Char('\n'));
    const QString typePart = newline < 0 ? text : text.left(newline);
    const QString valuePart = newline < 0 ? QString() : text.mid(newline + 1);

    const editors::Parsed<model::DataType> type = editors::parseTypeText(typePart);
    if (type.ok) {
        const QString printed = editors::typeText(type.value);
        const editors::Parsed<model::DataType> again = editors::parseTypeText(printed);
        FUZZ_CHECK(again.ok && again.value == type.value, printed);
    }
    const editors::Parsed<std::optional<model::Value>> value = editors::parseValueText(valuePart);
    if (value.ok) {
        const QString printed = editors::valueText(value.value);
        const editors::Parsed<std::optional<model::Value>> again = editors::parseValueText(printed);
        FUZZ_CHECK(again.ok && again.value == value.value, printed);
    }
    editors::integerLiteral(typePart);
    return 0;
}
