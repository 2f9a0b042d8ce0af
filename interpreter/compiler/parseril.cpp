// The parser (parserclass.h): IL instruction lists.
#include "interpreter/compiler/parserclass.h"

namespace iec::interp::parsing {

// ============================================================================ IL

std::vector<IlInstruction> Parser::ilInstructions(std::initializer_list<std::string_view> ends)
{
    std::vector<IlInstruction> list;
    const auto atBodyEnd = [&] {
        return isEnd(ends) || (ends.size() == 0 && atEnd())
            || (!atEnd() && tok().kind == TokenKind::Keyword && text().startsWith(QLatin1String("END_"), Qt::CaseInsensitive))
            || isWord("ACTION") || isPouStart() || startsMember();
    };
    while (!atEnd() && !atBodyEnd()) {
        IlInstruction ins;
        ins.location = here();
        const size_t before = m_pos;
        if (isName() && isOp(u":", 1)) {
            const Token labelToken = tok();
            ins.label = takeName();
            ++m_pos;
            // A label may stand on its own line.
            if (atEnd() || atBodyEnd() || lineOf(tok()) != lineOf(labelToken)) {
                list.push_back(std::move(ins));
                continue;
            }
        }
        const Token opToken = tok();
        // An IL line never ends with ';' and an IL operator is never followed by ':=', '[' or '.'.
        size_t lineEnd = m_pos;
        while (lineEnd + 1 < m_tokens.size() && lineOf(m_tokens[lineEnd + 1]) == lineOf(opToken))
            ++lineEnd;
        const bool endsWithSemicolon = text(m_tokens[lineEnd]) == u";";
        if (isWord("IF") || isWord("FOR") || isWord("WHILE") || isWord("CASE") || isWord("REPEAT") || endsWithSemicolon
            || (isName() && (isOp(u":=", 1) || isOp(u"[", 1) || isOp(u".", 1)))) {
            // ST inside an IL body: one message, and the rest of the body is not read as IL.
            error(here(), QCoreApplication::translate("iec::interp::Compiler", "This is ST, but the body is written in IL; a body uses one language."),
                  QCoreApplication::translate("iec::interp::Compiler", "write it in IL (LD, ST, JMPC ...) or write the whole body in ST"));
            while (!atEnd() && !isEnd(ends) && !isPouStart() && !isWord("ACTION"))
                ++m_pos;
            m_recovering = false;
            break;
        }
        if (isOp(u")")) {
            ins.op = QStringLiteral(")");
            ++m_pos;
        } else if (isWordToken(opToken)) {
            ins.op = takeName().toUpper();
        } else {
            unexpected(QCoreApplication::translate("iec::interp::Compiler", "an IL operator such as LD, ST, ADD or JMP"));
            while (!atEnd() && lineOf(tok()) == lineOf(opToken))
                ++m_pos;
            m_recovering = false;
            if (m_pos == before)
                ++m_pos;
            continue;
        }
        const bool formalCall = opToken.kind == TokenKind::Identifier && ilOperandFollows(opToken) && isOp(u"(")
            && (isOp(u")", 1) || ((isName(1) || (!atEnd(1) && isWordToken(tok(1)))) && (isOp(u":=", 2) || isOp(u"=>", 2))));
        if (formalCall) {
            // LIMIT( MN := 1, IN := x, MX := 5 ): a function with a formal argument list, which may
            // span lines; the current result is not one of its arguments.
            ++m_pos;
            ins.callArgs = callArguments();
            m_recovering = false;
            list.push_back(std::move(ins));
            continue;
        }
        if (ilOperandFollows(opToken) && acceptOp(u"(")) {
            ins.openParen = true;
        }
        // An operand: a variable, a literal (also a negative one: ADD -1, SEL G, -5, 3) or a call.
        const auto ilOperand = [&] {
            if (isOp(u"-") && !atEnd(1) && (tok(1).kind == TokenKind::IntegerLiteral || tok(1).kind == TokenKind::RealLiteral)) {
                ++m_pos;
                Expr negative = primary();
                negative.text.prepend(QLatin1Char('-'));
                return negative;
            }
            return postfix(primary());
        };
        if (ilOperandFollows(opToken)) {
            Expr operand = ilOperand();
            if (operand.kind == ExprKind::Call) {
                ins.callArgs = std::move(operand.callArgs);
                Expr callee = std::move(operand.operands.front());
                operand = std::move(callee);
            }
            ins.operand = std::move(operand);
            // Further operands of a function call: SEL G, IN0, IN1 -> positional arguments.
            while (ilOperandFollows(opToken) && acceptOp(u",")) {
                CallArg extra;
                extra.value = ilOperand();
                ins.callArgs.push_back(std::move(extra));
            }
        }
        if (ilOperandFollows(opToken) && !m_recovering) {
            error(here(), QCoreApplication::translate("iec::interp::Compiler", "An IL instruction takes one operand; %1 is left over.").arg(describeCurrent()),
                  QCoreApplication::translate("iec::interp::Compiler", "put each instruction on its own line"));
        }
        while (!atEnd() && lineOf(tok()) == lineOf(opToken))
            ++m_pos;
        m_recovering = false;
        list.push_back(std::move(ins));
    }
    return list;
}

} // namespace iec::interp::parsing
