#include "interpreter/compiler/lexer.h"

#include "interpreter/compiler/literals.h"

#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <unordered_set>

namespace iec::interp {

namespace {

// Sorted, upper case. The IL operators are kept apart because ST treats them as names.
constexpr std::string_view kKeywords[] = {
    "ACTION",
    "AND",
    "AND_THEN",
    "ARRAY",
    "AT",
    "BY",
    "CASE",
    "CONFIGURATION",
    "CONSTANT",
    "CONTINUE",
    "DO",
    "ELSE",
    "ELSIF",
    "END_ACTION",
    "END_CASE",
    "END_CONFIGURATION",
    "END_FOR",
    "END_FUNCTION",
    "END_FUNCTION_BLOCK",
    "END_IF",
    "END_PROGRAM",
    "END_REPEAT",
    "END_RESOURCE",
    "END_STEP",
    "END_STRUCT",
    "END_TRANSITION",
    "END_TYPE",
    "END_VAR",
    "END_WHILE",
    "EXIT",
    "FALSE",
    "FOR",
    "FROM",
    "FUNCTION",
    "FUNCTION_BLOCK",
    "F_EDGE",
    "IF",
    "INITIAL_STEP",
    "INTERVAL",
    "MOD",
    "NON_RETAIN",
    "NOT",
    "OF",
    "ON",
    "OR",
    "OR_ELSE",
    "PERSISTENT",
    "PRIORITY",
    "PROGRAM",
    "READ_ONLY",
    "READ_WRITE",
    "REPEAT",
    "RESOURCE",
    "RETAIN",
    "RETURN",
    "R_EDGE",
    "SINGLE",
    "STEP",
    "STRUCT",
    "TASK",
    "THEN",
    "TO",
    "TRANSITION",
    "TRUE",
    "TYPE",
    "UNTIL",
    "VAR",
    "VAR_ACCESS",
    "VAR_CONFIG",
    "VAR_EXTERNAL",
    "VAR_GLOBAL",
    "VAR_INPUT",
    "VAR_IN_OUT",
    "VAR_OUTPUT",
    "VAR_TEMP",
    "WHILE",
    "WITH",
    "XOR",
};

constexpr std::string_view kIlOperators[] = {
    "ADD",
    "AND",
    "ANDN",
    "CAL",
    "CALC",
    "CALCN",
    "DIV",
    "EQ",
    "GE",
    "GT",
    "JMP",
    "JMPC",
    "JMPCN",
    "LD",
    "LDN",
    "LE",
    "LT",
    "MOD",
    "MUL",
    "NE",
    "NOT",
    "OR",
    "ORN",
    "R",
    "RET",
    "RETC",
    "RETCN",
    "S",
    "ST",
    "STN",
    "SUB",
    "XOR",
    "XORN",
};

constexpr std::string_view kTypeNames[] = {
    "ANY",
    "ANY_BIT",
    "ANY_DATE",
    "ANY_DERIVED",
    "ANY_ELEMENTARY",
    "ANY_INT",
    "ANY_MAGNITUDE",
    "ANY_NUM",
    "ANY_REAL",
    "ANY_STRING",
    "BOOL",
    "BYTE",
    "CHAR",
    "DATE",
    "DATE_AND_TIME",
    "DINT",
    "DT",
    "DWORD",
    "INT",
    "LDATE",
    "LDATE_AND_TIME",
    "LDT",
    "LINT",
    "LREAL",
    "LTIME",
    "LTIME_OF_DAY",
    "LTOD",
    "LWORD",
    "REAL",
    "SINT",
    "STRING",
    "TIME",
    "TIME_OF_DAY",
    "TOD",
    "UDINT",
    "UINT",
    "ULINT",
    "USINT",
    "WCHAR",
    "WORD",
    "WSTRING",
    "ANY_SIGNED",
    "ANY_UNSIGNED",
    "ANY_DURATION",
    "ANY_CHAR",
    "ANY_CHARS",
};

constexpr qsizetype kLongestTableWord = 24;

template<size_t N> constexpr bool allFit(const std::string_view (&table)[N])
{
    return std::all_of(std::begin(table), std::end(table), [](std::string_view word) {
        return std::ssize(word) <= kLongestTableWord;
    });
}
static_assert(allFit(kKeywords) && allFit(kIlOperators) && allFit(kTypeNames));

// Upper-cases an ASCII word; anything else, or a word longer than every table entry, makes it
// match no entry (and a long name costs no allocation).
std::string upperAscii(QStringView word)
{
    if (word.size() > kLongestTableWord)
        return {};
    std::string out;
    out.reserve(static_cast<size_t>(word.size()));
    for (const QChar c : word) {
        const char16_t u = c.unicode();
        if (u > 0x7f)
            return {};
        out.push_back(static_cast<char>(u >= u'a' && u <= u'z' ? u - 32 : u));
    }
    return out;
}

// The tables as hash sets, built once: the lexer looks up every word it reads, and a linear
// search through them was half the time of reading a large file.
using WordSet = std::unordered_set<std::string_view>;
template<size_t N> WordSet setOf(const std::string_view (&table)[N])
{
    return WordSet(std::begin(table), std::end(table));
}

bool isKeywordUpper(const std::string &upper)
{
    static const WordSet keywords = setOf(kKeywords);
    static const WordSet ilOperators = setOf(kIlOperators);
    return keywords.contains(upper) || ilOperators.contains(upper);
}

bool isTypeNameUpper(const std::string &upper)
{
    static const WordSet typeNames = setOf(kTypeNames);
    return typeNames.contains(upper);
}

bool isIlOperatorUpper(const std::string &upper)
{
    static const WordSet ilOperators = setOf(kIlOperators);
    return ilOperators.contains(upper);
}

bool isLetter(QChar c)
{
    const char16_t u = c.unicode();
    return (u >= u'a' && u <= u'z') || (u >= u'A' && u <= u'Z') || u == u'_';
}

bool isDigit(QChar c)
{
    return c.unicode() >= u'0' && c.unicode() <= u'9';
}

bool isWordChar(QChar c)
{
    return isLetter(c) || isDigit(c);
}

bool isSpace(QChar c)
{
    const char16_t u = c.unicode();
    return u == u' ' || u == u'\t' || u == u'\n' || u == u'\r' || u == u'\f' || u == u'\v' || u == 0xa0 || u == 0xfeff
        || u == 0x3000;
}

// Operators, longest first so ":=" wins over ":".
constexpr std::array<std::u16string_view, 24> kOperators {{
    u":=",
    u"=>",
    u"**",
    u"<>",
    u"<=",
    u">=",
    u"..",
    u"+",
    u"-",
    u"*",
    u"/",
    u"=",
    u"<",
    u">",
    u"&",
    u"(",
    u")",
    u"[",
    u"]",
    u",",
    u";",
    u":",
    u".",
    u"^", // dereference (CODESYS pointers, IEC REF_TO)
}};

class Lexer
{
public:
    Lexer(QStringView text, LexState &state)
        : m_text(text)
        , m_state(state)
    { }

