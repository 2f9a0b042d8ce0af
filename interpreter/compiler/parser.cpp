#include "interpreter/compiler/parser.h"

#include "interpreter/compiler/compilerstack.h"
#include "interpreter/compiler/limits.h"

#include <QCoreApplication>
#include <QScopeGuard>
#include <algorithm>
#include <array>
#include <optional>
#include <string_view>

namespace iec::interp {

using namespace ast;

namespace {

// Words that are keywords only in a few places (configurations, tasks, SFC) and ordinary names
// elsewhere. RESOURCE and TASK are here because tools name them so ("RESOURCE Resource",
// "TASK Task"), and PLCopen files carry such names.
// STEP, TRANSITION and ACTION start textual SFC only when a name follows (STEP Fill:); CODESYS
// programs commonly call a state variable Step.
constexpr std::string_view kSoftKeywords[] = {"INTERVAL",  "PRIORITY",   "SINGLE",   "ON",       "FROM", "STEP", "TRANSITION",
                                              "ACTION",    "READ_ONLY",  "READ_WRITE", "CONSTANT", "RESOURCE", "TASK"};
// IL operators that are also ST operators, and so never names in ST.
constexpr std::string_view kStOperatorWords[] = {"AND", "OR", "XOR", "NOT", "MOD"};

bool equalsUpper(QStringView text, std::string_view upper)
{
    if (text.size() != static_cast<qsizetype>(upper.size()))
        return false;
    for (qsizetype i = 0; i < text.size(); ++i) {
        if (text[i].toUpper().unicode() != static_cast<char16_t>(upper[static_cast<size_t>(i)]))
            return false;
    }
    return true;
}

template<size_t N>
bool inList(QStringView word, const std::string_view (&list)[N])
{
    return std::any_of(std::begin(list), std::end(list), [&](std::string_view w) { return equalsUpper(word, w); });
}

// Binary operators with their IEC precedence (higher binds tighter), the table of the grammar.
struct BinaryOperator {
    std::string_view spelling;
    int precedence;
    const char *canonical;
};
constexpr BinaryOperator kBinaryOperators[] = {
    {"OR", 1, "OR"}, {"OR_ELSE", 1, "OR_ELSE"}, {"XOR", 2, "XOR"}, {"AND", 3, "AND"}, {"AND_THEN", 3, "AND_THEN"}, {"&", 3, "AND"}, {"=", 4, "="},
    {"<>", 4, "<>"}, {"<", 5, "<"},     {">", 5, ">"},     {"<=", 5, "<="},  {">=", 5, ">="},
    {"+", 6, "+"},   {"-", 6, "-"},     {"*", 7, "*"},     {"/", 7, "/"},    {"MOD", 7, "MOD"},
    {"**", 8, "**"},
};

class Parser
{
public:
    Parser(QStringView text, Diagnostics &diagnostics, QString pou, int firstLine)
        : m_text(text)
        , m_diagnostics(diagnostics)
        , m_pou(std::move(pou))
        , m_firstLine(firstLine)
    {
        std::vector<Token> pragmas;
        for (const Token &t : tokenize(text)) {
            if (t.kind == TokenKind::Pragma)
                pragmas.push_back(t);
            else if (t.kind != TokenKind::Comment)
                m_tokens.push_back(t);
        }
        m_lineStarts.push_back(0);
        for (qsizetype i = 0; i < text.size(); ++i) {
            if (text[i] == QLatin1Char('\n'))
                m_lineStarts.push_back(static_cast<int>(i + 1));
        }
        for (const Token &t : pragmas)
            pragma(t);
    }

    CompilationUnit unit();
    std::vector<Stmt> stBody()
    {
        auto body = statements();
        if (!atEnd())
            unexpected(QCoreApplication::translate("iec::interp::Compiler", "a statement"));
        return body;
    }
    std::vector<IlInstruction> ilBody() { return ilInstructions(); }
    std::vector<VarSection> declarations()
    {
        std::vector<VarSection> sections;
        while (!atEnd()) {
            if (isVarSectionStart())
                sections.push_back(varSection());
            else {
                unexpected(QCoreApplication::translate("iec::interp::Compiler", "VAR ... END_VAR"));
                ++m_pos;
            }
        }
        return sections;
    }

private:
    // ---- tokens ----
    bool atEnd(size_t ahead = 0) const { return m_pos + ahead >= m_tokens.size(); }
    const Token &tok(size_t ahead = 0) const
    {
        static const Token end{TokenKind::Error, 0, 0};
        return atEnd(ahead) ? end : m_tokens[m_pos + ahead];
    }
    QStringView text(const Token &t) const { return m_text.mid(t.offset, t.length); }
    QStringView text(size_t ahead = 0) const { return atEnd(ahead) ? QStringView() : text(tok(ahead)); }

    SourceLocation locationOf(int offset) const
    {
        const auto it = std::upper_bound(m_lineStarts.begin(), m_lineStarts.end(), offset);
        const int line = static_cast<int>(it - m_lineStarts.begin());
        return {line + m_firstLine - 1, offset - *(it - 1) + 1};
    }
    SourceLocation here() const
    {
        if (atEnd())
            return locationOf(m_tokens.empty() ? 0 : m_tokens.back().offset + m_tokens.back().length);
        return locationOf(tok().offset);
    }
    // Just after the previous token: where a missing ';' belongs.
    SourceLocation afterPrevious() const
    {
        if (m_pos == 0)
            return here();
        const Token &t = m_tokens[m_pos - 1];
        return locationOf(t.offset + t.length);
    }
    int lineOf(const Token &t) const { return locationOf(t.offset).line; }

