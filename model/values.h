#pragma once

#include "model/box.h"

#include <QString>

#include <optional>
#include <variant>
#include <vector>

namespace iec::model {

struct Value;

// ppx:value — the initial value of a variable or data type.
struct SimpleValue {
    std::optional<QString> value;

    bool operator==(const SimpleValue &) const = default;
};

struct ArrayValueItem {
    std::optional<QString> repetitionValue; // "n" in n(value); absent means 1
    Box<Value> value;

    bool operator==(const ArrayValueItem &) const = default;
};

struct ArrayValue {
    std::vector<ArrayValueItem> values;

    bool operator==(const ArrayValue &) const = default;
};

struct StructValueItem {
    QString member;
    Box<Value> value;

    bool operator==(const StructValueItem &) const = default;
};

struct StructValue {
    std::vector<StructValueItem> values;

    bool operator==(const StructValue &) const = default;
};

struct Value {
    std::variant<SimpleValue, ArrayValue, StructValue> kind;

    bool operator==(const Value &) const = default;
};

} // namespace iec::model