    std::vector<Token> run()
    {
        if (m_state.commentDepth > 0)
            blockComment(0);
        else if (m_state.inPragma)
            pragma(0);
        while (m_pos < m_text.size()) {
            if (isSpace(m_text[m_pos])) {
                ++m_pos;
                continue;
            }
            next();
        }
        return std::move(m_tokens);
    }

private:
    QChar at(qsizetype i) const { return i < m_text.size() ? m_text[i] : QChar(); }
    bool startsWith(qsizetype i, std::u16string_view s) const
    {
        // Compared in place: a slice per call cost a tenth of the fuzzer's time.
        const auto length = static_cast<qsizetype>(s.size());
        if (i < 0 || m_text.size() - i < length)
            return false;
        for (qsizetype k = 0; k < length; ++k) {
            if (m_text[i + k].unicode() != s[std::size_t(k)])
                return false;
        }
        return true;
    }

    void push(TokenKind kind, qsizetype start)
    {
        if (m_pos > start) // an empty line inside a comment has no token
            m_tokens.push_back({kind, int(start), int(m_pos - start)});
    }

    void next()
    {
        const qsizetype start = m_pos;
        const QChar c = m_text[m_pos];
        if (startsWith(m_pos, u"(*")) {
            m_state.commentDepth = 1;
            m_pos += 2;
            blockComment(start);
        } else if (startsWith(m_pos, u"//")) {
            while (m_pos < m_text.size() && m_text[m_pos] != QLatin1Char('\n'))
                ++m_pos;
            push(TokenKind::Comment, start);
        } else if (c == QLatin1Char('{')) {
            m_state.inPragma = true;
            ++m_pos;
            pragma(start);
        } else if (isLetter(c)) {
            word();
        } else if (isDigit(c)) {
            number(start);
        } else if (c == QLatin1Char('\'') || c == QLatin1Char('"')) {
            string(start, c == QLatin1Char('\'') ? TokenKind::StringLiteral : TokenKind::WStringLiteral);
        } else if (c == QLatin1Char('%')) {
            address();
        } else {
            op();
        }
    }