    bool isWordToken(const Token &t) const
    {
        return t.kind == TokenKind::Keyword || t.kind == TokenKind::Identifier || t.kind == TokenKind::TypeName;
    }
    bool isWord(std::string_view upper, size_t ahead = 0) const
    {
        return !atEnd(ahead) && isWordToken(tok(ahead)) && equalsUpper(text(ahead), upper);
    }
    bool isOp(std::u16string_view op, size_t ahead = 0) const
    {
        return !atEnd(ahead) && tok(ahead).kind == TokenKind::Operator
            && text(ahead) == QStringView(op.data(), static_cast<qsizetype>(op.size()));
    }
    bool acceptWord(std::string_view upper)
    {
        if (!isWord(upper))
            return false;
        ++m_pos;
        return true;
    }
    bool acceptOp(std::u16string_view op)
    {
        if (!isOp(op))
            return false;
        ++m_pos;
        return true;
    }
    // A name in ST: identifiers, and keywords that are only keywords in IL or in tasks/SFC.
    bool isName(size_t ahead = 0) const
    {
        if (atEnd(ahead))
            return false;
        const Token &t = tok(ahead);
        if (t.kind == TokenKind::Identifier)
            return true;
        if (t.kind != TokenKind::Keyword)
            return false;
        const QStringView word = text(t);
        return (isIlOperator(word) && !inList(word, kStOperatorWords)) || inList(word, kSoftKeywords);
    }

    // CODESYS pragmas: {warning 'text'} is shown as a warning, {error 'text'} as an error; attributes and the other pragmas
    // CODESYS writes are kept in the text and have no effect; anything else is ignored with a note.
    void pragma(const Token &t)
    {
        const QString raw = text(t).toString();
        const QString body = raw.mid(1, raw.size() - (raw.endsWith(QLatin1Char('}')) ? 2 : 1)).trimmed();
        const QString word = body.section(QLatin1Char(' '), 0, 0).toLower();
        static const QStringList known {QStringLiteral("attribute"), QStringLiteral("region"), QStringLiteral("endregion"),
                                        QStringLiteral("library"), QStringLiteral("info"), QStringLiteral("text"),
                                        QStringLiteral("messageguid"), QStringLiteral("implicit"), QStringLiteral("flag")};
        const SourceLocation at = locationOf(t.offset);
        if (body.startsWith(QLatin1String("__")) || body.contains(QLatin1String("data__")))
            return; // Beremiz's inline C (its standard blocks read the clock so): nothing to do here
        const QString message = body.section(QLatin1Char(' '), 1).trimmed().remove(QLatin1Char('\''));
        if (word == QLatin1String("warning")) {
            m_diagnostics.warning(m_pou, at, message);
        } else if (word == QLatin1String("error")) {
            m_diagnostics.error(m_pou, at, message);
        } else if (!known.contains(word)) {
            m_diagnostics.warning(m_pou, at, QCoreApplication::translate("iec::interp::Compiler", "The pragma {%1} means nothing to IEC Studio; it is ignored.").arg(body.left(40)));
        }
    }

