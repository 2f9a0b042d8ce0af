#pragma once

#include "interpreter/compiler/lexer.h"

#include <QString>
#include <QStringView>

#include <vector>

// Reading IEC text by its tokens to cut it into the pieces the project model keeps as text (a
// POU's body, an action's, a method's), exactly as written.
namespace iec::interp::frontend {

// The significant tokens of the source (no comments or pragmas) with the words they spell.
class TokenCursor
{
public:
    explicit TokenCursor(QStringView text)
        : m_text(text)
    {
        for (const Token &t : tokenize(text)) {
            if (t.kind != TokenKind::Comment && t.kind != TokenKind::Pragma)
                m_tokens.push_back(t);
        }
    }
    bool atEnd() const { return m_pos >= m_tokens.size(); }
    bool is(const char *word) const
    {
        return !atEnd() && text().compare(QLatin1String(word), Qt::CaseInsensitive) == 0;
    }
    QStringView text() const
    {
        return atEnd() ? QStringView() : m_text.mid(m_tokens[m_pos].offset, m_tokens[m_pos].length);
    }
    int start() const { return atEnd() ? int(m_text.size()) : m_tokens[m_pos].offset; }
    int end() const { return m_tokens[m_pos].offset + m_tokens[m_pos].length; }
    void next() { ++m_pos; }
    // Moves past the next `word`; returns the offset just after it.
    int skipPast(const char *word)
    {
        while (!atEnd() && !is(word))
            next();
        const int after = atEnd() ? int(m_text.size()) : end();
        next();
        return after;
    }
    // VAR, VAR_INPUT, VAR_GLOBAL ... (every section keyword starts with VAR and then '_' or ends)
    bool isVarSection() const
    {
        if (atEnd() || !text().startsWith(QLatin1String("VAR"), Qt::CaseInsensitive))
            return false;
        return m_tokens[m_pos].kind == TokenKind::Keyword && (text().size() == 3 || text()[3] == u'_');
    }
    bool isName() const { return !atEnd() && m_tokens[m_pos].kind == TokenKind::Identifier; }
    // Whether a name follows this token (INTERFACE I starts an interface; "Interface := 1;" does not).
    bool nameFollows() const { return m_pos + 1 < m_tokens.size() && m_tokens[m_pos + 1].kind == TokenKind::Identifier; }
    // METHOD or PROPERTY followed by a name or a qualifier, as the parser reads a member
    // ("Method := 1;" is a statement).
    bool startsMember() const
    {
        if ((!is("METHOD") && !is("PROPERTY")) || m_pos + 1 >= m_tokens.size())
            return false;
        const TokenKind next = m_tokens[m_pos + 1].kind;
        return next == TokenKind::Identifier || next == TokenKind::Keyword;
    }
    int lineEndAfter(int offset) const
    {
        const qsizetype newline = m_text.indexOf(u'\n', offset);
        return newline < 0 ? int(m_text.size()) : int(newline);
    }

private:
    QStringView m_text;
    std::vector<Token> m_tokens;
    size_t m_pos = 0;
};

// A body as written: without the line break that follows the declarations and without trailing
// blank lines.
inline QString bodyText(QStringView source, int from, int to)
{
    QStringView body = source.mid(from, to - from);
    // The rest of the line before it (END_VAR's), and empty lines (where a CoDeSys 2.3 export had
    // its (* @END_DECLARATION *) marker, sourcefile.h).
    for (qsizetype newline = body.indexOf(u'\n'); newline >= 0 && body.left(newline).trimmed().isEmpty();
         newline = body.indexOf(u'\n'))
        body = body.mid(newline + 1);
    while (!body.isEmpty() && body.back().isSpace())
        body.chop(1);
    return body.toString();
}

} // namespace iec::interp::frontend
