#include "editors/text/bracketmatcher.h"

namespace iec::editors {

namespace {

QChar partnerOf(QChar c)
{
    switch (c.unicode()) {
    case '(':
        return QLatin1Char(')');
    case ')':
        return QLatin1Char('(');
    case '[':
        return QLatin1Char(']');
    case ']':
        return QLatin1Char('[');
    default:
        return {};
    }
}

} // namespace

int matchingBracket(QStringView text, int position, interp::LexState state)
{
    if (position < 0 || position >= text.size())
        return kNoBracket;
    const QChar bracket = text[position];
    const QChar partner = partnerOf(bracket);
    if (partner.isNull())
        return kNoBracket;

    // Only the brackets the lexer reports as operators; a bracket inside a comment or string is text.
    const std::vector<interp::Token> tokens = interp::tokenize(text, state);
    std::vector<int> brackets; // positions of single-character bracket tokens of this kind
    int self = -1;
    for (const interp::Token &token : tokens) {
        if (token.kind != interp::TokenKind::Operator || token.length != 1)
            continue;
        const QChar c = text[token.offset];
        if (c != bracket && c != partner)
            continue;
        if (token.offset == position)
            self = int(brackets.size());
        brackets.push_back(token.offset);
    }
    if (self < 0)
        return kNoBracket;

    const bool forward = bracket == QLatin1Char('(') || bracket == QLatin1Char('[');
    const int step = forward ? 1 : -1;
    int depth = 0;
    for (int i = self; i >= 0 && i < int(brackets.size()); i += step) {
        depth += text[brackets[size_t(i)]] == bracket ? 1 : -1;
        if (depth == 0)
            return brackets[size_t(i)];
    }
    return kUnmatchedBracket;
}

} // namespace iec::editors