    // ---- diagnostics ----
    void error(SourceLocation at, const QString &message, const QString &hint = {})
    {
        if (m_recovering)
            return; // one typo, one message
        m_diagnostics.error(m_pou, at, message, hint);
        m_recovering = true;
    }
    QString describeCurrent() const
    {
        if (atEnd())
            return QCoreApplication::translate("iec::interp::Compiler", "the end of the text");
        return QLatin1Char('\'') + text().toString() + QLatin1Char('\'');
    }
    void unexpected(const QString &expected)
    {
        if (!atEnd() && tok().kind == TokenKind::Error) {
            const QStringView bad = text();
            if (bad.startsWith(QLatin1Char('\'')) || bad.startsWith(QLatin1Char('"')))
                error(here(), QCoreApplication::translate("iec::interp::Compiler", "This string is not closed on its line."), badTokenHint(bad));
            else
                error(here(), QCoreApplication::translate("iec::interp::Compiler", "'%1' is not valid IEC 61131-3 text.").arg(bad.toString()),
                      badTokenHint(bad));
            return;
        }
        error(here(), QCoreApplication::translate("iec::interp::Compiler", "Expected %1 but found %2.").arg(expected, describeCurrent()));
    }
    static QString badTokenHint(QStringView bad)
    {
        if (bad.startsWith(QLatin1Char('\'')) || bad.startsWith(QLatin1Char('"')))
            return QCoreApplication::translate("iec::interp::Compiler", "close the string on the same line, and write $$ for a dollar sign");
        if (bad.contains(QLatin1Char('#')))
            return QCoreApplication::translate("iec::interp::Compiler", "check the digits and units of the literal, e.g. 16#FF or T#1s500ms");
        return {};
    }
    bool expectOp(std::u16string_view op, const QString &what)
    {
        if (acceptOp(op))
            return true;
        unexpected(what);
        return false;
    }
    bool expectWord(std::string_view upper)
    {
        if (acceptWord(upper))
            return true;
        unexpected(QString::fromLatin1(upper.data(), static_cast<qsizetype>(upper.size())));
        return false;
    }
    QString expectName(const QString &what)
    {
        if (isName())
            return takeName();
        unexpected(what);
        return {};
    }
    QString takeName() { return text(m_tokens[m_pos++]).toString(); }
    // Skips to just after the next ';' or to a word that starts something new.
    void synchronize(bool stopAtStatementStart)
    {
        while (!atEnd()) {
            if (acceptOp(u";"))
                break;
            if (isBlockWord() || (stopAtStatementStart && isStatementKeyword()))
                break;
            ++m_pos;
        }
        m_recovering = false;
    }
    // Recovery that stopped where it started would loop for ever: take one token.
    void skipIfStuck(size_t before)
    {
        if (m_pos == before && !atEnd())
            ++m_pos;
    }
    bool isBlockWord() const
    {
        if (atEnd() || tok().kind != TokenKind::Keyword)
            return false;
        const QStringView w = text();
        return w.startsWith(QLatin1String("END_"), Qt::CaseInsensitive) || isWord("ELSE") || isWord("ELSIF")
            || isWord("UNTIL") || isWord("VAR") || w.startsWith(QLatin1String("VAR_"), Qt::CaseInsensitive)
            || isPouStart();
    }
    // END_FI, END_WHIL: an identifier where a block ends, most likely a misspelled END_ word.
    bool isMisspelledEnd() const
    {
        return !atEnd() && tok().kind == TokenKind::Identifier && text().startsWith(QLatin1String("END_"), Qt::CaseInsensitive);
    }
    // The keyword a misspelled word most likely stands for (one letter added, missing, changed or
    // two swapped), for a hint; empty when none is that close.
    static QString nearKeyword(QStringView word)
    {
        static constexpr std::string_view keywords[] = {"IF", "ELSIF", "ELSE", "CASE", "FOR", "WHILE", "REPEAT", "UNTIL", "EXIT", "RETURN"};
        const QString w = word.toString().toUpper();
        for (const std::string_view k : keywords) {
            const QString kw = QString::fromLatin1(k.data(), qsizetype(k.size()));
            if (editDistanceAtMostOne(w, kw))
                return kw;
        }
        return {};
    }
    static bool editDistanceAtMostOne(const QString &a, const QString &b)
    {
        if (a == b || std::abs(a.size() - b.size()) > 1)
            return a == b;
        qsizetype i = 0;
        while (i < a.size() && i < b.size() && a[i] == b[i])
            ++i;
        if (a.size() == b.size()) {
            if (i + 1 < a.size() && a[i] == b[i + 1] && a[i + 1] == b[i] && a.mid(i + 2) == b.mid(i + 2))
                return true; // two letters swapped
            return a.mid(i + 1) == b.mid(i + 1);
        }
        return a.size() > b.size() ? a.mid(i + 1) == b.mid(i) : a.mid(i) == b.mid(i + 1);
    }
    bool isStatementKeyword() const
    {
        return isWord("IF") || isWord("CASE") || isWord("FOR") || isWord("WHILE") || isWord("REPEAT")
            || isWord("EXIT") || isWord("RETURN") || isWord("CONTINUE");
    }
    bool isPouStart() const
    {
        return isWord("PROGRAM") || isWord("FUNCTION") || isWord("FUNCTION_BLOCK") || isWord("TYPE")
            || isWord("CONFIGURATION") || (isWord("INTERFACE") && isName(1));
    }
    // METHOD or PROPERTY of a function block (CODESYS, edition 3): a name, perhaps after
    // qualifiers, follows; "Method := 1;" is a statement.
    bool startsMember() const
    {
        return (isWord("METHOD") || isWord("PROPERTY")) && !atEnd(1) && isWordToken(tok(1)) && !isOp(u":=", 1) && !isOp(u".", 1)
            && !isOp(u"(", 1) && !isOp(u"[", 1);
    }

    // ---- units ----
    void pou(CompilationUnit &unit);
    void pouHeader(Pou &p);
    void members(Pou &p);
    Method method(bool prototype);
    void property(Pou &p, bool prototype);
    Access qualifiers(bool &isAbstract, bool &isFinal);
    void typeBlock(CompilationUnit &unit);
    void configuration(CompilationUnit &unit);
    void resourceContents(ResourceDecl &resource, std::string_view end);
    bool isVarSectionStart() const { return isWord("VAR") || (!atEnd() && tok().kind == TokenKind::Keyword && text().startsWith(QLatin1String("VAR_"), Qt::CaseInsensitive)); }
    VarSection varSection();
    void varDeclarations(std::vector<VarDecl> &out, std::string_view end);
    TypeSpec typeSpec();
    Initializer initializer();
    Body body(std::initializer_list<std::string_view> ends);
    bool looksLikeIl() const;
    bool looksLikeSfc() const;
    void sfc(SfcChart &chart, std::initializer_list<std::string_view> ends);
    void sfcStep(SfcChart &chart, bool initial);
    void sfcTransition(SfcChart &chart);
    QStringList stepList();
    bool isEnd(std::initializer_list<std::string_view> ends) const
    {
        return atEnd() || std::any_of(ends.begin(), ends.end(), [&](std::string_view e) {
                   // "ACTION Fill:" starts an action; "Action := 3;" is a statement.
                   return isWord(e) && (e != "ACTION" || startsSfcElement());
               });
    }
    // STEP/INITIAL_STEP/TRANSITION/ACTION used as keywords: a name or the TRANSITION's FROM or
    // (PRIORITY := n) follows, not an assignment or a member access.
    bool startsSfcElement() const
    {
        if (isWord("TRANSITION") && (isOp(u"(", 1) || equalsUpper(text(1), "FROM")))
            return true;
        return (isWord("STEP") || isWord("INITIAL_STEP") || isWord("TRANSITION") || isWord("ACTION")) && !atEnd(1)
            && (tok(1).kind == TokenKind::Identifier || tok(1).kind == TokenKind::Keyword) && !isOp(u":=", 1);
    }

    // ---- ST ----
    std::vector<Stmt> statements();
    bool isStatementListEnd() const;
    Stmt statement();
    Stmt ifStatement();
    Stmt caseStatement();
    bool isCaseLabelStart() const;
    Stmt forStatement();
    Stmt whileStatement();
    Stmt repeatStatement();
    void closeBlock(std::string_view endWord, const char *blockName, SourceLocation opened, const QString &hint = {});
    void recoverMisspelledBlock();
    void endStatement();

    // ---- expressions ----
    Expr expression(int minPrecedence = 1);
    Expr unary();
    Expr primary();
    Expr postfix(Expr base);
    std::vector<CallArg> callArguments();
    const BinaryOperator *binaryOperator() const;
    Expr errorExpr() const
    {
        Expr e;
        e.location = here();
        return e;
    }

