// The parser (parserclass.h): textual SFC (steps, transitions, actions) and ST statements.
#include "interpreter/compiler/parserclass.h"

namespace iec::interp::parsing {

// ============================================================================ SFC

void Parser::sfc(SfcChart &chart, std::initializer_list<std::string_view> ends)
{
    while (!isEnd(ends)) {
        if (acceptWord("INITIAL_STEP")) {
            sfcStep(chart, true);
        } else if (acceptWord("STEP")) {
            sfcStep(chart, false);
        } else if (isWord("TRANSITION")) {
            sfcTransition(chart);
        } else if (isWord("ACTION")) {
            const Nested nested(m_blockDepth); // a chart in an action of a chart ...
            if (blockTooDeep()) {
                refuseDeepBody(ends);
                break;
            }
            SfcAction action;
            action.location = here();
            ++m_pos;
            action.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the action"));
            acceptOp(u":");
            action.body = body({"END_ACTION"});
            expectWord("END_ACTION");
            chart.actions.push_back(std::move(action));
        } else {
            unexpected(QCoreApplication::translate("iec::interp::Compiler", "INITIAL_STEP, STEP, TRANSITION or ACTION"));
            ++m_pos;
            while (!isEnd(ends) && !isWord("STEP") && !isWord("INITIAL_STEP") && !isWord("TRANSITION") && !isWord("ACTION"))
                ++m_pos;
            m_recovering = false;
        }
    }
}

void Parser::sfcStep(SfcChart &chart, bool initial)
{
    SfcStep step;
    step.location = here();
    step.initial = initial;
    step.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the step"));
    expectOp(u":", QCoreApplication::translate("iec::interp::Compiler", "':' after the step name"));
    while (!atEnd() && !isWord("END_STEP") && !isBlockWord() && !isWord("STEP") && !isWord("TRANSITION")) {
        SfcActionAssociation assoc;
        assoc.location = here();
        assoc.action = expectName(QCoreApplication::translate("iec::interp::Compiler", "an action name"));
        if (acceptOp(u"(")) {
            if (!isOp(u")") && !isOp(u",")) {
                if (!atEnd() && (isWordToken(tok())))
                    assoc.qualifier = takeName().toUpper();
                else
                    unexpected(QCoreApplication::translate("iec::interp::Compiler", "an action qualifier such as N, S, R, L or D"));
            }
            while (acceptOp(u",")) {
                if (!atEnd() && tok().kind == TokenKind::TimeLiteral)
                    assoc.duration = expression();
                else if (isName())
                    assoc.indicator = takeName();
                else
                    unexpected(QCoreApplication::translate("iec::interp::Compiler", "a duration or an indicator variable"));
            }
            expectOp(u")", QStringLiteral("')'"));
        }
        if (!acceptOp(u";"))
            error(afterPrevious(), QCoreApplication::translate("iec::interp::Compiler", "Missing ';' after the action association."));
        if (m_recovering)
            synchronize(false);
        step.actions.push_back(std::move(assoc));
    }
    if (!acceptWord("END_STEP"))
        error(step.location, QCoreApplication::translate("iec::interp::Compiler", "Step %1 has no END_STEP.").arg(step.name));
    m_recovering = false;
    chart.steps.push_back(std::move(step));
}

QStringList Parser::stepList()
{
    QStringList steps;
    if (acceptOp(u"(")) {
        do
            steps << expectName(QCoreApplication::translate("iec::interp::Compiler", "a step name"));
        while (acceptOp(u","));
        expectOp(u")", QCoreApplication::translate("iec::interp::Compiler", "')' after the step names"));
    } else {
        steps << expectName(QCoreApplication::translate("iec::interp::Compiler", "a step name"));
    }
    return steps;
}

void Parser::sfcTransition(SfcChart &chart)
{
    SfcTransition t;
    t.location = here();
    ++m_pos;
    if (isName() && !isWord("FROM"))
        t.name = takeName();
    if (acceptOp(u"(")) {
        expectWord("PRIORITY");
        expectOp(u":=", QStringLiteral("':='"));
        t.priority = expression();
        expectOp(u")", QStringLiteral("')'"));
    }
    expectWord("FROM");
    t.from = stepList();
    expectWord("TO");
    t.to = stepList();
    if (acceptOp(u":=")) {
        t.condition = expression();
        endStatement();
    } else if (acceptOp(u":")) {
        t.ilCondition = ilInstructions({"END_TRANSITION"});
    } else {
        unexpected(QCoreApplication::translate("iec::interp::Compiler", "':=' and the transition condition"));
    }
    if (!acceptWord("END_TRANSITION")) {
        error(t.location, QCoreApplication::translate("iec::interp::Compiler", "This TRANSITION has no END_TRANSITION."));
        while (!atEnd() && !isBlockWord() && !isWord("STEP") && !isWord("TRANSITION"))
            ++m_pos;
    }
    m_recovering = false;
    chart.transitions.push_back(std::move(t));
}

// ============================================================================ ST statements

bool Parser::isStatementListEnd() const
{
    return atEnd() || isBlockWord() || startsSfcElement() || isMisspelledEnd() || startsMember();
}

std::vector<Stmt> Parser::statements()
{
    std::vector<Stmt> list;
    while (!isStatementListEnd()) {
        const size_t before = m_pos;
        list.push_back(statement());
        // A statement that reached its ';' after an error needs no skipping: the next one is
        // read afresh, so that a second mistake on the next line is reported too.
        if (m_recovering && m_pos > before && text(m_tokens[m_pos - 1]) == u";")
            m_recovering = false;
        if (m_recovering)
            synchronize(true);
        if (m_pos == before) // never loop without progress
            ++m_pos;
    }
    return list;
}

void Parser::endStatement()
{
    if (acceptOp(u";"))
        return;
    if (isOp(u")")) {
        error(here(), QCoreApplication::translate("iec::interp::Compiler", "This ')' has no matching '('."));
        return;
    }
    error(afterPrevious(), QCoreApplication::translate("iec::interp::Compiler", "Missing ';' at the end of the statement."),
          QCoreApplication::translate("iec::interp::Compiler", "every ST statement ends with ';'"));
    // Carry on with the next statement when it clearly starts here, so one missing ';' gives
    // one message and the rest of the body is still checked.
    if (isStatementListEnd() || isStatementKeyword() || isName())
        m_recovering = false;
}

Stmt Parser::statement()
{
    Stmt s;
    s.location = here();
    if (acceptOp(u";"))
        return s;
    const Nested nested(m_blockDepth);
    if (isBlockStart() && blockTooDeep())
        return refuseDeepBlock();
    if (isWord("IF"))
        return ifStatement();
    if (isWord("CASE"))
        return caseStatement();
    if (isWord("FOR"))
        return forStatement();
    if (isWord("WHILE"))
        return whileStatement();
    if (isWord("REPEAT"))
        return repeatStatement();
    if (acceptWord("EXIT"))
        s.kind = StmtKind::Exit;
    else if (acceptWord("CONTINUE"))
        s.kind = StmtKind::Continue;
    else if (acceptWord("RETURN"))
        s.kind = StmtKind::Return;
    else if (isWord("JMP") && isName(1)) { // CODESYS: JMP label; in ST
        ++m_pos;
        s.kind = StmtKind::Jump;
        s.target.kind = ExprKind::Name;
        s.target.location = here();
        s.target.text = takeName();
    } else if (isName() && isOp(u":", 1)) { // label: in ST, before the statement it marks
        s.kind = StmtKind::Label;
        s.target.kind = ExprKind::Name;
        s.target.location = here();
        s.target.text = takeName();
        ++m_pos;
        return s;
    }
    if (s.kind != StmtKind::Empty) {
        endStatement();
        return s;
    }
    if (!isName() && !(!atEnd() && tok().kind == TokenKind::DirectAddress)) {
        unexpected(QCoreApplication::translate("iec::interp::Compiler", "a statement"));
        return s;
    }
    Expr target = postfix(primary());
    if (acceptOp(u":=")) {
        s.kind = StmtKind::Assign;
        s.target = std::move(target);
        s.value = expression();
    } else if (isWord("REF") && isOp(u"=", 1)) { // CODESYS: r REF= x;
        m_pos += 2;
        s.kind = StmtKind::RefAssign;
        s.target = std::move(target);
        s.value = expression();
    } else if (target.kind == ExprKind::Call) {
        s.kind = StmtKind::Call;
        s.target = std::move(target);
    } else if (isOp(u"=")) {
        ++m_pos;
        error(s.location, QCoreApplication::translate("iec::interp::Compiler", "'=' compares two values; to assign a value write ':='."),
              QCoreApplication::translate("iec::interp::Compiler", "write %1 := ...;").arg(target.text));
        s.kind = StmtKind::Assign;
        s.target = std::move(target);
        s.value = expression();
        m_recovering = false;
        endStatement();
        return s;
    } else {
        if (!m_recovering) {
            const QString keyword = target.kind == ExprKind::Name ? nearKeyword(target.text) : QString();
            error(here(), QCoreApplication::translate("iec::interp::Compiler", "Expected ':=' or a call after '%1'.").arg(target.text),
                  keyword.isEmpty() ? QString() : QCoreApplication::translate("iec::interp::Compiler", "did you mean %1?").arg(keyword));
        }
        if (target.kind == ExprKind::Name)
            recoverMisspelledBlock();
        return s;
    }
    endStatement();
    return s;
}

void Parser::closeBlock(std::string_view endWord, const char *blockName, SourceLocation opened, const QString &hint)
{
    if (acceptWord(endWord)) {
        acceptOp(u";");
        return;
    }
    const QString end = QString::fromLatin1(endWord.data(), static_cast<qsizetype>(endWord.size()));
    if (isMisspelledEnd()) {
        // END_FI: one message where the typo is, and the block ends there.
        error(here(), QCoreApplication::translate("iec::interp::Compiler", "Expected %1 but found '%2'.").arg(end, text().toString()),
              QCoreApplication::translate("iec::interp::Compiler", "the %1 of line %2 ends with %3").arg(QLatin1String(blockName)).arg(opened.line).arg(end));
        ++m_pos;
        acceptOp(u";");
        m_recovering = false;
        return;
    }
    // Reported where the block starts: that is where the student has to look.
    error(opened, QCoreApplication::translate("iec::interp::Compiler", "This %1 has no matching %2.").arg(QLatin1String(blockName), end),
          hint.isEmpty() ? QCoreApplication::translate("iec::interp::Compiler", "add %1; after the last statement that belongs to it").arg(end) : hint);
    m_recovering = false;
}

void Parser::recoverMisspelledBlock()
{
    const Nested nested(m_blockDepth);
    if (blockTooDeep())
        return; // the misspelled word is reported; what follows is skipped
    // "IFF a > 1 THEN ... END_IF": after the one message about the first word, the rest is read
    // as the block it looks like, so that its body is still checked and its END_ word matched.
    size_t k = m_pos;
    while (k < m_tokens.size()) {
        const QStringView w = text(m_tokens[k]);
        if (w == u";" || (m_tokens[k].kind == TokenKind::Keyword && w.startsWith(QLatin1String("END_"), Qt::CaseInsensitive)))
            return;
        const bool then = equalsUpper(w, "THEN"), doWord = equalsUpper(w, "DO");
        if (m_tokens[k].kind == TokenKind::Keyword && (then || doWord)) {
            m_pos = k + 1;
            m_recovering = false;
            statements();
            while (then && (isWord("ELSIF") || isWord("ELSE"))) {
                const bool elsif = isWord("ELSIF");
                ++m_pos;
                if (elsif) {
                    expression();
                    if (!acceptWord("THEN"))
                        unexpected(QStringLiteral("THEN"));
                }
                if (m_recovering)
                    synchronize(true);
                statements();
            }
            if (then ? acceptWord("END_IF") : (acceptWord("END_WHILE") || acceptWord("END_FOR")))
                acceptOp(u";");
            m_recovering = false;
            return;
        }
        ++k;
    }
}

Stmt Parser::ifStatement()
{
    Stmt s;
    s.kind = StmtKind::If;
    s.location = here();
    const SourceLocation opened = s.location;
    do {
        ConditionalBlock branch;
        branch.location = here();
        ++m_pos; // IF / ELSIF
        branch.condition = expression();
        if (!acceptWord("THEN")) {
            if (isOp(u":="))
                error(here(), QCoreApplication::translate("iec::interp::Compiler", "A condition compares with '=', not ':='."));
            else
                unexpected(QStringLiteral("THEN"));
            synchronize(true);
        }
        branch.body = statements();
        s.branches.push_back(std::move(branch));
    } while (isWord("ELSIF"));
    bool elseIf = false;
    if (acceptWord("ELSE")) {
        s.hasElse = true;
        elseIf = isWord("IF");
        s.body = statements();
    }
    closeBlock("END_IF", "IF", opened,
               elseIf ? QCoreApplication::translate("iec::interp::Compiler", "ELSE IF opens a second IF that needs its own END_IF; write ELSIF instead") : QString());
    return s;
}

bool Parser::isCaseLabelStart() const
{
    if (atEnd())
        return false;
    const TokenKind k = tok().kind;
    size_t next = 1;
    if (isOp(u"-"))
        next = 2;
    const TokenKind literal = tok(next - 1).kind;
    if (literal == TokenKind::IntegerLiteral || (next == 2 && tok(1).kind == TokenKind::IntegerLiteral))
        return true; // no statement starts with a number: a label, perhaps without its ':'
    if (k == TokenKind::Identifier) {
        // Red:, and CODESYS's qualified Color.Red:
        size_t after = 1;
        while (isOp(u".", after) && !atEnd(after + 1) && tok(after + 1).kind == TokenKind::Identifier)
            after += 2;
        return isOp(u":", after) || isOp(u",", after) || isOp(u"..", after);
    }
    return false;
}

Stmt Parser::caseStatement()
{
    Stmt s;
    s.kind = StmtKind::Case;
    s.location = here();
    ++m_pos;
    s.target = expression();
    expectWord("OF");
    while (!atEnd() && !isWord("END_CASE") && !isWord("ELSE") && !isBlockWord()) {
        if (!isCaseLabelStart()) {
            const size_t before = m_pos;
            unexpected(QCoreApplication::translate("iec::interp::Compiler", "a case label such as 1:, 2, 3: or 10..20:"));
            synchronize(true);
            skipIfStuck(before);
            continue;
        }
        CaseBranch branch;
        do {
            CaseLabel label;
            label.low = expression();
            if (acceptOp(u".."))
                label.high = expression();
            branch.labels.push_back(std::move(label));
        } while (acceptOp(u","));
        if (!expectOp(u":", QCoreApplication::translate("iec::interp::Compiler", "':' after the case label")))
            m_recovering = false; // the statements after it are still read
        while (!atEnd() && !isCaseLabelStart() && !isStatementListEnd()) {
            const size_t before = m_pos;
            branch.body.push_back(statement());
            if (m_recovering)
                synchronize(true);
            if (m_pos == before)
                ++m_pos;
        }
        s.cases.push_back(std::move(branch));
    }
    if (acceptWord("ELSE")) {
        s.hasElse = true;
        s.body = statements();
    }
    closeBlock("END_CASE", "CASE", s.location);
    return s;
}

Stmt Parser::forStatement()
{
    Stmt s;
    s.kind = StmtKind::For;
    s.location = here();
    ++m_pos;
    if (!isName()) {
        unexpected(QCoreApplication::translate("iec::interp::Compiler", "the control variable of the FOR loop"));
    } else {
        s.target = primary();
    }
    expectOp(u":=", QCoreApplication::translate("iec::interp::Compiler", "':=' and the start value"));
    s.value = expression();
    expectWord("TO");
    s.to = expression();
    if (acceptWord("BY"))
        s.by = expression();
    if (!acceptWord("DO"))
        unexpected(QStringLiteral("DO"));
    if (m_recovering)
        synchronize(true);
    s.body = statements();
    closeBlock("END_FOR", "FOR", s.location);
    return s;
}

Stmt Parser::whileStatement()
{
    Stmt s;
    s.kind = StmtKind::While;
    s.location = here();
    ++m_pos;
    s.value = expression();
    if (!acceptWord("DO"))
        unexpected(QStringLiteral("DO"));
    if (m_recovering)
        synchronize(true);
    s.body = statements();
    closeBlock("END_WHILE", "WHILE", s.location);
    return s;
}

Stmt Parser::repeatStatement()
{
    Stmt s;
    s.kind = StmtKind::Repeat;
    s.location = here();
    ++m_pos;
    s.body = statements();
    if (acceptWord("UNTIL")) {
        s.value = expression();
        acceptOp(u";"); // CODESYS allows "UNTIL x;"? no: but be lenient
    } else {
        error(s.location, QCoreApplication::translate("iec::interp::Compiler", "This REPEAT has no UNTIL condition."));
    }
    closeBlock("END_REPEAT", "REPEAT", s.location);
    return s;
}

} // namespace iec::interp::parsing
