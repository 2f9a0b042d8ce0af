#include "interpreter/graphical/astbuild.h"

#include "interpreter/compiler/parser.h"
#include "model/element.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <array>
#include <limits>

namespace iec::interp::graphical {

SourceLocation elementLocation(quint64 localId)
{
    SourceLocation at;
    if (localId <= quint64(std::numeric_limits<qint64>::max()))
        at.localId = qint64(localId);
    return at;
}

QString elementKindName(const model::Element &element)
{
    // Same order as the Element variant (model::elementTagName).
    static constexpr std::array<const char *, std::variant_size_v<model::Element>> kNames {
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "comment"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "unreadable element"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "connector"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "continuation"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "action block"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "vendor element"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "block"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "input variable"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "output variable"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "in-out variable"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "label"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "jump"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "return"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "left power rail"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "right power rail"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "coil"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "contact"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "step"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "macro step"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "jump"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "transition"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "selection divergence"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "selection convergence"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "simultaneous divergence"),
        QT_TRANSLATE_NOOP("iec::interp::Compiler", "simultaneous convergence"),
    };
    return QCoreApplication::translate("iec::interp::Compiler", kNames[element.index()]);
}

ast::Expr nameExpr(const QString &name, SourceLocation at)
{
    ast::Expr e;
    e.kind = ast::ExprKind::Name;
    e.location = at;
    e.text = name;
    return e;
}

ast::Expr boolLiteral(bool value, SourceLocation at)
{
    ast::Expr e;
    e.kind = ast::ExprKind::Literal;
    e.literal = TokenKind::Keyword;
    e.location = at;
    e.text = value ? QStringLiteral("TRUE") : QStringLiteral("FALSE");
    return e;
}

ast::Expr intLiteral(int value, SourceLocation at)
{
    ast::Expr e;
    e.kind = ast::ExprKind::Literal;
    e.literal = TokenKind::IntegerLiteral;
    e.location = at;
    e.text = QString::number(value);
    return e;
}

ast::Expr notExpr(ast::Expr operand)
{
    if (operand.kind == ast::ExprKind::Literal && operand.literal == TokenKind::Keyword)
        return boolLiteral(operand.text != QLatin1String("TRUE"), operand.location);
    ast::Expr e;
    e.kind = ast::ExprKind::Unary;
    e.location = operand.location;
    e.text = QStringLiteral("NOT");
    e.operands.push_back(std::move(operand));
    return e;
}

ast::Expr binaryExpr(const QString &op, ast::Expr left, ast::Expr right)
{
    ast::Expr e;
    e.kind = ast::ExprKind::Binary;
    e.location = left.location;
    e.text = op;
    e.operands.push_back(std::move(left));
    e.operands.push_back(std::move(right));
    return e;
}

ast::Expr memberExpr(ast::Expr base, const QString &member)
{
    ast::Expr e;
    e.kind = ast::ExprKind::Member;
    e.location = base.location;
    e.text = member;
    e.operands.push_back(std::move(base));
    return e;
}

ast::Expr callExpr(const QString &name, std::vector<ast::CallArg> args, SourceLocation at)
{
    ast::Expr e;
    e.kind = ast::ExprKind::Call;
    e.location = at;
    e.text = name;
    e.operands.push_back(nameExpr(name, at));
    e.callArgs = std::move(args);
    return e;
}

ast::Stmt assignStmt(ast::Expr target, ast::Expr value)
{
    ast::Stmt s;
    s.kind = ast::StmtKind::Assign;
    s.location = target.location;
    s.target = std::move(target);
    s.value = std::move(value);
    return s;
}

ast::Stmt callStmt(ast::Expr call)
{
    ast::Stmt s;
    s.kind = ast::StmtKind::Call;
    s.location = call.location;
    s.target = std::move(call);
    return s;
}

ast::Stmt ifStmt(ast::Expr condition, std::vector<ast::Stmt> body)
{
    ast::Stmt s;
    s.kind = ast::StmtKind::If;
    s.location = condition.location;
    ast::ConditionalBlock branch;
    branch.location = condition.location;
    branch.condition = std::move(condition);
    branch.body = std::move(body);
    s.branches.push_back(std::move(branch));
    return s;
}

ast::Stmt simpleStmt(ast::StmtKind kind, SourceLocation at)
{
    ast::Stmt s;
    s.kind = kind;
    s.location = at;
    return s;
}