    // ---- IL ----
    std::vector<IlInstruction> ilInstructions(std::initializer_list<std::string_view> ends = {});
    bool ilOperandFollows(const Token &opToken) const { return !atEnd() && lineOf(tok()) == lineOf(opToken); }

    QStringView m_text;
    Diagnostics &m_diagnostics;
    QString m_pou;
    int m_firstLine = 1;
    std::vector<Token> m_tokens;
    std::vector<int> m_lineStarts;
    size_t m_pos = 0;
    bool m_recovering = false;

    // ---- nesting (limits.h) ----
    // Every recursion of the parser follows nesting in the text; these count it, and a level
    // beyond the limit is reported once and skipped instead of entered.
    int m_depth = 0;      // within an expression
    int m_blockDepth = 0; // statements inside blocks, action bodies inside charts
    int m_typeDepth = 0;  // types inside types, initial values inside initial values
    class Nested
    {
    public:
        explicit Nested(int &depth)
            : m_depth(depth)
        {
            ++m_depth;
        }
        ~Nested() { --m_depth; }
        Nested(const Nested &) = delete;
        Nested &operator=(const Nested &) = delete;

    private:
        int &m_depth;
    };
    // The outermost expression is level 0: 1000 nested parentheses are 1000 levels.
    bool tooDeep() const { return m_depth - 1 > limits::kMaxNesting; }
    bool blockTooDeep() const { return m_blockDepth > limits::kMaxNesting; }
    bool typeTooDeep() const { return m_typeDepth > limits::kMaxTypeNesting; }
    // One level deeper inside an expression; false when that is beyond the limit.
    bool deeper()
    {
        ++m_depth;
        return !tooDeep();
    }
    Expr refuseDeepExpression();
    Stmt refuseDeepBlock();
    void refuseDeepBody(std::initializer_list<std::string_view> ends);
    void refuseDeepType();
    void refuseDeepInitializer();
    void skipRestOfExpression();
    bool isBlockStart() const
    {
        return isWord("IF") || isWord("CASE") || isWord("FOR") || isWord("WHILE") || isWord("REPEAT");
    }
};

// ============================================================================ units

CompilationUnit Parser::unit()
{
    CompilationUnit unit;
    while (!atEnd()) {
        m_pou.clear();
        if (isWord("PROGRAM") || isWord("FUNCTION") || isWord("FUNCTION_BLOCK") || (isWord("INTERFACE") && isName(1))) {
            pou(unit);
        } else if (isWord("TYPE")) {
            typeBlock(unit);
        } else if (isWord("CONFIGURATION")) {
            configuration(unit);
        } else if (isVarSectionStart()) {
            unit.globals.push_back(varSection());
        } else {
            unexpected(QCoreApplication::translate("iec::interp::Compiler", "PROGRAM, FUNCTION_BLOCK, FUNCTION, TYPE or CONFIGURATION"));
            ++m_pos;
            while (!atEnd() && !isPouStart() && !isVarSectionStart())
                ++m_pos;
            m_recovering = false;
        }
    }
    return unit;
}

void Parser::pou(CompilationUnit &unit)
{
    Pou p;
    p.location = here();
    std::string_view end;
    if (acceptWord("PROGRAM")) {
        p.kind = PouKind::Program;
        end = "END_PROGRAM";
    } else if (acceptWord("FUNCTION_BLOCK")) {
        p.kind = PouKind::FunctionBlock;
        end = "END_FUNCTION_BLOCK";
    } else if (acceptWord("INTERFACE")) {
        p.kind = PouKind::Interface;
        end = "END_INTERFACE";
    } else {
        acceptWord("FUNCTION");
        p.kind = PouKind::Function;
        end = "END_FUNCTION";
    }
    pouHeader(p);
    m_pou = p.name;
    if (p.kind == PouKind::Function) {
        if (acceptOp(u":"))
            p.returnType = typeSpec();
        else
            error(here(), QCoreApplication::translate("iec::interp::Compiler", "A FUNCTION needs a result type after its name."),
                  QCoreApplication::translate("iec::interp::Compiler", "write e.g. FUNCTION %1 : INT").arg(p.name));
    }
    while (isVarSectionStart())
        p.sections.push_back(varSection());
    members(p);
    if (p.kind != PouKind::Interface)
        p.body = body({end, "ACTION"});
    // Actions (and methods, properties) after the body, as CODESYS exports them.
    members(p);
    while (isWord("ACTION") && startsSfcElement()) {
        SfcAction action;
        action.location = here();
        ++m_pos;
        action.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the action"));
        acceptOp(u":");
        action.body = body({"END_ACTION"});
        expectWord("END_ACTION");
        p.actions.push_back(std::move(action));
    }
    members(p);
    if (p.body.language == Language::SFC) { // in a chart, actions belong to the chart
        for (SfcAction &action : p.actions)
            p.body.sfc->actions.push_back(std::move(action));
        p.actions.clear();
    }
    if (acceptWord(end)) {
        // closed
    } else if (isMisspelledEnd()) {
        error(here(), QCoreApplication::translate("iec::interp::Compiler", "Expected %1 but found '%2'.").arg(QString::fromLatin1(end.data(), qsizetype(end.size())), text().toString()));
        ++m_pos;
        m_recovering = false;
    } else {
        error(p.location, QCoreApplication::translate("iec::interp::Compiler", "%1 has no %2.").arg(p.name, QString::fromLatin1(end.data(), qsizetype(end.size()))),
              QCoreApplication::translate("iec::interp::Compiler", "add %1 after its last statement").arg(QString::fromLatin1(end.data(), qsizetype(end.size()))));
        while (!atEnd() && !isPouStart())
            ++m_pos;
        m_recovering = false;
    }
    unit.pous.push_back(std::move(p));
}

// The name and, for function blocks and interfaces, ABSTRACT/FINAL, EXTENDS and IMPLEMENTS.
void Parser::pouHeader(Pou &p)
{
    while ((isWord("ABSTRACT") || isWord("FINAL") || isWord("PUBLIC") || isWord("INTERNAL")) && isName(1)) {
        p.isAbstract = p.isAbstract || isWord("ABSTRACT");
        p.isFinal = p.isFinal || isWord("FINAL");
        ++m_pos;
    }
    p.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the POU"));
    if (p.kind != PouKind::FunctionBlock && p.kind != PouKind::Interface)
        return;
    if (acceptWord("EXTENDS")) {
        // An interface may extend several interfaces.
        do {
            const QString base = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name it extends"));
            if (p.kind == PouKind::Interface)
                p.implements << base;
            else
                p.extends = base;
        } while (p.kind == PouKind::Interface && acceptOp(u","));
    }
    if (p.kind == PouKind::FunctionBlock && acceptWord("IMPLEMENTS")) {
        do
            p.implements << expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of an interface"));
        while (acceptOp(u","));
    }
}

// PUBLIC, PRIVATE, PROTECTED, INTERNAL, ABSTRACT, FINAL before a method's or property's name.
Access Parser::qualifiers(bool &isAbstract, bool &isFinal)
{
    Access access = Access::Public;
    for (;;) {
        if (!isName(1) && !(!atEnd(1) && isWordToken(tok(1)) && !isOp(u":", 1) && !isOp(u";", 1)))
            break;
        if (acceptWord("PUBLIC"))
            access = Access::Public;
        else if (acceptWord("PRIVATE"))
            access = Access::Private;
        else if (acceptWord("PROTECTED"))
            access = Access::Protected;
        else if (acceptWord("INTERNAL"))
            access = Access::Internal;
        else if (acceptWord("ABSTRACT"))
            isAbstract = true;
        else if (acceptWord("FINAL"))
            isFinal = true;
        else
            break;
    }
    return access;
}

// The METHODs and PROPERTYs of a function block or interface, where they stand.
void Parser::members(Pou &p)
{
    while (startsMember()) {
        const size_t before = m_pos;
        if (isWord("METHOD"))
            p.methods.push_back(method(p.kind == PouKind::Interface));
        else
            property(p, p.kind == PouKind::Interface);
        skipIfStuck(before);
    }
}

Method Parser::method(bool prototype)
{
    Method m;
    m.location = here();
    ++m_pos; // METHOD
    m.access = qualifiers(m.isAbstract, m.isFinal);
    m.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the method"));
    if (acceptOp(u":"))
        m.returnType = typeSpec();
    acceptOp(u";");
    while (isVarSectionStart())
        m.sections.push_back(varSection());
    m.hasBody = !prototype && !m.isAbstract;
    m.body = body({"END_METHOD"});
    if (!acceptWord("END_METHOD")) {
        error(m.location, QCoreApplication::translate("iec::interp::Compiler", "The method %1 has no END_METHOD.").arg(m.name));
        while (!atEnd() && !isWord("END_METHOD") && !isPouStart())
            ++m_pos;
        acceptWord("END_METHOD");
        m_recovering = false;
    }
    acceptOp(u";");
    return m;
}

// PROPERTY name : type, with GET ... END_GET and SET ... END_SET: a getter returning the value
// and a setter taking it, both named like the property.
void Parser::property(Pou &p, bool prototype)
{
    const SourceLocation at = here();
    ++m_pos; // PROPERTY
    Method getter;
    getter.location = at;
    getter.access = qualifiers(getter.isAbstract, getter.isFinal);
    getter.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the property"));
    if (expectOp(u":", QCoreApplication::translate("iec::interp::Compiler", "':' and the type of the property")))
        getter.returnType = typeSpec();
    acceptOp(u";");
    bool hasGet = false, hasSet = false;
    Method setter = getter;
    setter.returnType.reset();
    getter.role = Method::Role::Getter;
    setter.role = Method::Role::Setter;
    while ((isWord("GET") || isWord("SET")) && !isOp(u":=", 1)) {
        const bool get = isWord("GET");
        Method &accessor = get ? getter : setter;
        (get ? hasGet : hasSet) = true;
        accessor.location = here();
        ++m_pos;
        while (isVarSectionStart())
            accessor.sections.push_back(varSection());
        accessor.hasBody = !prototype && !accessor.isAbstract;
        accessor.body = body({get ? "END_GET" : "END_SET"});
        expectWord(get ? "END_GET" : "END_SET");
        acceptOp(u";");
    }
    if (!acceptWord("END_PROPERTY")) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "The property %1 has no END_PROPERTY.").arg(getter.name));
        while (!atEnd() && !isWord("END_PROPERTY") && !isPouStart())
            ++m_pos;
        acceptWord("END_PROPERTY");
        m_recovering = false;
    }
    acceptOp(u";");
    if (hasSet && getter.returnType) {
        VarSection input;
        input.kind = VarKind::Input;
        VarDecl value;
        value.name = setter.name;
        value.location = setter.location;
        value.type = *getter.returnType;
        input.vars.push_back(std::move(value));
        setter.sections.insert(setter.sections.begin(), std::move(input));
        p.methods.push_back(std::move(setter));
    }
    if (hasGet || !hasSet)
        p.methods.push_back(std::move(getter));
}

