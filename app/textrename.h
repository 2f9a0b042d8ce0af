#pragma once

#include "interpreter/compiler/lexer.h"
#include "model/undo/variablerename.h"

#include <QString>
#include <QStringView>

#include <vector>

// The text half of renames: ST and IL text read through the shared lexer, so that comments,
// strings and pragmas never change, and identifiers replaced at their token's offset.
namespace iec::app {

using Renames = std::vector<model::VariableRename>;

enum class TextDialect { ST, IL };

// The new name `renames` gives `word` (compared case-insensitively); nullptr when none does.
[[nodiscard]] const QString *newNameOf(const Renames &renames, QStringView word);

// Replaces every reference to the old names by the new ones, all at once (a swap of two names
// works): identifiers that match as a whole word, case-insensitively (IEC names are). Kept as they
// are: a member after '.' (Timer.Q is another name), a formal parameter of a call (Timer(IN := x)
// names the callee's input), and in IL a jump label (`Loop:`, `JMP Loop`).
[[nodiscard]] QString renameIdentifiers(const QString &text, const Renames &renames, TextDialect dialect = TextDialect::ST);
[[nodiscard]] QString renameIdentifier(const QString &text, const QString &oldName, const QString &newName);

// A text as the shared lexer's tokens, and replacements of whole tokens collected while walking
// them forward; result() is the text with the replacements made.
class TokenText
{
public:
    explicit TokenText(const QString &text)
        : m_text(text)
        , m_tokens(interp::tokenize(text))
    { }

    [[nodiscard]] size_t size() const { return m_tokens.size(); }
    [[nodiscard]] const interp::Token &at(size_t i) const { return m_tokens[i]; }
    [[nodiscard]] QStringView word(size_t i) const
    {
        return QStringView(m_text).mid(m_tokens[i].offset, m_tokens[i].length);
    }
    [[nodiscard]] bool is(size_t i, interp::TokenKind kind) const { return i < size() && m_tokens[i].kind == kind; }
    [[nodiscard]] bool isOperator(size_t i, QStringView op) const
    {
        return is(i, interp::TokenKind::Operator) && word(i) == op;
    }
    [[nodiscard]] bool isAssignmentAfter(size_t i) const
    {
        return isOperator(i + 1, u":=") || isOperator(i + 1, u"=>");
    }
    // No token before it on its line.
    [[nodiscard]] bool startsLine(size_t i) const;

    // Replacements are made in token order: every walker moves forward only.
    void replace(size_t i, const QString &with) { m_edits.push_back({i, with}); }
    [[nodiscard]] QString result() const;

private:
    struct Edit {
        size_t token;
        QString text;
    };
    const QString &m_text;
    std::vector<interp::Token> m_tokens;
    std::vector<Edit> m_edits;
};

} // namespace iec::app