    // Continues a (* *) comment, counting nesting, from m_pos; the token starts at `start`.
    void blockComment(qsizetype start)
    {
        while (m_pos < m_text.size() && m_state.commentDepth > 0) {
            if (startsWith(m_pos, u"(*")) {
                ++m_state.commentDepth;
                m_pos += 2;
            } else if (startsWith(m_pos, u"*)")) {
                --m_state.commentDepth;
                m_pos += 2;
            } else {
                ++m_pos;
            }
        }
        push(TokenKind::Comment, start);
    }

    void pragma(qsizetype start)
    {
        while (m_pos < m_text.size() && m_text[m_pos] != QLatin1Char('}'))
            ++m_pos;
        if (m_pos < m_text.size()) {
            ++m_pos;
            m_state.inPragma = false;
        }
        push(TokenKind::Pragma, start);
    }

    void word()
    {
        const qsizetype start = m_pos;
        while (m_pos < m_text.size() && isWordChar(m_text[m_pos]))
            ++m_pos;
        const QStringView name = m_text.mid(start, m_pos - start);
        if (at(m_pos) == QLatin1Char('#')) {
            typedLiteral(start, name);
            return;
        }
        const std::string upper = upperAscii(name);
        if (isKeywordUpper(upper))
            push(TokenKind::Keyword, start);
        else if (isTypeNameUpper(upper))
            push(TokenKind::TypeName, start);
        else
            push(TokenKind::Identifier, start);
    }

    // Consumes characters while `accept` holds.
    template<typename Accept> void skipWhile(Accept accept)
    {
        while (m_pos < m_text.size() && accept(m_text[m_pos]))
            ++m_pos;
    }

    void skipSign()
    {
        if (at(m_pos) == QLatin1Char('-') || at(m_pos) == QLatin1Char('+'))
            ++m_pos;
    }

    // Emits `kind` when `valid`, an Error token otherwise.
    void pushChecked(bool valid, TokenKind kind, qsizetype start) { push(valid ? kind : TokenKind::Error, start); }

    void typedLiteral(qsizetype start, QStringView prefix)
    {
        ++m_pos; // '#'
        const qsizetype bodyStart = m_pos;
        const auto body = [&] { return m_text.mid(bodyStart, m_pos - bodyStart); };
        switch (literalFamilyOfPrefix(prefix)) {
        case LiteralFamily::Duration:
            skipSign();
            skipWhile([](QChar c) { return isWordChar(c) || c == QLatin1Char('.'); });
            pushChecked(decodeDuration(body()).has_value(), TokenKind::TimeLiteral, start);
            return;
        case LiteralFamily::Date:
            skipWhile([](QChar c) { return isDigit(c) || c == QLatin1Char('_') || c == QLatin1Char('-'); });
            pushChecked(decodeDate(body()).has_value(), TokenKind::DateTimeLiteral, start);
            return;
        case LiteralFamily::TimeOfDay:
            skipWhile([](QChar c) {
                return isDigit(c) || c == QLatin1Char('_') || c == QLatin1Char(':') || c == QLatin1Char('.');
            });
            pushChecked(decodeTimeOfDay(body()).has_value(), TokenKind::DateTimeLiteral, start);
            return;
        case LiteralFamily::DateAndTime:
            skipWhile([](QChar c) {
                return isDigit(c) || c == QLatin1Char('_') || c == QLatin1Char(':') || c == QLatin1Char('.')
                    || c == QLatin1Char('-');
            });
            pushChecked(decodeDateAndTime(body()).has_value(), TokenKind::DateTimeLiteral, start);
            return;
        case LiteralFamily::String:
        case LiteralFamily::WString:
            if (at(m_pos) == QLatin1Char('\'') || at(m_pos) == QLatin1Char('"')) {
                string(start, at(m_pos) == QLatin1Char('\'') ? TokenKind::StringLiteral : TokenKind::WStringLiteral);
                return;
            }
            push(TokenKind::Error, start);
            return;
        case LiteralFamily::Bool:
            if (isLetter(at(m_pos))) {
                skipWhile(isWordChar);
                const std::string upper = upperAscii(body());
                pushChecked(upper == "TRUE" || upper == "FALSE", TokenKind::IntegerLiteral, start);
                return;
            }
            typedNumber(start, false);
            return;
        case LiteralFamily::Integer:
            typedNumber(start, false);
            return;
        case LiteralFamily::Real:
            typedNumber(start, true);
            return;
        case LiteralFamily::Unknown:
        case LiteralFamily::None:
            // An enumerated value qualified by its type: Color#Red is one name.
            if (isLetter(at(m_pos))) {
                skipWhile(isWordChar);
                push(TokenKind::Identifier, start);
                return;
            }
            push(TokenKind::Error, start);
            return;
        }
    }