void Parser::typeBlock(CompilationUnit &unit)
{
    ++m_pos; // TYPE
    while (!atEnd() && !isWord("END_TYPE") && !isPouStart()) {
        const size_t before = m_pos;
        TypeDecl decl;
        decl.location = here();
        decl.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of a type"));
        if (decl.name.isEmpty() || !expectOp(u":", QCoreApplication::translate("iec::interp::Compiler", "':' after the type name"))) {
            synchronize(false);
            skipIfStuck(before);
            continue;
        }
        decl.type = typeSpec();
        if (acceptOp(u":="))
            decl.init = initializer();
        if (!acceptOp(u";")) {
            error(afterPrevious(), QCoreApplication::translate("iec::interp::Compiler", "Missing ';' after the declaration of type %1.").arg(decl.name));
            synchronize(false);
        }
        m_recovering = false;
        unit.types.push_back(std::move(decl));
    }
    expectWord("END_TYPE");
    m_recovering = false;
}

void Parser::configuration(CompilationUnit &unit)
{
    ConfigurationDecl config;
    config.location = here();
    ++m_pos;
    config.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the configuration"));
    m_pou = config.name;
    while (isVarSectionStart())
        config.globals.push_back(varSection());
    if (isWord("RESOURCE")) {
        while (acceptWord("RESOURCE")) {
            ResourceDecl resource;
            resource.location = here();
            resource.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the resource"));
            if (acceptWord("ON"))
                resource.on = expectName(QCoreApplication::translate("iec::interp::Compiler", "the processor type after ON"));
            resourceContents(resource, "END_RESOURCE");
            expectWord("END_RESOURCE");
            config.resources.push_back(std::move(resource));
        }
    } else {
        ResourceDecl resource; // tasks and programs directly in the configuration
        resource.location = config.location;
        resourceContents(resource, "END_CONFIGURATION");
        config.resources.push_back(std::move(resource));
    }
    expectWord("END_CONFIGURATION");
    m_recovering = false;
    unit.configurations.push_back(std::move(config));
}

