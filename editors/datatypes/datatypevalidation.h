#pragma once

#include "editors/datatypes/datatypeform.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <vector>

namespace iec::model {
struct Project;
}

namespace iec::editors {

// Which field of the form a message belongs to; `row` is the table row for row fields.
enum class FormField {
    Name,
    Members, // the member table as a whole
    MemberName,
    MemberType,
    MemberValue,
    EnumValues,
    EnumName,
    EnumValue,
    EnumBaseType,
    Dimensions,
    DimensionLow,
    DimensionHigh,
    ElementType,
    BaseType,
    RangeLow,
    RangeHigh,
    StringLength,
    InitialValue,
};

struct FormError {
    FormField field = FormField::Name;
    int row = -1;
    QString message;

    bool operator==(const FormError &) const = default;
};

// What the form is checked against: the names the type may not take and the type names it may use.
struct TypeContext {
    QStringList takenNames; // other data types and every POU (one namespace)
    QStringList typeNames; // the project's other data types and function blocks (library ones are known anyway)
    model::DataTypeDecl original;
};

// The context for editing data type `name` of `project`.
TypeContext typeContext(const model::Project &project, const QString &name);

// Every problem of the form, in field order; empty when the form may be applied.
class DataTypeValidator
{
    Q_DECLARE_TR_FUNCTIONS(iec::editors::DataTypeValidator)

public:
    static std::vector<FormError> validate(const DataTypeForm &form, const TypeContext &context);

    // nullopt for a valid IEC identifier that is not a keyword; otherwise why not.
    static std::optional<QString> identifierError(const QString &name);
};

} // namespace iec::editors
