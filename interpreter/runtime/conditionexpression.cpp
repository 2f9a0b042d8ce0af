#include "interpreter/runtime/conditionexpression.h"

#include "interpreter/compiler/literals.h"
#include "interpreter/compiler/parser.h"
#include "interpreter/runtime/symbols.h"

#include <QCoreApplication>

#include <cmath>
#include <variant>

namespace iec::interp {

namespace {

// A value while evaluating: Boolean, a number (durations and dates in nanoseconds), or text
// (strings, enumeration values).
using Value = std::variant<bool, double, QString>;

struct Failed {
    QString message;
};

// The value an IEC literal stands for, as formatValue writes them and a user types them.
Value valueOfLiteral(const QString &text)
{
    const QString upper = text.toUpper();
    if (upper == QLatin1String("TRUE") || upper == QLatin1String("BOOL#TRUE") || upper == QLatin1String("BOOL#1"))
        return true;
    if (upper == QLatin1String("FALSE") || upper == QLatin1String("BOOL#FALSE") || upper == QLatin1String("BOOL#0"))
        return false;
    const LiteralParts parts = splitTypedLiteral(text);
    const QStringView body = parts.body;
    std::optional<std::int64_t> nanoseconds;
    switch (literalFamilyOfPrefix(parts.typePrefix)) {
    case LiteralFamily::Duration: nanoseconds = decodeDuration(body); break;
    case LiteralFamily::Date: nanoseconds = decodeDate(body); break;
    case LiteralFamily::TimeOfDay: nanoseconds = decodeTimeOfDay(body); break;
    case LiteralFamily::DateAndTime: nanoseconds = decodeDateAndTime(body); break;
    default: break;
    }
    if (nanoseconds)
        return double(*nanoseconds);
    if (const auto integer = decodeInteger(body))
        return integer->negative ? -double(integer->magnitude) : double(integer->magnitude);
    if (const auto real = decodeReal(body))
        return *real;
    if (const auto string = decodeString(body))
        return *string;
    return text; // an enumeration value (Color#Red, Red)
}

class Evaluator
{
public:
    explicit Evaluator(const ConditionScope &scope)
        : m_scope(scope)
    {
    }

    Value eval(const ast::Expr &e, int depth = 0)
    {
        if (depth > 200)
            throw Failed{QCoreApplication::translate("iec::interp::Condition", "The condition is nested too deeply.")};
        switch (e.kind) {
        case ast::ExprKind::Literal: return valueOfLiteral(e.text);
        case ast::ExprKind::Name:
        case ast::ExprKind::Member:
        case ast::ExprKind::Index:
        case ast::ExprKind::BitAccess:
        case ast::ExprKind::DirectAddress: return read(path(e, depth));
        case ast::ExprKind::Unary: return unary(e.text.toUpper(), eval(e.operands.at(0), depth + 1));
        case ast::ExprKind::Binary: return binary(e.text.toUpper(), eval(e.operands.at(0), depth + 1), eval(e.operands.at(1), depth + 1));
        default: throw Failed{QCoreApplication::translate("iec::interp::Condition", "A condition can only read variables and compare them; it cannot call anything.")};
        }
    }

private:
    QString path(const ast::Expr &e, int depth)
    {
        switch (e.kind) {
        case ast::ExprKind::Name:
        case ast::ExprKind::DirectAddress: return e.text;
        case ast::ExprKind::Member:
        case ast::ExprKind::BitAccess: return path(e.operands.at(0), depth + 1) + QLatin1Char('.') + e.text;
        case ast::ExprKind::Index: {
            QStringList indices;
            for (size_t i = 1; i < e.operands.size(); ++i)
                indices << QString::number(std::llround(number(eval(e.operands[i], depth + 1))));
            return path(e.operands.at(0), depth + 1) + QLatin1Char('[') + indices.join(QLatin1Char(',')) + QLatin1Char(']');
        }
        default: throw Failed{QCoreApplication::translate("iec::interp::Condition", "A condition can only read variables and compare them; it cannot call anything.")};
        }
    }

    Value read(const QString &name)
    {
        std::optional<VariableRef> ref;
        if (!m_scope.instance.isEmpty() && !name.startsWith(QLatin1Char('%')))
            ref = resolveSymbol(m_scope.module, m_scope.instance + QLatin1Char('.') + name);
        if (!ref)
            ref = resolveSymbol(m_scope.module, name);
        if (!ref)
            throw Failed{QCoreApplication::translate("iec::interp::Condition", "There is no variable called %1 here.").arg(name)};
        const int area = ref->imageArea == 'I' ? 0 : ref->imageArea == 'Q' ? 1 : 2;
        return valueOfLiteral(formatValue(*ref, m_scope.memory, m_scope.images[size_t(area)]));
    }