void Parser::resourceContents(ResourceDecl &resource, std::string_view end)
{
    while (!atEnd() && !isWord(end) && !isWord("END_CONFIGURATION")) {
        if (isVarSectionStart()) {
            resource.globals.push_back(varSection());
        } else if (acceptWord("TASK")) {
            TaskDecl task;
            task.location = here();
            task.name = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the task"));
            if (expectOp(u"(", QCoreApplication::translate("iec::interp::Compiler", "'(' with the task's INTERVAL and PRIORITY"))) {
                while (!atEnd() && !isOp(u")")) {
                    const bool single = isWord("SINGLE"), interval = isWord("INTERVAL"), priority = isWord("PRIORITY");
                    if (!single && !interval && !priority) {
                        unexpected(QCoreApplication::translate("iec::interp::Compiler", "SINGLE, INTERVAL or PRIORITY"));
                        break;
                    }
                    ++m_pos;
                    expectOp(u":=", QStringLiteral("':='"));
                    Expr value = expression();
                    (single ? task.single : interval ? task.interval : task.priority) = std::move(value);
                    if (!acceptOp(u","))
                        break;
                }
                expectOp(u")", QStringLiteral("')'"));
            }
            endStatement();
            resource.tasks.push_back(std::move(task));
        } else if (acceptWord("PROGRAM")) {
            ProgramConfig program;
            program.location = here();
            program.retain = acceptWord("RETAIN");
            acceptWord("NON_RETAIN");
            program.instance = expectName(QCoreApplication::translate("iec::interp::Compiler", "the name of the program instance"));
            if (acceptWord("WITH"))
                program.task = expectName(QCoreApplication::translate("iec::interp::Compiler", "the task name after WITH"));
            expectOp(u":", QCoreApplication::translate("iec::interp::Compiler", "':' and the program type"));
            program.type = expectName(QCoreApplication::translate("iec::interp::Compiler", "the program type"));
            if (acceptOp(u"("))
                program.args = callArguments();
            endStatement();
            resource.programs.push_back(std::move(program));
        } else {
            const size_t before = m_pos;
            unexpected(QCoreApplication::translate("iec::interp::Compiler", "TASK, PROGRAM or %1").arg(QString::fromLatin1(end.data(), qsizetype(end.size()))));
            synchronize(false);
            skipIfStuck(before);
        }
    }
}

VarSection Parser::varSection()
{
    VarSection section;
    section.location = here();
    struct Kind {
        std::string_view word;
        VarKind kind;
    };
    static constexpr Kind kinds[] = {
        {"VAR", VarKind::Local},          {"VAR_INPUT", VarKind::Input},   {"VAR_OUTPUT", VarKind::Output},
        {"VAR_IN_OUT", VarKind::InOut},   {"VAR_EXTERNAL", VarKind::External}, {"VAR_GLOBAL", VarKind::Global},
        {"VAR_TEMP", VarKind::Temp},      {"VAR_ACCESS", VarKind::Access}, {"VAR_CONFIG", VarKind::Config},
    };
    for (const Kind &k : kinds) {
        if (isWord(k.word))
            section.kind = k.kind;
    }
    ++m_pos;
    for (;;) {
        if (acceptWord("CONSTANT"))
            section.constant = true;
        else if (acceptWord("RETAIN"))
            section.retain = true;
        else if (acceptWord("NON_RETAIN"))
            section.nonRetain = true;
        else if (!acceptWord("PERSISTENT"))
            break;
    }
    varDeclarations(section.vars, "END_VAR");
    if (!acceptWord("END_VAR"))
        error(section.location, QCoreApplication::translate("iec::interp::Compiler", "This variable section has no END_VAR."),
              QCoreApplication::translate("iec::interp::Compiler", "add END_VAR after its last declaration"));
    m_recovering = false;
    return section;
}

