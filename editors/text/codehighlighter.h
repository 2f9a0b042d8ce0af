#pragma once

#include "editors/text/textlanguage.h"
#include "interpreter/compiler/lexer.h"

#include <QSyntaxHighlighter>
#include <QTextCharFormat>

namespace iec::editors {

// Colours ST and IL with the interpreter's lexer. Each block's user state holds the LexState at
// its end (comment depth, pragma), so QSyntaxHighlighter re-lexes only the edited line and then
// the following lines for as long as their starting state changes: typing inside a line costs
// one line; opening a (* comment costs the lines it swallows.
class CodeHighlighter : public QSyntaxHighlighter
{
    Q_OBJECT

public:
    // The format a token gets. Beyond the lexer's kinds: the names of standard functions and
    // function blocks, and IL operator words in ST (ordinary names there).
    enum class Style {
        Plain,
        Keyword,
        TypeName,
        Number,
        TimeLiteral,
        String,
        DirectAddress,
        Operator,
        Comment,
        Pragma,
        Error,
        StandardPou
    };

    explicit CodeHighlighter(TextLanguage language, QTextDocument *document);

    [[nodiscard]] TextLanguage language() const { return m_language; }
    void setLanguage(TextLanguage language);

    [[nodiscard]] static QTextCharFormat format(Style style);
    [[nodiscard]] Style styleOf(interp::TokenKind kind, QStringView word) const;

    // The lexer state at the end of a block (the start state of the next one).
    [[nodiscard]] static interp::LexState stateAfter(const QTextBlock &block);
    [[nodiscard]] static int encode(interp::LexState state);
    [[nodiscard]] static interp::LexState decode(int blockState);

    // How many times highlightBlock ran since the last reset (tests and the bench).
    [[nodiscard]] int highlightedBlockCount() const { return m_highlightedBlocks; }
    void resetHighlightedBlockCount() { m_highlightedBlocks = 0; }

protected:
    void highlightBlock(const QString &text) override;

private:
    TextLanguage m_language;
    int m_highlightedBlocks = 0;
};

} // namespace iec::editors
