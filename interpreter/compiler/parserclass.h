#pragma once

// The ST/IL/SFC-text parser's class, shared by the files that define its parts: parser.cpp (units,
// POUs, declarations, types, the entry points), parserstatements.cpp (textual SFC and ST
// statements), parserexpressions.cpp (expressions and the nesting limits) and parseril.cpp (IL).
// Private to the compiler: everything else uses parser.h.
#include "interpreter/compiler/ast.h"
#include "interpreter/compiler/diagnostics.h"
#include "interpreter/compiler/lexer.h"
#include "interpreter/compiler/limits.h"

#include <QCoreApplication>
#include <QScopeGuard>
#include <algorithm>
#include <array>
#include <optional>
#include <string_view>

namespace iec::interp::parsing {

using namespace ast;

// Words that are keywords only in a few places (configurations, tasks, SFC) and ordinary names
// elsewhere. RESOURCE and TASK are here because tools name them so ("RESOURCE Resource",
// "TASK Task"), and PLCopen files carry such names.
// STEP, TRANSITION and ACTION start textual SFC only when a name follows (STEP Fill:); CODESYS
// programs commonly call a state variable Step.
inline constexpr std::string_view kSoftKeywords[] = {"INTERVAL",  "PRIORITY",   "SINGLE",   "ON",       "FROM", "STEP", "TRANSITION",
                                              "ACTION",    "READ_ONLY",  "READ_WRITE", "CONSTANT", "RESOURCE", "TASK"};
// The long date types of IEC 61131-3 ed.3, which CODESYS and TwinCAT do not have: their projects
// use these words as names (OSCAT's CALENDAR has members LDT, LDATE and LTOD). Where a name can
// stand they are names; where a type can, types.
inline constexpr std::string_view kSoftTypeNames[] = {"LDATE", "LDT", "LTOD", "LDATE_AND_TIME", "LTIME_OF_DAY"};
// IL operators that are also ST operators, and so never names in ST.
inline constexpr std::string_view kStOperatorWords[] = {"AND", "OR", "XOR", "NOT", "MOD"};

inline bool equalsUpper(QStringView text, std::string_view upper)
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
inline constexpr BinaryOperator kBinaryOperators[] = {
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
            pragma(t, m_pou.isEmpty() ? pouAround(t.offset) : m_pou);
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
        if (t.kind == TokenKind::TypeName)
            return inList(text(t), kSoftTypeNames);
        if (t.kind != TokenKind::Keyword)
            return false;
        const QStringView word = text(t);
        return (isIlOperator(word) && !inList(word, kStOperatorWords)) || inList(word, kSoftKeywords);
    }

    // The POU a pragma at `offset` of a whole text belongs to: the one it stands in, or else the
    // next one (CODESYS writes a POU's attributes before its keyword); empty outside any.
    QString pouAround(int offset) const
    {
        static constexpr std::array<std::string_view, 5> kStarts {"PROGRAM", "FUNCTION_BLOCK", "FUNCTION", "INTERFACE", "CONFIGURATION"};
        static constexpr std::array<std::string_view, 5> kEnds {"END_PROGRAM", "END_FUNCTION_BLOCK", "END_FUNCTION", "END_INTERFACE", "END_CONFIGURATION"};
        const auto isOneOf = [this](const Token &t, const std::array<std::string_view, 5> &words) {
            return isWordToken(t) && std::ranges::any_of(words, [&](std::string_view w) { return equalsUpper(text(t), w); });
        };
        // The name of the POU whose keyword is token i; empty when token i starts none.
        const auto startsPou = [&](std::size_t i) {
            const bool named = i + 1 < m_tokens.size() && m_tokens[i + 1].kind == TokenKind::Identifier;
            return named && isOneOf(m_tokens[i], kStarts) ? text(m_tokens[i + 1]).toString() : QString();
        };
        QString inside;
        std::size_t i = 0;
        for (; i < m_tokens.size() && m_tokens[i].offset < offset; ++i) {
            if (const QString name = startsPou(i); !name.isEmpty())
                inside = name;
            else if (isOneOf(m_tokens[i], kEnds))
                inside.clear();
        }
        for (; inside.isEmpty() && i < m_tokens.size(); ++i)
            inside = startsPou(i);
        return inside;
    }

    // CODESYS pragmas: {warning 'text'} is shown as a warning, {error 'text'} as an error; attributes and the other pragmas
    // CODESYS writes are kept in the text and have no effect; anything else is ignored with a note.
    void pragma(const Token &t, const QString &pou)
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
            m_diagnostics.warning(pou, at, message);
        } else if (word == QLatin1String("error")) {
            m_diagnostics.requestedError(pou, at, message);
        } else if (!known.contains(word)) {
            m_diagnostics.warning(pou, at, QCoreApplication::translate("iec::interp::Compiler", "The pragma {%1} means nothing to IEC Studio; it is ignored.").arg(body.left(40)));
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
    Initializer declarationInitializer();
    void arrayItem(Initializer &init);
    bool continuesWithComma() const;
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

} // namespace iec::interp::parsing
