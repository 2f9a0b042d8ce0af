#include "interpreter/compiler/astdump.h"

#include "interpreter/compiler/parser.h"

namespace iec::interp::ast {

namespace {

QString join(const QStringList &parts)
{
    return parts.join(QLatin1Char(' '));
}

QString dumpArgs(const std::vector<CallArg> &args)
{
    QStringList parts;
    for (const CallArg &a : args) {
        QString text;
        if (a.negatedOutput)
            text += QStringLiteral("NOT ");
        if (!a.name.isEmpty())
            text += a.name + (a.isOutput ? QStringLiteral(" => ") : QStringLiteral(" := "));
        if (a.value.kind != ExprKind::Error || a.name.isEmpty())
            text += dump(a.value);
        parts << text;
    }
    return parts.join(QStringLiteral(", "));
}

QString dumpBlock(const std::vector<Stmt> &body)
{
    return QLatin1Char('{') + dump(body) + QLatin1Char('}');
}

} // namespace

namespace {

// Expressions are written through a list of what is left to write instead of by recursion, so
// that no expression, however deep, can exhaust the stack. A piece is an expression still to
// expand or text to append.
struct Piece {
    const Expr *expr = nullptr;
    QString text;
};
using Pieces = std::vector<Piece>;

Piece text(QString t)
{
    return {nullptr, std::move(t)};
}

Piece operand(const Expr &e)
{
    return {&e, {}};
}

// Writes `root`; `expand` turns one expression into its pieces in the order they are written.
template<class Expand>
QString writeOut(const Expr &root, Expand expand)
{
    QString out;
    Pieces todo {operand(root)};
    while (!todo.empty()) {
        Piece piece = std::move(todo.back());
        todo.pop_back();
        if (!piece.expr) {
            out += piece.text;
            continue;
        }
        Pieces pieces = expand(*piece.expr);
        for (auto it = pieces.rbegin(); it != pieces.rend(); ++it)
            todo.push_back(std::move(*it));
    }
    return out;
}

// Arguments of a call: positional, `name := value`, `name => variable`, `NOT name => variable`;
// `always` writes the value of a named argument also when it is missing (an error).
void addArguments(Pieces &pieces, const std::vector<CallArg> &args, bool always)
{
    for (size_t i = 0; i < args.size(); ++i) {
        const CallArg &a = args[i];
        QString prefix = i > 0 ? QStringLiteral(", ") : QString();
        if (a.negatedOutput)
            prefix += QStringLiteral("NOT ");
        if (!a.name.isEmpty())
            prefix += a.name + (a.isOutput ? QStringLiteral(" => ") : QStringLiteral(" := "));
        pieces.push_back(text(prefix));
        if (always || a.value.kind != ExprKind::Error || a.name.isEmpty())
            pieces.push_back(operand(a.value));
    }
}

void addIndices(Pieces &pieces, const Expr &e)
{
    pieces.push_back(text(QStringLiteral("[")));
    for (size_t i = 1; i < e.operands.size(); ++i) {
        if (i > 1)
            pieces.push_back(text(QStringLiteral(", ")));
        pieces.push_back(operand(e.operands[i]));
    }
    pieces.push_back(text(QStringLiteral("]")));
}

Pieces dumpPieces(const Expr &e)
{
    switch (e.kind) {
    case ExprKind::Literal:
    case ExprKind::Name:
    case ExprKind::DirectAddress:
        return {text(e.text)};
    case ExprKind::Member:
        return {operand(e.operands[0]), text(QLatin1Char('.') + e.text)};
    case ExprKind::BitAccess:
        return {operand(e.operands[0]), text(QStringLiteral(".%") + e.text)};
    case ExprKind::Index: {
        Pieces pieces {operand(e.operands[0])};
        addIndices(pieces, e);
        return pieces;
    }
    case ExprKind::Unary:
        return {text(QLatin1Char('(') + e.text + QLatin1Char(' ')), operand(e.operands[0]), text(QStringLiteral(")"))};
    case ExprKind::Binary:
        return {text(QLatin1Char('(') + e.text + QLatin1Char(' ')), operand(e.operands[0]), text(QStringLiteral(" ")),
                operand(e.operands[1]), text(QStringLiteral(")"))};
    case ExprKind::Call: {
        Pieces pieces {operand(e.operands[0]), text(QStringLiteral("("))};
        addArguments(pieces, e.callArgs, false);
        pieces.push_back(text(QStringLiteral(")")));
        return pieces;
    }
    case ExprKind::Deref:
        return {operand(e.operands[0]), text(QStringLiteral("^"))};
    case ExprKind::Error:
        return {text(QStringLiteral("<error>"))};
    }
    return {};
}

// An operand in parentheses when it would otherwise bind differently: a binary operation below
// one that binds tighter, or on the right of one that binds as tight (operators are
// left-associative, so a - (b - c) keeps its parentheses and (a - b) - c needs none).
Pieces sourceOperand(const Expr &side, int precedence, bool right)
{
    if (side.kind != ExprKind::Binary)
        return {operand(side)};
    const int inner = binaryPrecedence(side.text);
    if (inner > precedence || (inner == precedence && !right))
        return {operand(side)};
    return {text(QStringLiteral("(")), operand(side), text(QStringLiteral(")"))};
}

Pieces sourcePieces(const Expr &e)
{
    switch (e.kind) {
    case ExprKind::Literal:
    case ExprKind::Name:
    case ExprKind::DirectAddress:
    case ExprKind::Error:
        return {text(e.text)};
    case ExprKind::Member:
    case ExprKind::BitAccess:
        return {operand(e.operands[0]), text(QLatin1Char('.') + e.text)};
    case ExprKind::Index: {
        Pieces pieces {operand(e.operands[0])};
        addIndices(pieces, e);
        return pieces;
    }
    case ExprKind::Unary: {
        const Expr &inner = e.operands[0];
        // NOT a, -x; -(a + b), and -(-5) rather than --5.
        const bool parenthesised = inner.kind == ExprKind::Binary || (e.text != QLatin1String("NOT") && (inner.kind == ExprKind::Unary || inner.text.startsWith(QLatin1Char('-'))));
        const QString op = e.text == QLatin1String("NOT") ? QStringLiteral("NOT ") : e.text;
        if (!parenthesised)
            return {text(op), operand(inner)};
        return {text(op + QLatin1Char('(')), operand(inner), text(QStringLiteral(")"))};
    }
    case ExprKind::Binary: {
        const int precedence = binaryPrecedence(e.text);
        Pieces pieces = sourceOperand(e.operands[0], precedence, false);
        pieces.push_back(text(QLatin1Char(' ') + e.text + QLatin1Char(' ')));
        for (Piece &p : sourceOperand(e.operands[1], precedence, true))
            pieces.push_back(std::move(p));
        return pieces;
    }
    case ExprKind::Call: {
        Pieces pieces;
        if (e.operands.empty())
            pieces.push_back(text(e.text));
        else
            pieces.push_back(operand(e.operands[0]));
        pieces.push_back(text(QStringLiteral("(")));
        addArguments(pieces, e.callArgs, true);
        pieces.push_back(text(QStringLiteral(")")));
        return pieces;
    }    case ExprKind::Deref:
        return {operand(e.operands[0]), text(QStringLiteral("^"))};
    }
    return {};
}

} // namespace

QString dump(const Expr &e)
{
    return writeOut(e, dumpPieces);
}

QString sourceText(const Expr &e)
{
    return writeOut(e, sourcePieces);
}

QString dump(const Stmt &s)
{
    switch (s.kind) {
    case StmtKind::Assign:
        return QStringLiteral("(:= ") + dump(s.target) + QLatin1Char(' ') + dump(s.value) + QLatin1Char(')');
    case StmtKind::Call:
        return QStringLiteral("(call ") + dump(s.target) + QLatin1Char(')');
    case StmtKind::If: {
        QStringList parts{QStringLiteral("(if")};
        for (const ConditionalBlock &b : s.branches)
            parts << dump(b.condition) + QLatin1Char(' ') + dumpBlock(b.body);
        if (s.hasElse)
            parts << QStringLiteral("else ") + dumpBlock(s.body);
        return join(parts) + QLatin1Char(')');
    }
    case StmtKind::Case: {
        QStringList parts{QStringLiteral("(case"), dump(s.target)};
        for (const CaseBranch &b : s.cases) {
            QStringList labels;
            for (const CaseLabel &l : b.labels)
                labels << (l.high ? dump(l.low) + QStringLiteral("..") + dump(*l.high) : dump(l.low));
            parts << labels.join(QLatin1Char(',')) + QStringLiteral(": ") + dumpBlock(b.body);
        }
        if (s.hasElse)
            parts << QStringLiteral("else ") + dumpBlock(s.body);
        return join(parts) + QLatin1Char(')');
    }
    case StmtKind::For:
        return QStringLiteral("(for ") + dump(s.target) + QLatin1Char(' ') + dump(s.value) + QLatin1Char(' ')
            + (s.to ? dump(*s.to) : QString()) + (s.by ? QStringLiteral(" by ") + dump(*s.by) : QString())
            + QLatin1Char(' ') + dumpBlock(s.body) + QLatin1Char(')');
    case StmtKind::While:
        return QStringLiteral("(while ") + dump(s.value) + QLatin1Char(' ') + dumpBlock(s.body) + QLatin1Char(')');
    case StmtKind::Repeat:
        return QStringLiteral("(repeat ") + dumpBlock(s.body) + QStringLiteral(" until ") + dump(s.value)
            + QLatin1Char(')');
    case StmtKind::Exit: return QStringLiteral("(exit)");
    case StmtKind::Continue: return QStringLiteral("(continue)");
    case StmtKind::Return: return QStringLiteral("(return)");
    case StmtKind::Empty: return QStringLiteral("(empty)");
    case StmtKind::Jump: return QStringLiteral("(jmp ") + s.target.text + QLatin1Char(')');
    case StmtKind::Label: return QStringLiteral("(label ") + s.target.text + QLatin1Char(')');
    case StmtKind::RefAssign: return QStringLiteral("(ref= ") + dump(s.target) + QLatin1Char(' ') + dump(s.value) + QLatin1Char(')');
    }
    return {};
}

QString dump(const std::vector<Stmt> &statements)
{
    QStringList parts;
    for (const Stmt &s : statements)
        parts << dump(s);
    return join(parts);
}

QString dump(const IlInstruction &ins)
{
    QStringList parts;
    if (!ins.label.isEmpty())
        parts << ins.label + QLatin1Char(':');
    if (!ins.op.isEmpty())
        parts << ins.op + (ins.openParen ? QStringLiteral("(") : QString());
    if (ins.operand)
        parts << dump(*ins.operand);
    if (!ins.callArgs.empty())
        parts << QLatin1Char('[') + dumpArgs(ins.callArgs) + QLatin1Char(']');
    return join(parts);
}

QString dump(const TypeSpec &t)
{
    switch (t.kind) {
    case TypeSpec::Kind::Named:
        return t.name;
    case TypeSpec::Kind::String:
        return (t.wide ? QStringLiteral("WSTRING") : QStringLiteral("STRING"))
            + (t.length ? QLatin1Char('[') + dump(*t.length) + QLatin1Char(']') : QString());
    case TypeSpec::Kind::Array: {
        QStringList ranges;
        for (const Range &r : t.ranges)
            ranges << dump(r.low) + QStringLiteral("..") + dump(r.high);
        return QStringLiteral("ARRAY[") + ranges.join(QLatin1Char(',')) + QStringLiteral("] OF ")
            + dump(t.element.front());
    }
    case TypeSpec::Kind::Subrange:
        return t.name + QLatin1Char('(') + dump(t.ranges[0].low) + QStringLiteral("..") + dump(t.ranges[0].high)
            + QLatin1Char(')');
    case TypeSpec::Kind::Enum: {
        QStringList values;
        for (qsizetype i = 0; i < t.enumValues.size(); ++i) {
            const auto &explicitValue = t.enumExplicit[static_cast<size_t>(i)];
            values << t.enumValues[i] + (explicitValue ? QStringLiteral(":=") + dump(*explicitValue) : QString());
        }
        return QLatin1Char('(') + values.join(QLatin1Char(',')) + QLatin1Char(')') + t.name;
    }
    case TypeSpec::Kind::Pointer:
        return QStringLiteral("POINTER TO ") + dump(t.element.front());
    case TypeSpec::Kind::Reference:
        return QStringLiteral("REFERENCE TO ") + dump(t.element.front());
    case TypeSpec::Kind::Struct: {
        QStringList members;
        for (const VarDecl &m : t.members)
            members << m.name + QStringLiteral(":") + dump(m.type)
                    + (m.init.kind != Initializer::Kind::None ? QStringLiteral(":=") + dump(m.init) : QString());
        return QStringLiteral("STRUCT(") + members.join(QStringLiteral("; ")) + QLatin1Char(')');
    }
    }
    return {};
}

QString dump(const Initializer &init)
{
    switch (init.kind) {
    case Initializer::Kind::None:
        return {};
    case Initializer::Kind::Expression:
        return dump(*init.value);
    case Initializer::Kind::Array: {
        QStringList items;
        for (size_t i = 0; i < init.items.size(); ++i) {
            const auto &repeat = init.repeats[i];
            items << (repeat ? dump(*repeat) + QLatin1Char('(') + dump(init.items[i]) + QLatin1Char(')')
                             : dump(init.items[i]));
        }
        return QLatin1Char('[') + items.join(QLatin1Char(',')) + QLatin1Char(']');
    }
    case Initializer::Kind::Struct: {
        QStringList items;
        for (size_t i = 0; i < init.items.size(); ++i)
            items << init.memberNames[static_cast<qsizetype>(i)] + QStringLiteral(":=") + dump(init.items[i]);
        return QLatin1Char('(') + items.join(QLatin1Char(',')) + QLatin1Char(')');
    }
    }
    return {};
}

QString dump(const VarSection &section)
{
    static const char *const kinds[] = {"VAR", "VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", "VAR_EXTERNAL",
                                        "VAR_GLOBAL", "VAR_TEMP", "VAR_ACCESS", "VAR_CONFIG"};
    QStringList parts{QString::fromLatin1(kinds[static_cast<int>(section.kind)])};
    if (section.constant)
        parts << QStringLiteral("CONSTANT");
    if (section.retain)
        parts << QStringLiteral("RETAIN");
    if (section.nonRetain)
        parts << QStringLiteral("NON_RETAIN");
    for (const VarDecl &v : section.vars) {
        QString text = v.name;
        if (!v.address.isEmpty())
            text += QStringLiteral(" AT ") + v.address;
        text += QStringLiteral(":") + dump(v.type);
        if (v.init.kind != Initializer::Kind::None)
            text += QStringLiteral(":=") + dump(v.init);
        parts << text + QLatin1Char(';');
    }
    return join(parts);
}

QString dump(const SfcChart &chart)
{
    QStringList parts;
    for (const SfcStep &s : chart.steps) {
        QStringList actions;
        for (const SfcActionAssociation &a : s.actions) {
            QStringList fields{a.qualifier};
            if (a.duration)
                fields << dump(*a.duration);
            if (!a.indicator.isEmpty())
                fields << a.indicator;
            actions << a.action + QLatin1Char('(') + fields.join(QLatin1Char(',')) + QLatin1Char(')');
        }
        parts << (s.initial ? QStringLiteral("(initial_step ") : QStringLiteral("(step ")) + s.name
                + (actions.isEmpty() ? QString() : QLatin1Char(' ') + actions.join(QLatin1Char(' '))) + QLatin1Char(')');
    }
    for (const SfcTransition &t : chart.transitions) {
        QString text = QStringLiteral("(transition ");
        if (!t.name.isEmpty())
            text += t.name + QLatin1Char(' ');
        if (t.priority)
            text += QStringLiteral("priority ") + dump(*t.priority) + QLatin1Char(' ');
        text += t.from.join(QLatin1Char(',')) + QStringLiteral(" -> ") + t.to.join(QLatin1Char(','));
        if (t.condition)
            text += QStringLiteral(" := ") + dump(*t.condition);
        if (!t.ilCondition.empty()) {
            QStringList il;
            for (const IlInstruction &i : t.ilCondition)
                il << dump(i);
            text += QStringLiteral(" il{") + il.join(QStringLiteral("; ")) + QLatin1Char('}');
        }
        parts << text + QLatin1Char(')');
    }
    for (const SfcAction &a : chart.actions) {
        QString body;
        if (a.body.language == Language::ST) {
            body = dump(a.body.statements);
        } else {
            QStringList il;
            for (const IlInstruction &i : a.body.il)
                il << dump(i);
            body = QStringLiteral("il{") + il.join(QStringLiteral("; ")) + QLatin1Char('}');
        }
        parts << QStringLiteral("(action ") + a.name + QLatin1Char(' ') + body + QLatin1Char(')');
    }
    return join(parts);
}

} // namespace iec::interp::ast