void Parser::varDeclarations(std::vector<VarDecl> &out, std::string_view end)
{
    while (!atEnd() && !isWord(end) && !isBlockWord() && !isStatementKeyword()) {
        // "a := 1;" is a statement: the section above lacks its END_VAR, which the caller reports.
        if (isName() && (isOp(u":=", 1) || isOp(u"(", 1) || isOp(u".", 1) || isOp(u"[", 1)))
            break;
        std::vector<VarDecl> names;
        do {
            if (!isName()) {
                unexpected(QCoreApplication::translate("iec::interp::Compiler", "a variable name"));
                break;
            }
            VarDecl decl;
            decl.location = here();
            decl.name = takeName();
            names.push_back(std::move(decl));
        } while (acceptOp(u","));
        QString address;
        if (acceptWord("AT")) {
            if (!atEnd() && tok().kind == TokenKind::DirectAddress)
                address = takeName();
            else
                unexpected(QCoreApplication::translate("iec::interp::Compiler", "an address such as %IX0.0 after AT"));
        }
        if (names.empty() || !expectOp(u":", QCoreApplication::translate("iec::interp::Compiler", "':' and a type"))) {
            synchronize(false);
            continue;
        }
        TypeSpec type = typeSpec();
        Initializer init;
        if (acceptOp(u":="))
            init = initializer();
        else if (isOp(u"="))
            error(here(), QCoreApplication::translate("iec::interp::Compiler", "An initial value is given with ':=', not '='."),
                  QCoreApplication::translate("iec::interp::Compiler", "write %1 : ... := value;").arg(names.front().name));
        if (!acceptOp(u";")) {
            error(afterPrevious(), QCoreApplication::translate("iec::interp::Compiler", "Missing ';' after the declaration of %1.").arg(names.front().name));
            synchronize(false);
        }
        m_recovering = false;
        for (VarDecl &decl : names) {
            decl.address = address;
            decl.type = type;
            decl.init = init;
            out.push_back(std::move(decl));
        }
    }
}

TypeSpec Parser::typeSpec()
{
    TypeSpec spec;
    spec.location = here();
    std::optional<Nested> level;
    if (isWord("ARRAY") || isWord("STRUCT")) {
        level.emplace(m_typeDepth);
        if (typeTooDeep()) {
            refuseDeepType();
            return spec;
        }
    }
    if (acceptWord("ARRAY")) {
        spec.kind = TypeSpec::Kind::Array;
        if (expectOp(u"[", QCoreApplication::translate("iec::interp::Compiler", "'[' and the index range, e.g. ARRAY[1..10]"))) {
            do {
                Range range;
                range.low = expression();
                if (expectOp(u"..", QCoreApplication::translate("iec::interp::Compiler", "'..' between the bounds")))
                    range.high = expression();
                spec.ranges.push_back(std::move(range));
            } while (acceptOp(u","));
            expectOp(u"]", QStringLiteral("']'"));
        }
        expectWord("OF");
        spec.element.push_back(typeSpec());
        return spec;
    }
    if (acceptWord("STRUCT")) {
        spec.kind = TypeSpec::Kind::Struct;
        varDeclarations(spec.members, "END_STRUCT");
        if (!acceptWord("END_STRUCT"))
            error(spec.location, QCoreApplication::translate("iec::interp::Compiler", "This STRUCT has no END_STRUCT."));
        return spec;
    }
    if (acceptOp(u"(")) {
        spec.kind = TypeSpec::Kind::Enum;
        do {
            spec.enumValues << expectName(QCoreApplication::translate("iec::interp::Compiler", "an enumeration value"));
            std::optional<Expr> value;
            if (acceptOp(u":="))
                value = expression();
            spec.enumExplicit.push_back(std::move(value));
        } while (acceptOp(u","));
        expectOp(u")", QCoreApplication::translate("iec::interp::Compiler", "')' after the enumeration values"));
        if (!atEnd() && (tok().kind == TokenKind::TypeName))
            spec.name = takeName(); // CODESYS: (a, b) INT
        return spec;
    }
    // CODESYS POINTER TO T and REFERENCE TO T, IEC 61131-3 ed.3 REF_TO T.
    if ((isWord("POINTER") || isWord("REFERENCE")) && isWord("TO", 1)) {
        spec.kind = isWord("POINTER") ? TypeSpec::Kind::Pointer : TypeSpec::Kind::Reference;
        m_pos += 2;
        spec.element.push_back(typeSpec());
        return spec;
    }
    if (isWord("REF_TO")) {
        spec.kind = TypeSpec::Kind::Pointer;
        ++m_pos;
        spec.element.push_back(typeSpec());
        return spec;
    }
    if (isWord("STRING") || isWord("WSTRING")) {
        spec.kind = TypeSpec::Kind::String;
        spec.wide = isWord("WSTRING");
        ++m_pos;
        const bool square = acceptOp(u"[");
        if (square || acceptOp(u"(")) {
            spec.length = expression();
            expectOp(square ? u"]" : u")", QCoreApplication::translate("iec::interp::Compiler", "the closing bracket of the string length"));
        }
        return spec;
    }
    if (atEnd() || !(tok().kind == TokenKind::TypeName || isName())) {
        unexpected(QCoreApplication::translate("iec::interp::Compiler", "a type"));
        return spec;
    }
    spec.name = takeName();
    if (acceptOp(u"(")) { // subrange INT (0..100)
        spec.kind = TypeSpec::Kind::Subrange;
        Range range;
        range.low = expression();
        expectOp(u"..", QCoreApplication::translate("iec::interp::Compiler", "'..' between the bounds"));
        range.high = expression();
        spec.ranges.push_back(std::move(range));
        expectOp(u")", QStringLiteral("')'"));
    }
    return spec;
}

