#include "interpreter/graphical/typeguess.h"

#include "interpreter/compiler/compiler.h"
#include "interpreter/graphical/evaluator.h"

#include <QRegularExpression>
#include <QSet>

namespace iec::interp::graphical {

namespace {

const QSet<QString> &comparisons()
{
    static const QSet<QString> names {QStringLiteral("GT"), QStringLiteral("GE"), QStringLiteral("EQ"),
        QStringLiteral("LE"), QStringLiteral("LT"), QStringLiteral("NE")};
    return names;
}

std::optional<ast::TypeSpec> fromAddData(const model::Block &block)
{
    static const QRegularExpression text(QStringLiteral(">\\s*([A-Za-z_][A-Za-z0-9_]*)\\s*<"));
    for (const model::AddDataEntry &entry : block.addData) {
        if (!entry.name.endsWith(QLatin1String("/outputparamtypes"), Qt::CaseInsensitive))
            continue;
        const auto match = text.match(entry.content);
        if (match.hasMatch())
            return namedType(match.captured(1).toUpper());
    }
    return std::nullopt;
}

// The first input whose type is known, for functions whose result has their inputs' type.
std::optional<ast::TypeSpec> firstKnown(const std::vector<Signal> &inputs, std::size_t from)
{
    for (std::size_t i = from; i < inputs.size(); ++i) {
        if (inputs[i].type)
            return inputs[i].type;
    }
    return std::nullopt;
}

} // namespace

std::optional<ast::TypeSpec> byStandardRule(const model::Block &block, const std::vector<Signal> &inputs);

bool isStandardFunction(const QString &name)
{
    return isStandardFunctionName(name);
}

DeclaredTypes declaredTypes(const ast::Pou &pou)
{
    DeclaredTypes types;
    for (const ast::VarSection &section : pou.sections) {
        for (const ast::VarDecl &var : section.vars)
            types.insert(var.name.toUpper(), var.type);
    }
    return types;
}

std::optional<ast::TypeSpec> literalOrDeclaredType(const ast::Expr &expr, const DeclaredTypes &declared)
{
    switch (expr.kind) {
    case ast::ExprKind::Name: {
        const auto found = declared.find(expr.text.toUpper());
        if (found == declared.end())
            return std::nullopt;
        return *found;
    }
    case ast::ExprKind::Literal: {
        if (expr.literal == TokenKind::Keyword)
            return namedType(QStringLiteral("BOOL"));
        const qsizetype hash = expr.text.indexOf(QLatin1Char('#'));
        const QString prefix = hash > 0 ? expr.text.left(hash).toUpper() : QString();
        if (expr.literal == TokenKind::TimeLiteral)
            return namedType(prefix.startsWith(QLatin1Char('L')) ? QStringLiteral("LTIME") : QStringLiteral("TIME"));
        if ((expr.literal == TokenKind::IntegerLiteral || expr.literal == TokenKind::RealLiteral) && !prefix.isEmpty()
            && !prefix.front().isDigit())
            return namedType(prefix);
        return std::nullopt; // untyped numbers take the type of what they meet
    }
    case ast::ExprKind::DirectAddress: {
        const QString size = expr.text.mid(2, 1).toUpper();
        static const QHash<QString, QString> bySize {{QStringLiteral("X"), QStringLiteral("BOOL")},
            {QStringLiteral("B"), QStringLiteral("BYTE")}, {QStringLiteral("W"), QStringLiteral("WORD")},
            {QStringLiteral("D"), QStringLiteral("DWORD")}, {QStringLiteral("L"), QStringLiteral("LWORD")}};
        return namedType(bySize.value(size, QStringLiteral("BOOL")));
    }
    case ast::ExprKind::Unary:
        return literalOrDeclaredType(expr.operands.front(), declared);
    default:
        return std::nullopt;
    }
}

std::optional<ast::TypeSpec> guessResultType(const model::Block &block, const std::vector<Signal> &inputs)
{
    if (auto type = byStandardRule(block, inputs))
        return type;
    return fromAddData(block); // CODESYS writes it, but not always right (MUX of BOOLs says INT)
}

std::optional<ast::TypeSpec> byStandardRule(const model::Block &block, const std::vector<Signal> &inputs)
{
    const QString name = block.typeName.trimmed().toUpper();
    if (comparisons().contains(name))
        return namedType(QStringLiteral("BOOL"));
    if (const auto m = conversionNamePattern().match(name); m.hasMatch())
        return namedType(m.captured(2) == QLatin1String("TRUNC") ? QStringLiteral("DINT") : m.captured(3));
    if (name == QLatin1String("TRUNC"))
        return namedType(QStringLiteral("DINT"));
    if (name == QLatin1String("LEN") || name == QLatin1String("FIND"))
        return namedType(QStringLiteral("INT"));
    if (name == QLatin1String("SEL"))
        return firstKnown(inputs, 1);
    if (name == QLatin1String("MUX"))
        return firstKnown(inputs, 1);
    if (name == QLatin1String("LIMIT"))
        return firstKnown(inputs, 0);
    if (name.endsWith(QLatin1String("_TIME")) && (name.startsWith(QLatin1String("ADD")) || name.startsWith(QLatin1String("SUB"))))
        return inputs.empty() ? std::nullopt : inputs.front().type;
    // The difference of two dates or times of day is a TIME (IEC 61131-3 table 30); a date is only
    // ever subtracted from a date, so a date as IN2 is enough to know it (IN1 may be a connector).
    const auto isDate = [&](size_t i) {
        static const QSet<QString> dates {QStringLiteral("DT"), QStringLiteral("DATE_AND_TIME"), QStringLiteral("TOD"),
            QStringLiteral("TIME_OF_DAY"), QStringLiteral("DATE"), QStringLiteral("D")};
        return i < inputs.size() && inputs[i].type && inputs[i].type->kind == ast::TypeSpec::Kind::Named
            && dates.contains(inputs[i].type->name.toUpper());
    };
    if (name == QLatin1String("SUB_DT_DT") || name == QLatin1String("SUB_TOD_TOD") || name == QLatin1String("SUB_DATE_DATE")
        || (name == QLatin1String("SUB") && isDate(1)))
        return namedType(QStringLiteral("TIME"));
    static const QSet<QString> sameAsInputs {QStringLiteral("ADD"), QStringLiteral("MUL"), QStringLiteral("SUB"),
        QStringLiteral("DIV"), QStringLiteral("MOD"), QStringLiteral("AND"), QStringLiteral("OR"), QStringLiteral("XOR"),
        QStringLiteral("NOT"), QStringLiteral("MOVE"), QStringLiteral("ABS"), QStringLiteral("MAX"), QStringLiteral("MIN"),
        QStringLiteral("SHL"), QStringLiteral("SHR"), QStringLiteral("ROL"), QStringLiteral("ROR"), QStringLiteral("EXPT"),
        QStringLiteral("SQRT"), QStringLiteral("LN"), QStringLiteral("LOG"), QStringLiteral("EXP"), QStringLiteral("SIN"),
        QStringLiteral("COS"), QStringLiteral("TAN"), QStringLiteral("ASIN"), QStringLiteral("ACOS"), QStringLiteral("ATAN")};
    if (sameAsInputs.contains(name))
        return firstKnown(inputs, 0);
    return std::nullopt;
}

} // namespace iec::interp::graphical