    void typedNumber(qsizetype start, bool real)
    {
        skipSign();
        const qsizetype numberStart = m_pos;
        if (!isDigit(at(m_pos))) {
            push(TokenKind::Error, start);
            return;
        }
        const TokenKind kind = scanNumber(numberStart);
        if (kind == TokenKind::Error) {
            push(TokenKind::Error, start);
            return;
        }
        if (real)
            push(TokenKind::RealLiteral, start);
        else
            pushChecked(kind == TokenKind::IntegerLiteral, TokenKind::IntegerLiteral, start);
    }

    // After a member access's dot, digits are a bit number (x.0), never a fraction: "x.0.25" is
    // bit 25 of x.0, so that it prints back as it reads (found by fuzz_typetext).
    bool afterMemberDot() const
    {
        for (auto it = m_tokens.rbegin(); it != m_tokens.rend(); ++it) {
            if (it->kind != TokenKind::Comment && it->kind != TokenKind::Pragma)
                return it->kind == TokenKind::Operator && it->length == 1 && m_text[it->offset] == QLatin1Char('.');
        }
        return false;
    }

    void number(qsizetype start)
    {
        if (!afterMemberDot()) {
            push(scanNumber(start), start);
            return;
        }
        m_pos = start;
        skipWhile(isDigit);
        if (isWordChar(at(m_pos))) { // x.0abc
            skipWhile(isWordChar);
            push(TokenKind::Error, start);
            return;
        }
        push(TokenKind::IntegerLiteral, start);
    }

    // Scans 42, 16#FF, 1.5E3 from `start`; returns its kind (Error when malformed).
    TokenKind scanNumber(qsizetype start)
    {
        m_pos = start;
        skipWhile([](QChar c) { return isDigit(c) || c == QLatin1Char('_'); });
        if (at(m_pos) == QLatin1Char('#')) {
            ++m_pos;
            skipWhile(isWordChar);
            return decodeInteger(m_text.mid(start, m_pos - start)) ? TokenKind::IntegerLiteral : TokenKind::Error;
        }
        bool real = false;
        // "1..5" is a range, and "1.x" is not a number: a fraction needs a digit after the dot.
        if (at(m_pos) == QLatin1Char('.') && isDigit(at(m_pos + 1))) {
            real = true;
            ++m_pos;
            skipWhile([](QChar c) { return isDigit(c) || c == QLatin1Char('_'); });
        }
        if ((at(m_pos) == QLatin1Char('e') || at(m_pos) == QLatin1Char('E'))) {
            qsizetype e = m_pos + 1;
            if (at(e) == QLatin1Char('+') || at(e) == QLatin1Char('-'))
                ++e;
            if (isDigit(at(e))) {
                real = true;
                m_pos = e;
                skipWhile(isDigit);
            }
        }
        if (isLetter(at(m_pos))) { // 12abc
            skipWhile(isWordChar);
            return TokenKind::Error;
        }
        const QStringView text = m_text.mid(start, m_pos - start);
        if (real)
            return decodeReal(text) ? TokenKind::RealLiteral : TokenKind::Error;
        return decodeInteger(text) ? TokenKind::IntegerLiteral : TokenKind::Error;
    }