Initializer Parser::initializer()
{
    Initializer init;
    init.location = here();
    std::optional<Nested> level;
    if (isOp(u"[") || (isOp(u"(") && isName(1) && isOp(u":=", 2))) {
        level.emplace(m_typeDepth);
        if (typeTooDeep()) {
            refuseDeepInitializer();
            return init;
        }
    }
    if (acceptOp(u"[")) {
        init.kind = Initializer::Kind::Array;
        if (acceptOp(u"]"))
            return init;
        do {
            std::optional<Expr> repeat;
            if (!atEnd() && tok().kind == TokenKind::IntegerLiteral && isOp(u"(", 1)) {
                repeat = expression(9); // just the literal
                ++m_pos;                // (
                Initializer item;
                if (!isOp(u")"))
                    item = initializer();
                expectOp(u")", QCoreApplication::translate("iec::interp::Compiler", "')' after the repeated value"));
                init.items.push_back(std::move(item));
            } else {
                init.items.push_back(initializer());
            }
            init.repeats.push_back(std::move(repeat));
        } while (acceptOp(u","));
        expectOp(u"]", QCoreApplication::translate("iec::interp::Compiler", "']' at the end of the array's initial values"));
        return init;
    }
    if (isOp(u"(") && isName(1) && isOp(u":=", 2)) {
        ++m_pos;
        init.kind = Initializer::Kind::Struct;
        do {
            init.memberNames << expectName(QCoreApplication::translate("iec::interp::Compiler", "a member name"));
            expectOp(u":=", QStringLiteral("':='"));
            init.items.push_back(initializer());
        } while (acceptOp(u","));
        expectOp(u")", QCoreApplication::translate("iec::interp::Compiler", "')' at the end of the structure's initial values"));
        return init;
    }
    init.kind = Initializer::Kind::Expression;
    init.value = expression();
    return init;
}

Body Parser::body(std::initializer_list<std::string_view> ends)
{
    Body b;
    if (isEnd(ends))
        return b;
    if (looksLikeSfc()) {
        b.language = Language::SFC;
        b.sfc = std::make_shared<SfcChart>();
        sfc(*b.sfc, ends);
    } else if (looksLikeIl()) {
        b.language = Language::IL;
        b.il = ilInstructions(ends);
    } else {
        b.language = Language::ST;
        b.statements = statements();
        // A misspelled END_PROGRAM that ends the text or comes before the next POU: the POU reports it.
        const auto pouStartsAt = [&](size_t ahead) {
            static constexpr std::string_view starts[] = {"PROGRAM", "FUNCTION", "FUNCTION_BLOCK", "TYPE", "CONFIGURATION", "ACTION"};
            return atEnd(ahead) || std::any_of(std::begin(starts), std::end(starts), [&](std::string_view w) { return equalsUpper(text(ahead), w); });
        };
        if (!isEnd(ends) && !atEnd() && !(isMisspelledEnd() && pouStartsAt(1)) && !startsMember()) {
            unexpected(QCoreApplication::translate("iec::interp::Compiler", "a statement"));
            while (!isEnd(ends) && !isPouStart())
                ++m_pos;
            m_recovering = false;
        }
    }
    return b;
}

bool Parser::looksLikeSfc() const
{
    return (isWord("INITIAL_STEP") || isWord("STEP") || isWord("TRANSITION")) && startsSfcElement();
}

bool Parser::looksLikeIl() const
{
    if (atEnd())
        return false;
    // A label "Start:" is IL unless an ST statement follows it (CODESYS has labels in ST too).
    if (isName() && isOp(u":", 1)) {
        const bool stFollows = (isName(2) && (isOp(u":=", 3) || isOp(u"(", 3) || isOp(u".", 3) || isOp(u"[", 3) || isOp(u"^", 3)))
            || isWord("IF", 2) || isWord("FOR", 2) || isWord("WHILE", 2) || isWord("CASE", 2) || isWord("REPEAT", 2);
        return !stFollows;
    }
    if (tok().kind != TokenKind::Keyword || !isIlOperator(text()))
        return false;
    // "R := TRUE;", "ADD(...)" and "R REF= x;" are ST; "LD x" is IL.
    return !(isOp(u":=", 1) || isOp(u"(", 1) || isOp(u".", 1) || isOp(u"[", 1) || isOp(u"=>", 1) || isOp(u"^", 1)
             || (isWord("REF", 1) && isOp(u"=", 2)));
}

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

} // namespace

int binaryPrecedence(QStringView op)
{
    for (const BinaryOperator &o : kBinaryOperators) {
        if (op == QLatin1String(o.canonical))
            return o.precedence;
    }
    return 0;
}

// The entry points parse on the compiler's stack (compilerstack.h): the nesting limits above are
// safe there whatever thread asks (an editor's check while typing, the GUI thread).
namespace {

template<class Result, class Read>
Result onCompilerStack(Read read)
{
    Result result;
    runOnCompilerStack([&] { result = read(); });
    return result;
}

} // namespace

CompilationUnit parseUnit(QStringView text, Diagnostics &diagnostics)
{
    return onCompilerStack<CompilationUnit>([&] { return Parser(text, diagnostics, QString(), 1).unit(); });
}

std::vector<Stmt> parseStBody(QStringView text, const QString &pou, Diagnostics &diagnostics, int firstLine)
{
    return onCompilerStack<std::vector<Stmt>>([&] { return Parser(text, diagnostics, pou, firstLine).stBody(); });
}

std::vector<IlInstruction> parseIlBody(QStringView text, const QString &pou, Diagnostics &diagnostics, int firstLine)
{
    return onCompilerStack<std::vector<IlInstruction>>([&] { return Parser(text, diagnostics, pou, firstLine).ilBody(); });
}

std::vector<VarSection> parseDeclarations(QStringView text, const QString &pou, Diagnostics &diagnostics,
                                          int firstLine)
{
    return onCompilerStack<std::vector<VarSection>>([&] { return Parser(text, diagnostics, pou, firstLine).declarations(); });
}

} // namespace iec::interp
