#include "editors/datatypes/typetext.h"

#include "interpreter/frontend/iecprinter.h"
#include "interpreter/frontend/iecreader.h"

namespace iec::editors {

namespace {

// Parses "TYPE T : <type> := <value>; END_TYPE"; one declaration and no error, or nothing.
std::optional<model::DataTypeDecl> parseDeclaration(const QString &type, const QString &value)
{
    QString source = QStringLiteral("TYPE ParsedType : ") + type;
    if (!value.isEmpty())
        source += QStringLiteral(" := ") + value;
    source += QStringLiteral(";\nEND_TYPE\n");
    interp::frontend::TextReadResult result = interp::frontend::readIecText(source, QString());
    if (result.diagnostics.hasErrors() || result.project.types.dataTypes.size() != 1
        || !result.project.types.pous.empty() || !result.project.instances.configurations.empty())
        return std::nullopt;
    return std::move(result.project.types.dataTypes.front());
}

} // namespace

QString typeText(const model::DataType &type)
{
    return interp::frontend::printDataType(type);
}

QString valueText(const std::optional<model::Value> &value)
{
    return value ? interp::frontend::printValue(*value) : QString();
}

Parsed<model::DataType> parseTypeText(const QString &text, const model::DataType *previous)
{
    const QString trimmed = text.trimmed();
    if (previous && typeText(*previous) == trimmed)
        return {true, *previous};
    if (trimmed.isEmpty())
        return {};
    const std::optional<model::DataTypeDecl> decl = parseDeclaration(trimmed, {});
    if (!decl)
        return {};
    return {true, decl->baseType};
}

Parsed<std::optional<model::Value>> parseValueText(const QString &text, const std::optional<model::Value> *previous)
{
    const QString trimmed = text.trimmed();
    if (previous && valueText(*previous) == trimmed)
        return {true, *previous};
    if (trimmed.isEmpty())
        return {true, std::nullopt};
    // The initializer's form ([..], (a := ..) or an expression) follows from its syntax alone.
    const std::optional<model::DataTypeDecl> decl = parseDeclaration(QStringLiteral("INT"), trimmed);
    if (!decl || !decl->initialValue)
        return {};
    return {true, decl->initialValue};
}

bool isIntegerTypeName(const QString &name)
{
    static const QStringList integers {QStringLiteral("SINT"), QStringLiteral("INT"), QStringLiteral("DINT"),
        QStringLiteral("LINT"), QStringLiteral("USINT"), QStringLiteral("UINT"), QStringLiteral("UDINT"),
        QStringLiteral("ULINT")};
    return integers.contains(name.trimmed(), Qt::CaseInsensitive);
}

std::optional<qint64> integerLiteral(const QString &text)
{
    QString digits = text.trimmed();
    digits.remove(QLatin1Char('_'));
    bool negative = false;
    if (digits.startsWith(QLatin1Char('-')) || digits.startsWith(QLatin1Char('+'))) {
        negative = digits.startsWith(QLatin1Char('-'));
        digits.remove(0, 1);
    }
    int base = 10;
    const qsizetype hash = digits.indexOf(QLatin1Char('#'));
    if (hash > 0) {
        base = digits.left(hash).toInt();
        digits = digits.mid(hash + 1);
        if (base != 2 && base != 8 && base != 16)
            return std::nullopt;
    }
    if (digits.isEmpty() || !digits.front().isLetterOrNumber())
        return std::nullopt;
    bool ok = false;
    const qint64 magnitude = digits.toLongLong(&ok, base);
    if (!ok)
        return std::nullopt;
    return negative ? -magnitude : magnitude;
}

} // namespace iec::editors
