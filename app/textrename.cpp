#include "app/textrename.h"

#include <algorithm>

namespace iec::app {

const QString *newNameOf(const Renames &renames, QStringView word)
{
    for (const model::VariableRename &rename : renames) {
        if (word.compare(rename.oldName, Qt::CaseInsensitive) == 0)
            return &rename.newName;
    }
    return nullptr;
}

bool TokenText::startsLine(size_t i) const
{
    if (i == 0)
        return true;
    const int from = m_tokens[i - 1].offset + m_tokens[i - 1].length;
    return QStringView(m_text).mid(from, m_tokens[i].offset - from).contains(QLatin1Char('\n'));
}

QString TokenText::result() const
{
    if (m_edits.empty())
        return m_text;
    QString out;
    int copiedUpTo = 0;
    for (const Edit &edit : m_edits) { // in token order: every walker moves forward only
        const interp::Token &token = m_tokens[edit.token];
        out += QStringView(m_text).mid(copiedUpTo, token.offset - copiedUpTo);
        out += edit.text;
        copiedUpTo = token.offset + token.length;
    }
    out += QStringView(m_text).mid(copiedUpTo);
    return out;
}

namespace {

bool isIlLabel(const TokenText &tokens, size_t i)
{
    const bool definition = tokens.startsLine(i) && tokens.isOperator(i + 1, u":");
    const bool jumpTarget = i > 0 && tokens.is(i - 1, interp::TokenKind::Keyword)
        && tokens.word(i - 1).startsWith(QLatin1String("JMP"), Qt::CaseInsensitive);
    return definition || jumpTarget;
}

} // namespace

QString renameIdentifiers(const QString &text, const Renames &renames, TextDialect dialect)
{
    if (renames.empty())
        return text;
    TokenText tokens(text);
    int parentheses = 0;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (tokens.isOperator(i, u"("))
            ++parentheses;
        else if (tokens.isOperator(i, u")"))
            parentheses = std::max(0, parentheses - 1);
        if (!tokens.is(i, interp::TokenKind::Identifier))
            continue;
        const bool member = i > 0 && tokens.isOperator(i - 1, u".");
        // Assignments never stand inside parentheses; there `Name :=` is a call's formal parameter.
        const bool formalParameter = parentheses > 0 && tokens.isAssignmentAfter(i);
        const bool label = dialect == TextDialect::IL && isIlLabel(tokens, i);
        if (member || formalParameter || label)
            continue;
        if (const QString *newName = newNameOf(renames, tokens.word(i)))
            tokens.replace(i, *newName);
    }
    return tokens.result();
}

QString renameIdentifier(const QString &text, const QString &oldName, const QString &newName)
{
    return renameIdentifiers(text, {{oldName, newName}});
}

} // namespace iec::app