    static double number(const Value &v)
    {
        if (const double *d = std::get_if<double>(&v))
            return *d;
        if (const bool *b = std::get_if<bool>(&v))
            return *b ? 1 : 0;
        throw Failed{QCoreApplication::translate("iec::interp::Condition", "Text cannot be calculated with.")};
    }
    static bool boolean(const Value &v)
    {
        if (const bool *b = std::get_if<bool>(&v))
            return *b;
        throw Failed{QCoreApplication::translate("iec::interp::Condition", "AND, OR, XOR and NOT need TRUE or FALSE here.")};
    }

    static Value unary(const QString &op, const Value &v)
    {
        if (op == QLatin1String("NOT")) {
            if (std::holds_alternative<double>(v))
                return double(~std::llround(number(v)));
            return !boolean(v);
        }
        if (op == QLatin1String("-"))
            return -number(v);
        return number(v);
    }

    static Value binary(const QString &op, const Value &a, const Value &b)
    {
        if (op == QLatin1String("AND") || op == QLatin1String("&") || op == QLatin1String("OR") || op == QLatin1String("XOR")) {
            if (std::holds_alternative<double>(a) && std::holds_alternative<double>(b)) {
                const long long x = std::llround(number(a)), y = std::llround(number(b));
                return double(op == QLatin1String("OR") ? x | y : op == QLatin1String("XOR") ? x ^ y : x & y);
            }
            const bool x = boolean(a), y = boolean(b);
            return op == QLatin1String("OR") ? x || y : op == QLatin1String("XOR") ? x != y : x && y;
        }
        if (op == QLatin1String("=") || op == QLatin1String("<>")) {
            bool equal = false;
            if (a.index() == b.index())
                equal = a == b;
            else if (!std::holds_alternative<QString>(a) && !std::holds_alternative<QString>(b))
                equal = number(a) == number(b);
            return op == QLatin1String("=") ? equal : !equal;
        }
        if (std::holds_alternative<QString>(a) && std::holds_alternative<QString>(b)) {
            const int c = std::get<QString>(a).compare(std::get<QString>(b));
            if (op == QLatin1String("<")) return c < 0;
            if (op == QLatin1String("<=")) return c <= 0;
            if (op == QLatin1String(">")) return c > 0;
            if (op == QLatin1String(">=")) return c >= 0;
        }
        const double x = number(a), y = number(b);
        if (op == QLatin1String("<")) return x < y;
        if (op == QLatin1String("<=")) return x <= y;
        if (op == QLatin1String(">")) return x > y;
        if (op == QLatin1String(">=")) return x >= y;
        if (op == QLatin1String("+")) return x + y;
        if (op == QLatin1String("-")) return x - y;
        if (op == QLatin1String("*")) return x * y;
        if (op == QLatin1String("**")) return std::pow(x, y);
        if (op == QLatin1String("/") || op == QLatin1String("MOD")) {
            if (y == 0)
                throw Failed{QCoreApplication::translate("iec::interp::Condition", "The condition divides by zero.")};
            return op == QLatin1String("/") ? x / y : std::fmod(x, y);
        }
        throw Failed{QCoreApplication::translate("iec::interp::Condition", "The operator %1 cannot be used in a condition.").arg(op)};
    }

    const ConditionScope &m_scope;
};

// The expression of a condition, parsed as the right side of an assignment.
std::optional<ast::Expr> parseCondition(const QString &text, QString *error)
{
    Diagnostics diagnostics;
    std::vector<ast::Stmt> statements = parseStBody(QStringLiteral("__condition := (%1);").arg(text), QString(), diagnostics);
    if (diagnostics.hasErrors() || statements.size() != 1 || statements[0].kind != ast::StmtKind::Assign) {
        if (error)
            *error = QCoreApplication::translate("iec::interp::Condition", "This is not an expression: %1").arg(text);
        return std::nullopt;
    }
    return std::move(statements[0].value);
}

} // namespace

ConditionResult evaluateCondition(const QString &text, const ConditionScope &scope)
{
    ConditionResult result;
    const std::optional<ast::Expr> expr = parseCondition(text, &result.error);
    if (!expr)
        return result;
    try {
        const Value value = Evaluator(scope).eval(*expr);
        if (const bool *b = std::get_if<bool>(&value))
            result.value = *b;
        else
            result.error = QCoreApplication::translate("iec::interp::Condition", "The condition must be TRUE or FALSE, not a number or a text.");
    } catch (const Failed &failed) {
        result.error = failed.message;
    }
    return result;
}

QString conditionSyntaxError(const QString &text)
{
    QString error;
    parseCondition(text, &error);
    return error;
}

} // namespace iec::interp
