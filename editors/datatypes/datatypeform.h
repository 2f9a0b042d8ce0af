#pragma once

#include "model/datatypes.h"

#include <QString>

#include <optional>
#include <vector>

// The data type editor's fields as plain text, and the conversions between them and a
// DataTypeDecl. Pure: no widgets, so both directions are tested as tables.
namespace iec::editors {

// The forms the editor offers. Elementary, derived and pointer types are all edited as an alias.
enum class TypeKind { Struct, Enum, Array, Subrange, Alias, String };

struct MemberRow {
    QString name;
    QString type;
    QString initialValue;
    QString comment;
    int origin = -1; // index of the model member this row shows, -1 for a new row

    bool operator==(const MemberRow &) const = default;
};

struct EnumRow {
    QString name;
    QString value; // empty: no explicit value

    bool operator==(const EnumRow &) const = default;
};

struct DataTypeForm {
    QString name;
    TypeKind kind = TypeKind::Alias;
    std::vector<MemberRow> members; // Struct
    std::vector<EnumRow> enumValues; // Enum
    QString enumBaseType; // Enum, empty: none
    std::vector<model::Range> dimensions; // Array
    QString elementType; // Array
    QString baseType; // Subrange, Alias
    model::Range range; // Subrange
    bool wideString = false; // String
    QString stringLength; // String, empty: the default length
    QString initialValue;

    bool operator==(const DataTypeForm &) const = default;
};

DataTypeForm formFromDecl(const model::DataTypeDecl &decl);

// The declaration the form describes. `original` is the type being edited: what the form does not
// show (vendor data, documentation, untouched fields) is kept from it. nullopt when a type or
// value text does not parse (validateForm says which).
std::optional<model::DataTypeDecl> declFromForm(const DataTypeForm &form, const model::DataTypeDecl &original);

// The member of `original` (a struct) that `row` shows, nullptr for a new row.
const model::Variable *originalMember(const model::DataTypeDecl &original, const MemberRow &row);

// The form switched to `kind`; the new kind's fields get a small valid start where they are empty,
// so that switching the kind alone is a valid edit.
DataTypeForm withKind(DataTypeForm form, TypeKind kind);

} // namespace iec::editors
