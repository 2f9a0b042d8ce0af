#pragma once

#include "model/box.h"
#include "model/opaque.h"
#include "model/values.h"

#include <QString>

#include <optional>
#include <variant>
#include <vector>

namespace iec::model {

struct DataType;
struct Variable; // defined in variables.h, included at the end of this file

// ppx:dataType — one of the XSD's elementary, derived or extended types.

// BOOL, BYTE, ..., TOD and the generic ANY, ANY_NUM, ...: the XSD element name is the type name.
struct ElementaryType {
    QString name = QStringLiteral("BOOL");

    bool operator==(const ElementaryType &) const = default;
};

// <string length=".."/> and <wstring length=".."/>.
struct StringType {
    bool wide = false;
    std::optional<QString> length;

    bool operator==(const StringType &) const = default;
};

// ppx:rangeSigned / ppx:rangeUnsigned: bounds are kept as written (they may be constants).
struct Range {
    QString lower;
    QString upper;

    bool operator==(const Range &) const = default;
};

struct ArrayType {
    std::vector<Range> dimensions;
    Box<DataType> baseType;

    bool operator==(const ArrayType &) const = default;
};

// A reference to a user-defined type by name.
struct DerivedType {
    QString name;
    AddData addData;
    Extras extras;

    bool operator==(const DerivedType &) const = default;
};

struct EnumValue {
    QString name;
    std::optional<QString> value;

    bool operator==(const EnumValue &) const = default;
};

struct EnumType {
    std::vector<EnumValue> values;
    std::optional<Box<DataType>> baseType;

    bool operator==(const EnumType &) const = default;
};

// <struct> is a ppx:varListPlain.
struct StructType {
    std::vector<Variable> members;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const StructType &) const;
};

struct SubrangeType {
    bool isUnsigned = false; // subrangeUnsigned instead of subrangeSigned
    Range range;
    Box<DataType> baseType;

    bool operator==(const SubrangeType &) const = default;
};

struct PointerType {
    Box<DataType> baseType;

    bool operator==(const PointerType &) const = default;
};

struct DataType {
    std::variant<ElementaryType, StringType, ArrayType, DerivedType, EnumType, StructType, SubrangeType, PointerType>
        kind;

    bool operator==(const DataType &) const = default;
};

// A named type under types/dataTypes.
struct DataTypeDecl {
    QString name;
    DataType baseType;
    std::optional<Value> initialValue;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;
    // Set when the type came from a vendor addData entry (CODESYS keeps data types there); the
    // writer puts it back into that entry instead of types/dataTypes. 0: an ordinary type.
    quint32 addDataSlot = 0;

    bool operator==(const DataTypeDecl &) const = default;
};

} // namespace iec::model

#include "model/variables.h"
