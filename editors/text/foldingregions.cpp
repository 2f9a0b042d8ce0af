#include "editors/text/foldingregions.h"

#include "editors/text/blockrules.h"
#include "interpreter/compiler/lexer.h"

#include <algorithm>

namespace iec::editors {

QList<FoldRange> foldingRanges(QStringView text, TextLanguage language)
{
    interp::LexState state;
    const std::vector<interp::Token> tokens = interp::tokenize(text, state);

    QList<FoldRange> ranges;
    struct Open {
        QString closer;
        int line;
    };
    QList<Open> stack;
    int line = 0;
    int scanned = 0; // text[0, scanned) has been counted into `line`
    auto lineAt = [&](int offset) {
        for (; scanned < offset; ++scanned) {
            if (text[scanned] == QLatin1Char('\n'))
                ++line;
        }
        return line;
    };

    for (const interp::Token &token : tokens) {
        const int first = lineAt(token.offset);
        if (token.kind == interp::TokenKind::Comment) {
            const int last = lineAt(token.offset + token.length - 1);
            if (last > first)
                ranges.append({first, last});
            continue;
        }
        if (token.kind != interp::TokenKind::Keyword && token.kind != interp::TokenKind::Identifier)
            continue;
        const QString word = text.mid(token.offset, token.length).toString().toUpper();
        if (word.startsWith(QLatin1String("END_"))) {
            // Close the nearest block this keyword ends; blocks left open inside it are errors.
            for (qsizetype i = stack.size() - 1; i >= 0; --i) {
                if (stack[i].closer == word) {
                    if (first > stack[i].line)
                        ranges.append({stack[i].line, first});
                    stack.resize(i);
                    break;
                }
            }
            continue;
        }
        const QString closer = blockCloserFor(word, language);
        if (!closer.isEmpty())
            stack.append({closer, first});
    }
    std::sort(ranges.begin(), ranges.end(), [](const FoldRange &a, const FoldRange &b) {
        return a.firstLine != b.firstLine ? a.firstLine < b.firstLine : a.lastLine > b.lastLine;
    });
    return ranges;
}

} // namespace iec::editors
