#include "editors/datatypes/datatypevalidation.h"

#include "editors/datatypes/typetext.h"
#include "interpreter/compiler/ast.h"
#include "interpreter/compiler/compiler.h"
#include "interpreter/compiler/lexer.h"
#include "interpreter/compiler/svghmi.h"
#include "model/project.h"

#include <QRegularExpression>
#include <QSet>

#include <algorithm>

namespace iec::editors {

namespace {

bool sameName(const QString &a, const QString &b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

// The user-defined type names a type refers to (elementary names need no check).
void collectNames(const model::DataType &type, QStringList &names)
{
    std::visit(
        [&names](const auto &kind) {
            using Kind = std::decay_t<decltype(kind)>;
            if constexpr (std::is_same_v<Kind, model::DerivedType>) {
                names << kind.name;
            } else if constexpr (
                std::is_same_v<Kind,
                    model::
                        ArrayType> || std::is_same_v<Kind, model::SubrangeType> || std::is_same_v<Kind, model::PointerType>) {
                collectNames(*kind.baseType, names);
            } else if constexpr (std::is_same_v<Kind, model::StructType>) {
                for (const model::Variable &member : kind.members)
                    collectNames(member.type, names);
            } else if constexpr (std::is_same_v<Kind, model::EnumType>) {
                if (kind.baseType)
                    collectNames(**kind.baseType, names);
            }
        },
        type.kind);
}

// Types the compiler knows without the project declaring them: the standard function blocks
// (CTU_DINT too), the Util library's blocks and types (BLINK, GEN_MODE, ...) and Beremiz's SVGHMI
// types. Read from the compiler's own definitions, so the editor accepts what it compiles.
bool isLibraryType(const QString &name)
{
    static const QSet<QString> names = [] {
        QSet<QString> all;
        for (const interp::ast::CompilationUnit *unit : {&interp::standardLibrary(), &interp::utilLibrary()}) {
            for (const interp::ast::Pou &pou : unit->pous) {
                if (pou.kind == interp::ast::PouKind::FunctionBlock)
                    all.insert(pou.name.toUpper());
            }
            for (const interp::ast::TypeDecl &type : unit->types)
                all.insert(type.name.toUpper());
        }
        return all;
    }();
    const QString upper = name.toUpper();
    return names.contains(upper) || !interp::svgHmiBaseType(upper).isEmpty();
}

// Collects the messages of one form; each check adds at most one message per field.
class Checker
{
public:
    Checker(const DataTypeForm &form, const TypeContext &context)
        : m_form(form)
        , m_context(context)
    { }

    std::vector<FormError> run()
    {
        checkName();
        checkKind();
        checkValue(m_form.initialValue, &m_context.original.initialValue, FormField::InitialValue, -1);
        return std::move(m_errors);
    }

private:
    void add(FormField field, int row, const QString &message) { m_errors.push_back({field, row, message}); }

    void checkName()
    {
        const QString name = m_form.name.trimmed();
        if (const auto error = DataTypeValidator::identifierError(name))
            add(FormField::Name, -1, *error);
        else if (std::ranges::any_of(m_context.takenNames, [&](const QString &taken) { return sameName(taken, name); }))
            add(FormField::Name, -1,
                DataTypeValidator::tr("A POU or data type named \"%1\" exists already.").arg(name));
    }

    void checkKind()
    {
        switch (m_form.kind) {
        case TypeKind::Struct:
            return checkMembers();
        case TypeKind::Enum:
            return checkEnum();
        case TypeKind::Array:
            return checkArray();
        case TypeKind::Subrange:
            return checkSubrange();
        case TypeKind::Alias:
            return checkType(m_form.baseType, &m_context.original.baseType, FormField::BaseType, -1);
        case TypeKind::String:
            return checkStringLength();
        }
    }

    // Reports a missing, malformed or duplicate name of row `row`; `seen` collects the names.
    void checkRowName(const QString &text, FormField field, int row, QStringList &seen, const QString &duplicate)
    {
        const QString name = text.trimmed();
        if (const auto error = DataTypeValidator::identifierError(name))
            add(field, row, *error);
        else if (seen.contains(name, Qt::CaseInsensitive))
            add(field, row, duplicate.arg(name));
        seen << name;
    }

    void checkMembers()
    {
        if (m_form.members.empty())
            add(FormField::Members, -1, DataTypeValidator::tr("A structure needs at least one member."));
        QStringList seen;
        for (int row = 0; row < int(m_form.members.size()); ++row) {
            const MemberRow &member = m_form.members[size_t(row)];
            checkRowName(member.name, FormField::MemberName, row, seen,
                DataTypeValidator::tr("There is a member named \"%1\" already."));
            const model::Variable *previous = originalMember(m_context.original, member);
            checkType(member.type, previous ? &previous->type : nullptr, FormField::MemberType, row);
            checkValue(member.initialValue, previous ? &previous->initialValue : nullptr, FormField::MemberValue, row);
        }
    }

    void checkEnum()
    {
        if (m_form.enumValues.empty())
            add(FormField::EnumValues, -1, DataTypeValidator::tr("An enumeration needs at least one value."));
        QStringList seen;
        for (int row = 0; row < int(m_form.enumValues.size()); ++row) {
            const EnumRow &value = m_form.enumValues[size_t(row)];
            checkRowName(value.name, FormField::EnumName, row, seen,
                DataTypeValidator::tr("The value \"%1\" is listed already."));
            if (!value.value.trimmed().isEmpty() && !integerLiteral(value.value))
                add(FormField::EnumValue, row, DataTypeValidator::tr("Enter a whole number, or leave it empty."));
        }
        if (!m_form.enumBaseType.trimmed().isEmpty())
            checkIntegerType(m_form.enumBaseType, FormField::EnumBaseType);
    }

    void checkArray()
    {
        if (m_form.dimensions.empty())
            add(FormField::Dimensions, -1, DataTypeValidator::tr("An array needs at least one dimension."));
        for (int row = 0; row < int(m_form.dimensions.size()); ++row)
            checkRange(m_form.dimensions[size_t(row)], FormField::DimensionLow, FormField::DimensionHigh, row);
        const auto *original = std::get_if<model::ArrayType>(&m_context.original.baseType.kind);
        checkType(m_form.elementType, original ? &*original->baseType : nullptr, FormField::ElementType, -1);
    }

    void checkSubrange()
    {
        checkIntegerType(m_form.baseType, FormField::BaseType);
        checkRange(m_form.range, FormField::RangeLow, FormField::RangeHigh, -1);
    }

    void checkStringLength()
    {
        const QString length = m_form.stringLength.trimmed();
        const std::optional<qint64> value = integerLiteral(length);
        if (!length.isEmpty() && (!value || *value < 1 || *value > 65535))
            add(FormField::StringLength, -1,
                DataTypeValidator::tr("Enter a length from 1 to 65535, or leave it empty for the default."));
    }

    void checkIntegerType(const QString &text, FormField field)
    {
        if (!isIntegerTypeName(text))
            add(field, -1, DataTypeValidator::tr("Choose an integer type such as INT, DINT or UINT."));
    }

    // A bound is a whole number or the name of a constant; number bounds must not be reversed.
    void checkRange(const model::Range &range, FormField lowField, FormField highField, int row)
    {
        const bool lowOk = checkBound(range.lower, lowField, row);
        const bool highOk = checkBound(range.upper, highField, row);
        const std::optional<qint64> low = integerLiteral(range.lower);
        const std::optional<qint64> high = integerLiteral(range.upper);
        if (lowOk && highOk && low && high && *low > *high)
            add(highField, row,
                DataTypeValidator::tr("The upper bound %1 is less than the lower bound %2.")
                    .arg(range.upper.trimmed(), range.lower.trimmed()));
    }

    bool checkBound(const QString &text, FormField field, int row)
    {
        const QString bound = text.trimmed();
        if (bound.isEmpty()) {
            add(field, row, DataTypeValidator::tr("Enter a bound."));
            return false;
        }
        if (!integerLiteral(bound) && DataTypeValidator::identifierError(bound)) {
            add(field, row, DataTypeValidator::tr("Enter a whole number or the name of a constant."));
            return false;
        }
        return true;
    }

    void checkType(const QString &text, const model::DataType *previous, FormField field, int row)
    {
        if (text.trimmed().isEmpty()) {
            add(field, row, DataTypeValidator::tr("Enter a type."));
            return;
        }
        const Parsed<model::DataType> type = parseTypeText(text, previous);
        if (!type.ok) {
            add(field, row, DataTypeValidator::tr("\"%1\" is not a type.").arg(text.trimmed()));
            return;
        }
        QStringList names;
        collectNames(type.value, names);
        for (const QString &name : names) {
            if (sameName(name, m_form.name.trimmed())) {
                add(field, row, DataTypeValidator::tr("A type cannot contain itself."));
                return;
            }
            if (!m_context.typeNames.contains(name, Qt::CaseInsensitive) && !isLibraryType(name)) {
                add(field, row, DataTypeValidator::tr("Unknown type \"%1\".").arg(name));
                return;
            }
        }
    }

    void checkValue(const QString &text, const std::optional<model::Value> *previous, FormField field, int row)
    {
        if (!parseValueText(text, previous).ok)
            add(field, row, DataTypeValidator::tr("\"%1\" is not a valid initial value.").arg(text.trimmed()));
    }

    const DataTypeForm &m_form;
    const TypeContext &m_context;
    std::vector<FormError> m_errors;
};

} // namespace

TypeContext typeContext(const model::Project &project, const QString &name)
{
    TypeContext context;
    for (const model::DataTypeDecl &type : project.types.dataTypes) {
        if (sameName(type.name, name)) {
            context.original = type;
            continue;
        }
        context.takenNames << type.name;
        context.typeNames << type.name;
    }
    for (const model::Pou &pou : project.types.pous) {
        context.takenNames << pou.name;
        if (pou.kind == model::PouKind::FunctionBlock)
            context.typeNames << pou.name;
    }
    return context;
}

std::vector<FormError> DataTypeValidator::validate(const DataTypeForm &form, const TypeContext &context)
{
    return Checker(form, context).run();
}

std::optional<QString> DataTypeValidator::identifierError(const QString &name)
{
    if (name.isEmpty())
        return tr("Enter a name.");
    if (!interp::hasIdentifierShape(name))
        return tr("\"%1\" is not an IEC identifier: use letters, digits and single underscores, starting with a "
                  "letter or an underscore and not ending with an underscore.")
            .arg(name);
    if (interp::isKeyword(name) || interp::isTypeName(name))
        return tr("\"%1\" is a reserved word of IEC 61131-3.").arg(name);
    return std::nullopt;
}

} // namespace iec::editors
