// The parser (parserclass.h): ST expressions, and the nesting limits that refuse input nested
// deeper than the compiler's stack allows (limits.h).
#include "interpreter/compiler/parserclass.h"

namespace iec::interp::parsing {

// ============================================================================ expressions

const BinaryOperator *Parser::binaryOperator() const
{
    if (atEnd())
        return nullptr;
    const Token &t = tok();
    if (t.kind != TokenKind::Operator && t.kind != TokenKind::Keyword)
        return nullptr;
    for (const BinaryOperator &op : kBinaryOperators) {
        if (equalsUpper(text(t), op.spelling))
            return &op;
    }
    return nullptr;
}

// Precedence climbing over the table above; every binary operator is left-associative.
Expr Parser::expression(int minPrecedence)
{
    const Nested nested(m_depth);
    if (tooDeep())
        return refuseDeepExpression();
    Expr left = unary();
    for (;;) {
        const BinaryOperator *op = binaryOperator();
        if (!op || op->precedence < minPrecedence)
            return left;
        Expr e;
        e.kind = ExprKind::Binary;
        e.location = here();
        e.text = QString::fromLatin1(op->canonical);
        ++m_pos;
        Expr right = expression(op->precedence + 1);
        e.operands.push_back(std::move(left));
        e.operands.push_back(std::move(right));
        left = std::move(e);
    }
}

Expr Parser::unary()
{
    if (isOp(u"-") || isOp(u"+") || isWord("NOT")) {
        const Nested nested(m_depth);
        if (tooDeep())
            return refuseDeepExpression();
        Expr e;
        e.kind = ExprKind::Unary;
        e.location = here();
        e.text = isWord("NOT") ? QStringLiteral("NOT") : text().toString();
        ++m_pos;
        // A minus directly before a number is part of the literal: -128 is a valid SINT.
        if (e.text == QLatin1String("-") && !atEnd()
            && (tok().kind == TokenKind::IntegerLiteral || tok().kind == TokenKind::RealLiteral)
            && !text().contains(QLatin1Char('#')) && tok().offset == m_tokens[m_pos - 1].offset + 1) {
            Expr literal = primary();
            literal.text.prepend(QLatin1Char('-'));
            literal.location = e.location;
            return literal;
        }
        e.operands.push_back(unary());
        return e;
    }
    return postfix(primary());
}

Expr Parser::primary()
{
    Expr e;
    e.location = here();
    if (atEnd()) {
        unexpected(QCoreApplication::translate("iec::interp::Compiler", "a value"));
        return e;
    }
    const Token &t = tok();
    switch (t.kind) {
    case TokenKind::IntegerLiteral:
    case TokenKind::RealLiteral:
    case TokenKind::TimeLiteral:
    case TokenKind::DateTimeLiteral:
    case TokenKind::StringLiteral:
    case TokenKind::WStringLiteral:
        e.kind = ExprKind::Literal;
        e.literal = t.kind;
        e.text = takeName();
        return e;
    case TokenKind::DirectAddress:
        e.kind = ExprKind::DirectAddress;
        e.text = takeName().toUpper();
        return e;
    default:
        break;
    }
    if (isWord("TRUE") || isWord("FALSE")) {
        e.kind = ExprKind::Literal;
        e.literal = TokenKind::Keyword;
        e.text = takeName().toUpper();
        return e;
    }
    if (acceptOp(u"(")) {
        e = expression();
        expectOp(u")", QStringLiteral("')'"));
        return e;
    }
    // Type names as conversion functions (INT(x)), AND(a, b) and MOD(a, b) as functions, and names.
    const bool operatorFunction = (isWord("AND") || isWord("OR") || isWord("XOR") || isWord("MOD")) && isOp(u"(", 1);
    // A type name alone is an argument of SIZEOF(INT).
    if (isName() || operatorFunction || (t.kind == TokenKind::TypeName && (isOp(u"(", 1) || isOp(u")", 1) || isOp(u",", 1)))) {
        e.kind = ExprKind::Name;
        e.text = takeName();
        return e;
    }
    if (t.kind == TokenKind::Error)
        unexpected(QString());
    else if (isOp(u"=") && m_pos > 0 && text(m_tokens[m_pos - 1]) == u"=")
        error(here(), QCoreApplication::translate("iec::interp::Compiler", "Expected a value, a variable or a function call but found '='."),
              QCoreApplication::translate("iec::interp::Compiler", "IEC 61131-3 compares with a single '='"));
    else
        unexpected(QCoreApplication::translate("iec::interp::Compiler", "a value, a variable or a function call"));
    return e;
}

Expr Parser::postfix(Expr base)
{
    // Each member, bit, index or call nests what is before it one level deeper.
    const int depthBefore = m_depth;
    const auto restoreDepth = qScopeGuard([&] { m_depth = depthBefore; });
    for (;;) {
        if (base.kind == ExprKind::Error)
            return base;
        if (isOp(u".")) {
            if (!deeper())
                return refuseDeepExpression();
            ++m_pos;
            Expr e;
            e.location = base.location;
            if (!atEnd() && tok().kind == TokenKind::IntegerLiteral) {
                e.kind = ExprKind::BitAccess;
                e.text = takeName();
            } else if (!atEnd() && isWordToken(tok())) {
                e.kind = ExprKind::Member;
                e.text = takeName();
            } else {
                unexpected(QCoreApplication::translate("iec::interp::Compiler", "a member name or a bit number after '.'"));
                return base;
            }
            e.operands.push_back(std::move(base));
            base = std::move(e);
        } else if (isOp(u"[")) {
            if (!deeper())
                return refuseDeepExpression();
            ++m_pos;
            Expr e;
            e.kind = ExprKind::Index;
            e.location = base.location;
            e.operands.push_back(std::move(base));
            do
                e.operands.push_back(expression());
            while (acceptOp(u","));
            expectOp(u"]", QStringLiteral("']'"));
            base = std::move(e);
        } else if (isOp(u"^")) {
            if (!deeper())
                return refuseDeepExpression();
            ++m_pos;
            Expr e;
            e.kind = ExprKind::Deref;
            e.location = base.location;
            e.text = base.text + QLatin1Char('^');
            e.operands.push_back(std::move(base));
            base = std::move(e);
        } else if (isOp(u"(") && (base.kind == ExprKind::Name || base.kind == ExprKind::Member || base.kind == ExprKind::Index
                                  || base.kind == ExprKind::Deref)) {
            if (!deeper())
                return refuseDeepExpression();
            ++m_pos;
            Expr e;
            e.kind = ExprKind::Call;
            e.location = base.location;
            e.text = base.text;
            e.operands.push_back(std::move(base));
            e.callArgs = callArguments();
            base = std::move(e);
        } else {
            return base;
        }
    }
}

// After '(' up to and including ')'.
std::vector<CallArg> Parser::callArguments()
{
    std::vector<CallArg> args;
    if (acceptOp(u")"))
        return args;
    do {
        CallArg arg;
        if (isWord("NOT") && isName(1) && isOp(u"=>", 2)) {
            ++m_pos;
            arg.negatedOutput = true;
        }
        if ((isName() || (!atEnd() && isWordToken(tok()))) && (isOp(u":=", 1) || isOp(u"=>", 1))) {
            arg.name = takeName();
            arg.isOutput = isOp(u"=>");
            ++m_pos;
            if (arg.isOutput && isOp(u")")) { // Q => (left open)
                args.push_back(std::move(arg));
                break;
            }
        }
        arg.value = expression();
        args.push_back(std::move(arg));
    } while (acceptOp(u","));
    expectOp(u")", QCoreApplication::translate("iec::interp::Compiler", "')' or ',' in the argument list"));
    return args;
}

// ============================================================================ nesting

// A level beyond limits::kMaxNesting: one message, and the rest of that level is skipped.
Expr Parser::refuseDeepExpression()
{
    Expr e = errorExpr();
    error(here(), QCoreApplication::translate("iec::interp::Compiler", "This expression is nested too deeply (more than %1 levels).").arg(limits::kMaxNesting),
          QCoreApplication::translate("iec::interp::Compiler", "split it into several statements, with variables for the parts"));
    skipRestOfExpression();
    return e;
}

// Up to where the level around the refused one goes on: a ')' or ']' the skipped part did not
// open, a ',' or a word that continues the statement (THEN, DO, OF ...), or the statement's end.
void Parser::skipRestOfExpression()
{
    int open = 0;
    while (!atEnd() && !isOp(u";") && !isBlockWord() && !isStatementKeyword()) {
        if (isOp(u"(") || isOp(u"[")) {
            ++open;
        } else if (isOp(u")") || isOp(u"]")) {
            if (open == 0)
                return;
            --open;
        } else if (open == 0
                   && (isOp(u",") || isOp(u":=") || isOp(u"=>") || isOp(u"..") || isOp(u":") || isWord("THEN")
                       || isWord("DO") || isWord("OF") || isWord("TO") || isWord("BY"))) {
            return;
        }
        ++m_pos;
    }
}

// A block beyond the limit: one message, and the block is skipped up to its END_ word.
Stmt Parser::refuseDeepBlock()
{
    Stmt s;
    s.location = here();
    error(here(), QCoreApplication::translate("iec::interp::Compiler", "These statements are nested too deeply (more than %1 levels).").arg(limits::kMaxNesting),
          QCoreApplication::translate("iec::interp::Compiler", "move the inner blocks into a function, a function block or an action"));
    const auto isBlockEnd = [&] {
        return isWord("END_IF") || isWord("END_CASE") || isWord("END_FOR") || isWord("END_WHILE") || isWord("END_REPEAT");
    };
    int open = 0;
    while (!atEnd()) {
        if (isBlockStart()) {
            ++open;
        } else if (isBlockEnd()) {
            ++m_pos;
            if (--open <= 0) {
                acceptOp(u";");
                break;
            }
            continue;
        } else if (isPouStart() || isVarSectionStart() || isWord("END_PROGRAM") || isWord("END_FUNCTION")
                   || isWord("END_FUNCTION_BLOCK") || isWord("END_ACTION") || isWord("END_TRANSITION") || isWord("END_STEP")) {
            break;
        }
        ++m_pos;
    }
    return s;
}

void Parser::refuseDeepBody(std::initializer_list<std::string_view> ends)
{
    error(here(), QCoreApplication::translate("iec::interp::Compiler", "These statements are nested too deeply (more than %1 levels).").arg(limits::kMaxNesting),
          QCoreApplication::translate("iec::interp::Compiler", "move the inner blocks into a function, a function block or an action"));
    while (!atEnd() && !isEnd(ends))
        ++m_pos;
}

// A type beyond limits::kMaxTypeNesting: one message, and the type is skipped up to the ';' or
// ':=' after it.
void Parser::refuseDeepType()
{
    error(here(), QCoreApplication::translate("iec::interp::Compiler", "This type is nested too deeply (more than %1 levels).").arg(limits::kMaxTypeNesting),
          QCoreApplication::translate("iec::interp::Compiler", "declare the inner types as types of their own in a TYPE block"));
    int open = 0;
    while (!atEnd() && !isWord("END_TYPE") && !isWord("END_VAR") && !isPouStart() && !isVarSectionStart()) {
        if (isOp(u"(") || isOp(u"[") || isWord("STRUCT")) {
            ++open;
        } else if (isOp(u")") || isOp(u"]") || isWord("END_STRUCT")) {
            if (open == 0)
                return;
            --open;
        } else if (open == 0 && (isOp(u";") || isOp(u":="))) {
            return;
        }
        ++m_pos;
    }
}

void Parser::refuseDeepInitializer()
{
    error(here(), QCoreApplication::translate("iec::interp::Compiler", "This initial value is nested too deeply (more than %1 levels).").arg(limits::kMaxTypeNesting));
    skipRestOfExpression();
}

} // namespace iec::interp::parsing