bool isBoolLiteral(const ast::Expr &expr, bool value)
{
    return expr.kind == ast::ExprKind::Literal && expr.literal == TokenKind::Keyword
        && expr.text.compare(value ? QLatin1String("TRUE") : QLatin1String("FALSE"), Qt::CaseInsensitive) == 0;
}

bool isSimple(const ast::Expr &expr)
{
    switch (expr.kind) {
    case ast::ExprKind::Name:
    case ast::ExprKind::Literal:
    case ast::ExprKind::DirectAddress:
        return true;
    case ast::ExprKind::Member:
    case ast::ExprKind::BitAccess:
        return isSimple(expr.operands.front());
    default:
        return false;
    }
}

void relocate(ast::Expr &expr, SourceLocation at)
{
    // With a list, not by recursion: the text of an element may be a sum of any length.
    std::vector<ast::Expr *> pending {&expr};
    while (!pending.empty()) {
        ast::Expr *e = pending.back();
        pending.pop_back();
        e->location = at;
        for (ast::Expr &operand : e->operands)
            pending.push_back(&operand);
        for (ast::CallArg &arg : e->callArgs)
            pending.push_back(&arg.value);
    }
}

void setPlace(std::vector<ast::Stmt> &statements, qint64 place)
{
    std::vector<std::vector<ast::Stmt> *> pending {&statements};
    while (!pending.empty()) {
        std::vector<ast::Stmt> *list = pending.back();
        pending.pop_back();
        for (ast::Stmt &s : *list) {
            s.location.place = place;
            s.value.location.place = place; // REPEAT marks its condition's line
            pending.push_back(&s.body);
            for (ast::ConditionalBlock &branch : s.branches) {
                branch.location.place = place;
                pending.push_back(&branch.body);
            }
            for (ast::CaseBranch &branch : s.cases)
                pending.push_back(&branch.body);
        }
    }
}

void relocate(std::vector<ast::Stmt> &statements, SourceLocation at)
{
    for (ast::Stmt &s : statements) {
        s.location = at;
        relocate(s.target, at);
        relocate(s.value, at);
        if (s.to)
            relocate(*s.to, at);
        if (s.by)
            relocate(*s.by, at);
        for (ast::ConditionalBlock &branch : s.branches) {
            branch.location = at;
            relocate(branch.condition, at);
            relocate(branch.body, at);
        }
        for (ast::CaseBranch &branch : s.cases)
            relocate(branch.body, at);
        relocate(s.body, at);
    }
}

std::optional<ast::Expr> parseExpression(const QString &text, const QString &owner, SourceLocation at,
    Diagnostics &diagnostics)
{
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty() || trimmed == QLatin1String("???")) {
        diagnostics.error(owner, at, QCoreApplication::translate("iec::interp::Compiler", "An element has no variable or value written in it."),
            QCoreApplication::translate("iec::interp::Compiler", "enter a variable name or a constant"));
        return std::nullopt;
    }
    // Most contacts, coils and variables are plain names: no need for the parser.
    static const QRegularExpression identifier(QStringLiteral("^[A-Za-z_][A-Za-z0-9_]*$"));
    static const QStringList words {QStringLiteral("TRUE"), QStringLiteral("FALSE"), QStringLiteral("NOT"),
        QStringLiteral("AND"), QStringLiteral("OR"), QStringLiteral("XOR"), QStringLiteral("MOD")};
    if (identifier.match(trimmed).hasMatch() && !words.contains(trimmed.toUpper()))
        return nameExpr(trimmed, at);
    Diagnostics local;
    const QString statement = QStringLiteral("__graphical := ") + trimmed + QStringLiteral("\n;");
    std::vector<ast::Stmt> parsed = parseStBody(statement, owner, local);
    const bool single = parsed.size() == 1 && parsed.front().kind == ast::StmtKind::Assign
        && parsed.front().target.kind == ast::ExprKind::Name;
    if (local.hasErrors() || !single) {
        diagnostics.error(owner, at, QCoreApplication::translate("iec::interp::Compiler", "'%1' is not a variable or an expression.").arg(trimmed),
            QCoreApplication::translate("iec::interp::Compiler", "write a name such as Motor, Tank.Level or %QX0.1, or a constant such as T#5s"));
        return std::nullopt;
    }
    ast::Expr value = std::move(parsed.front().value);
    relocate(value, at);
    return value;
}

} // namespace iec::interp::graphical