    // A string literal from m_pos (the quote); ends at its closing quote or, unterminated, at the
    // end of the line, which is an Error.
    void string(qsizetype start, TokenKind kind)
    {
        const QChar quote = m_text[m_pos];
        const qsizetype quoteStart = m_pos;
        ++m_pos;
        bool closed = false;
        while (m_pos < m_text.size() && m_text[m_pos] != QLatin1Char('\n')) {
            const QChar c = m_text[m_pos++];
            if (c == QLatin1Char('$') && m_pos < m_text.size() && m_text[m_pos] != QLatin1Char('\n')) {
                ++m_pos;
            } else if (c == quote) {
                closed = true;
                break;
            }
        }
        pushChecked(closed && decodeString(m_text.mid(quoteStart, m_pos - quoteStart)).has_value(), kind, start);
    }

    // %IX0.0, %QW3, %MD10, %I*, %IX1.2.3
    void address()
    {
        const qsizetype start = m_pos++;
        const QChar area = at(m_pos).toUpper();
        if (area != QLatin1Char('I') && area != QLatin1Char('Q') && area != QLatin1Char('M')) {
            skipWhile([](QChar c) { return isWordChar(c) || c == QLatin1Char('.'); });
            push(TokenKind::Error, start);
            return;
        }
        ++m_pos;
        const QChar size = at(m_pos).toUpper();
        if (size == QLatin1Char('X') || size == QLatin1Char('B') || size == QLatin1Char('W') || size == QLatin1Char('D')
            || size == QLatin1Char('L'))
            ++m_pos;
        if (at(m_pos) == QLatin1Char('*')) {
            ++m_pos;
            push(TokenKind::DirectAddress, start);
            return;
        }
        bool valid = isDigit(at(m_pos));
        skipWhile(isDigit);
        while (valid && at(m_pos) == QLatin1Char('.') && isDigit(at(m_pos + 1))) {
            ++m_pos;
            skipWhile(isDigit);
        }
        if (isLetter(at(m_pos))) {
            skipWhile(isWordChar);
            valid = false;
        }
        pushChecked(valid, TokenKind::DirectAddress, start);
    }

    void op()
    {
        const qsizetype start = m_pos;
        for (const auto &candidate : kOperators) {
            if (startsWith(m_pos, candidate)) {
                m_pos += static_cast<qsizetype>(candidate.size());
                push(TokenKind::Operator, start);
                return;
            }
        }
        ++m_pos;
        push(TokenKind::Error, start);
    }

    QStringView m_text;
    LexState &m_state;
    qsizetype m_pos = 0;
    std::vector<Token> m_tokens;
};

} // namespace

std::vector<Token> tokenize(QStringView text, LexState &state)
{
    return Lexer(text, state).run();
}

std::vector<Token> tokenize(QStringView text)
{
    LexState state;
    return tokenize(text, state);
}

bool isKeyword(QStringView word)
{
    return isKeywordUpper(upperAscii(word));
}

bool isTypeName(QStringView word)
{
    return isTypeNameUpper(upperAscii(word));
}

bool isIlOperator(QStringView word)
{
    return isIlOperatorUpper(upperAscii(word));
}

bool hasIdentifierShape(QStringView word)
{
    if (word.isEmpty() || word.back() == QLatin1Char('_'))
        return false;
    const auto isAsciiLetter = [](QChar c) {
        return (c >= QLatin1Char('A') && c <= QLatin1Char('Z')) || (c >= QLatin1Char('a') && c <= QLatin1Char('z'));
    };
    const auto isAsciiDigit = [](QChar c) { return c >= QLatin1Char('0') && c <= QLatin1Char('9'); };
    if (!isAsciiLetter(word.front()) && word.front() != QLatin1Char('_'))
        return false;
    for (qsizetype i = 1; i < word.size(); ++i) {
        const QChar c = word[i];
        if (c == QLatin1Char('_')) {
            if (word[i - 1] == QLatin1Char('_'))
                return false;
        } else if (!isAsciiLetter(c) && !isAsciiDigit(c)) {
            return false;
        }
    }
    return true;
}

bool isIecIdentifier(QStringView word)
{
    return hasIdentifierShape(word) && !isKeyword(word) && !isTypeName(word);
}

} // namespace iec::interp
