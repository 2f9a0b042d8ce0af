#include "editors/datatypes/datatypeform.h"

#include "editors/datatypes/typetext.h"

#include <type_traits>

namespace iec::editors {

namespace {

void fillMembers(DataTypeForm &form, const model::StructType &type)
{
    for (size_t i = 0; i < type.members.size(); ++i) {
        const model::Variable &member = type.members[i];
        form.members.push_back({member.name, typeText(member.type), valueText(member.initialValue),
            member.documentation ? member.documentation->text : QString(), int(i)});
    }
}

void fillKind(DataTypeForm &form, const model::DataType &type)
{
    std::visit(
        [&form, &type](const auto &kind) {
            using Kind = std::decay_t<decltype(kind)>;
            if constexpr (std::is_same_v<Kind, model::StructType>) {
                form.kind = TypeKind::Struct;
                fillMembers(form, kind);
            } else if constexpr (std::is_same_v<Kind, model::EnumType>) {
                form.kind = TypeKind::Enum;
                for (const model::EnumValue &value : kind.values)
                    form.enumValues.push_back({value.name, value.value.value_or(QString())});
                form.enumBaseType = kind.baseType ? typeText(**kind.baseType) : QString();
            } else if constexpr (std::is_same_v<Kind, model::ArrayType>) {
                form.kind = TypeKind::Array;
                form.dimensions = kind.dimensions;
                form.elementType = typeText(*kind.baseType);
            } else if constexpr (std::is_same_v<Kind, model::SubrangeType>) {
                form.kind = TypeKind::Subrange;
                form.baseType = typeText(*kind.baseType);
                form.range = kind.range;
            } else if constexpr (std::is_same_v<Kind, model::StringType>) {
                form.kind = TypeKind::String;
                form.wideString = kind.wide;
                form.stringLength = kind.length.value_or(QString());
            } else {
                form.kind = TypeKind::Alias;
                form.baseType = typeText(type);
            }
        },
        type.kind);
}

template<typename Kind> const Kind *originalKind(const model::DataTypeDecl &original)
{
    return std::get_if<Kind>(&original.baseType.kind);
}

// The text of an optional field: empty means absent.
std::optional<QString> optionalText(const QString &text)
{
    const QString trimmed = text.trimmed();
    return trimmed.isEmpty() ? std::nullopt : std::optional(trimmed);
}

std::optional<model::FormattedText> comment(const QString &text, const std::optional<model::FormattedText> &previous)
{
    if (previous && previous->text == text)
        return previous;
    return text.isEmpty() ? std::nullopt : std::optional(model::FormattedText {text, {}});
}

std::optional<model::Variable> member(const MemberRow &row, const model::Variable *previous)
{
    model::Variable variable = previous ? *previous : model::Variable {};
    const auto type = parseTypeText(row.type, previous ? &previous->type : nullptr);
    const auto value = parseValueText(row.initialValue, previous ? &previous->initialValue : nullptr);
    if (!type.ok || !value.ok)
        return std::nullopt;
    variable.name = row.name.trimmed();
    variable.type = type.value;
    variable.initialValue = value.value;
    variable.documentation = comment(row.comment, variable.documentation);
    return variable;
}

std::optional<model::DataType> structType(const DataTypeForm &form, const model::DataTypeDecl &original)
{
    const auto *previous = originalKind<model::StructType>(original);
    model::StructType type = previous ? *previous : model::StructType {};
    type.members.clear();
    for (const MemberRow &row : form.members) {
        std::optional<model::Variable> variable = member(row, originalMember(original, row));
        if (!variable)
            return std::nullopt;
        type.members.push_back(std::move(*variable));
    }
    return model::DataType {type};
}

std::optional<model::DataType> enumType(const DataTypeForm &form, const model::DataTypeDecl &original)
{
    model::EnumType type;
    for (const EnumRow &row : form.enumValues)
        type.values.push_back({row.name.trimmed(), optionalText(row.value)});
    if (optionalText(form.enumBaseType)) {
        const auto *previous = originalKind<model::EnumType>(original);
        const bool hadBase = previous && previous->baseType;
        const auto base = parseTypeText(form.enumBaseType, hadBase ? &**previous->baseType : nullptr);
        if (!base.ok)
            return std::nullopt;
        type.baseType = model::Box<model::DataType>(base.value);
    }
    return model::DataType {type};
}

std::optional<model::DataType> arrayType(const DataTypeForm &form, const model::DataTypeDecl &original)
{
    const auto *previous = originalKind<model::ArrayType>(original);
    const auto element = parseTypeText(form.elementType, previous ? &*previous->baseType : nullptr);
    if (!element.ok)
        return std::nullopt;
    model::ArrayType type;
    for (const model::Range &range : form.dimensions)
        type.dimensions.push_back({range.lower.trimmed(), range.upper.trimmed()});
    type.baseType = model::Box<model::DataType>(element.value);
    return model::DataType {type};
}

std::optional<model::DataType> subrangeType(const DataTypeForm &form, const model::DataTypeDecl &original)
{
    const auto *previous = originalKind<model::SubrangeType>(original);
    const auto base = parseTypeText(form.baseType, previous ? &*previous->baseType : nullptr);
    if (!base.ok)
        return std::nullopt;
    // As the IEC reader decides it: USINT, UINT, ... are the unsigned bases.
    const bool isUnsigned = form.baseType.trimmed().startsWith(QLatin1Char('U'), Qt::CaseInsensitive);
    const model::Range range {form.range.lower.trimmed(), form.range.upper.trimmed()};
    return model::DataType {model::SubrangeType {isUnsigned, range, model::Box<model::DataType>(base.value)}};
}

std::optional<model::DataType> aliasType(const DataTypeForm &form, const model::DataTypeDecl &original)
{
    const auto base = parseTypeText(form.baseType, &original.baseType);
    return base.ok ? std::optional(base.value) : std::nullopt;
}

std::optional<model::DataType> stringType(const DataTypeForm &form)
{
    return model::DataType {model::StringType {form.wideString, optionalText(form.stringLength)}};
}

std::optional<model::DataType> dataType(const DataTypeForm &form, const model::DataTypeDecl &original)
{
    switch (form.kind) {
    case TypeKind::Struct:
        return structType(form, original);
    case TypeKind::Enum:
        return enumType(form, original);
    case TypeKind::Array:
        return arrayType(form, original);
    case TypeKind::Subrange:
        return subrangeType(form, original);
    case TypeKind::Alias:
        return aliasType(form, original);
    case TypeKind::String:
        return stringType(form);
    }
    return std::nullopt;
}

} // namespace

DataTypeForm formFromDecl(const model::DataTypeDecl &decl)
{
    DataTypeForm form;
    form.name = decl.name;
    fillKind(form, decl.baseType);
    form.initialValue = valueText(decl.initialValue);
    return form;
}

std::optional<model::DataTypeDecl> declFromForm(const DataTypeForm &form, const model::DataTypeDecl &original)
{
    std::optional<model::DataType> type = dataType(form, original);
    const auto initial = parseValueText(form.initialValue, &original.initialValue);
    if (!type || !initial.ok)
        return std::nullopt;
    model::DataTypeDecl decl = original;
    decl.name = form.name.trimmed();
    decl.baseType = std::move(*type);
    decl.initialValue = initial.value;
    return decl;
}

const model::Variable *originalMember(const model::DataTypeDecl &original, const MemberRow &row)
{
    const auto *type = originalKind<model::StructType>(original);
    if (!type || row.origin < 0 || size_t(row.origin) >= type->members.size())
        return nullptr;
    return &type->members[size_t(row.origin)];
}

DataTypeForm withKind(DataTypeForm form, TypeKind kind)
{
    if (form.kind != kind)
        form.initialValue.clear(); // a value of the old kind rarely fits the new one
    form.kind = kind;
    const QString defaultType = QStringLiteral("INT");
    switch (kind) {
    case TypeKind::Struct:
        if (form.members.empty())
            form.members.push_back({QStringLiteral("Member1"), defaultType, {}, {}, -1});
        break;
    case TypeKind::Enum:
        if (form.enumValues.empty())
            form.enumValues.push_back({QStringLiteral("Value1"), {}});
        break;
    case TypeKind::Array:
        if (form.dimensions.empty())
            form.dimensions.push_back({QStringLiteral("1"), QStringLiteral("10")});
        if (form.elementType.trimmed().isEmpty()) // an alias becomes an array of what it named
            form.elementType = form.baseType.trimmed().isEmpty() ? defaultType : form.baseType;
        break;
    case TypeKind::Subrange:
        if (form.range.lower.trimmed().isEmpty() && form.range.upper.trimmed().isEmpty())
            form.range = {QStringLiteral("0"), QStringLiteral("100")};
        if (!isIntegerTypeName(form.baseType)) // a REAL alias becomes an INT subrange, not an invalid form
            form.baseType = defaultType;
        break;
    case TypeKind::Alias:
        if (form.baseType.trimmed().isEmpty())
            form.baseType = defaultType;
        break;
    case TypeKind::String:
        break;
    }
    return form;
}

} // namespace iec::editors
