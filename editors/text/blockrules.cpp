#include "editors/text/blockrules.h"

#include "interpreter/compiler/lexer.h"

#include <QList>

namespace iec::editors {

namespace {

using interp::TokenKind;

struct Word {
    QString upper;
    TokenKind kind;
};

// The tokens of one line that are not comments or pragmas, upper-cased.
QList<Word> significantWords(QStringView line)
{
    interp::LexState state;
    QList<Word> words;
    for (const interp::Token &token : interp::tokenize(line, state)) {
        if (token.kind == TokenKind::Comment || token.kind == TokenKind::Pragma)
            continue;
        words.append({line.mid(token.offset, token.length).toString().toUpper(), token.kind});
    }
    return words;
}

bool isVarKeyword(const QString &word)
{
    return word == QLatin1String("VAR") || word.startsWith(QLatin1String("VAR_"));
}

bool isPouHeader(const QString &word)
{
    return word == QLatin1String("PROGRAM") || word == QLatin1String("FUNCTION_BLOCK")
        || word == QLatin1String("FUNCTION") || word == QLatin1String("METHOD") || word == QLatin1String("ACTION");
}

QStringView leadingWhitespace(QStringView line)
{
    int i = 0;
    while (i < line.size() && (line[i] == QLatin1Char(' ') || line[i] == QLatin1Char('\t')))
        ++i;
    return line.left(i);
}

// The block a line opens, if any.
struct Opening {
    QStringList closers; // innermost first, each on its own line
    bool indentInside = false;
    bool lowerCase = false; // the opener was typed in lower case: close in lower case
};

std::optional<Opening> openingOf(QStringView line, TextLanguage language)
{
    const QList<Word> words = significantWords(line);
    if (words.isEmpty())
        return std::nullopt;
    const QString &first = words.first().upper;
    const QString &last = words.last().upper;
    bool lower = false;
    {
        interp::LexState state;
        for (const interp::Token &token : interp::tokenize(line, state)) {
            if (token.kind != TokenKind::Comment && token.kind != TokenKind::Pragma) {
                const QStringView text = line.mid(token.offset, token.length);
                lower = text.toString() == text.toString().toLower() && text.toString() != text.toString().toUpper();
                break;
            }
        }
    }
    Opening opening;
    opening.lowerCase = lower;
    const bool st = language == TextLanguage::ST;
    if (st && first == QLatin1String("IF") && last == QLatin1String("THEN")) {
        opening.closers = {QStringLiteral("END_IF")};
        opening.indentInside = true;
    } else if (st && first == QLatin1String("ELSIF") && last == QLatin1String("THEN")) {
        opening.indentInside = true;
    } else if (st && first == QLatin1String("ELSE") && words.size() == 1) {
        opening.indentInside = true;
    } else if (st && first == QLatin1String("CASE") && last == QLatin1String("OF")) {
        opening.closers = {QStringLiteral("END_CASE")};
        opening.indentInside = true;
    } else if (st && first == QLatin1String("FOR") && last == QLatin1String("DO")) {
        opening.closers = {QStringLiteral("END_FOR")};
        opening.indentInside = true;
    } else if (st && first == QLatin1String("WHILE") && last == QLatin1String("DO")) {
        opening.closers = {QStringLiteral("END_WHILE")};
        opening.indentInside = true;
    } else if (st && first == QLatin1String("REPEAT") && words.size() == 1) {
        opening.closers = {QStringLiteral("UNTIL"), QStringLiteral("END_REPEAT")};
        opening.indentInside = true;
    } else if (isVarKeyword(first)) {
        opening.closers = {QStringLiteral("END_VAR")};
        opening.indentInside = true;
    } else if (first == QLatin1String("TYPE")) {
        if (last == QLatin1String("STRUCT")) {
            opening.closers = {QStringLiteral("END_STRUCT"), QStringLiteral("END_TYPE")};
            opening.indentInside = true;
        } else {
            opening.closers = {QStringLiteral("END_TYPE")};
        }
    } else if (first == QLatin1String("STRUCT") || last == QLatin1String("STRUCT")) {
        opening.closers = {QStringLiteral("END_STRUCT")};
        opening.indentInside = true;
    } else if (isPouHeader(first) && words.size() >= 2) {
        opening.closers = {QStringLiteral("END_") + first};
    } else if (st && words.size() >= 2 && words.last().kind == TokenKind::Operator && last == QLatin1String(":")
        && (words.first().kind == TokenKind::IntegerLiteral || words.first().kind == TokenKind::Identifier)) {
        opening.indentInside = true; // a CASE label: "1:", "Red, Green:", "10..20:"
    } else {
        return std::nullopt;
    }
    return opening;
}

QStringView nextNonBlankLine(QStringView text)
{
    while (!text.isEmpty()) {
        const qsizetype end = text.indexOf(QLatin1Char('\n'));
        const QStringView line = end < 0 ? text : text.left(end);
        if (!line.trimmed().isEmpty())
            return line;
        if (end < 0)
            break;
        text = text.mid(end + 1);
    }
    return {};
}

bool startsWithWord(QStringView text, const QString &word)
{
    if (!text.startsWith(word, Qt::CaseInsensitive))
        return false;
    return text.size() == word.size()
        || !(text[word.size()].isLetterOrNumber() || text[word.size()] == QLatin1Char('_'));
}

bool containsWord(QStringView text, const QString &word)
{
    qsizetype from = 0;
    while ((from = text.indexOf(word, from, Qt::CaseInsensitive)) >= 0) {
        const bool startOk = from == 0 || !(text[from - 1].isLetterOrNumber() || text[from - 1] == QLatin1Char('_'));
        if (startOk && startsWithWord(text.mid(from), word))
            return true;
        from += word.size();
    }
    return false;
}

bool isClosingKeyword(const QString &word)
{
    return word == QLatin1String("END_IF") || word == QLatin1String("END_CASE") || word == QLatin1String("END_FOR")
        || word == QLatin1String("END_WHILE") || word == QLatin1String("END_REPEAT") || word == QLatin1String("UNTIL")
        || word == QLatin1String("ELSE") || word == QLatin1String("ELSIF") || word == QLatin1String("END_VAR")
        || word == QLatin1String("END_STRUCT");
}

} // namespace

int indentationOf(QStringView line)
{
    int columns = 0;
    for (QChar c : leadingWhitespace(line))
        columns += c == QLatin1Char('\t') ? kIndentWidth : 1;
    return columns;
}

QString blockCloserFor(QStringView word, TextLanguage language)
{
    const QString upper = word.toString().toUpper();
    if (language == TextLanguage::ST) {
        for (const char *control : {"IF", "CASE", "FOR", "WHILE", "REPEAT"}) {
            if (upper == QLatin1String(control))
                return QLatin1String("END_") + upper;
        }
    }
    if (isVarKeyword(upper) && upper != QLatin1String("END_VAR"))
        return QStringLiteral("END_VAR");
    if (upper == QLatin1String("STRUCT") || upper == QLatin1String("TYPE") || isPouHeader(upper))
        return QLatin1String("END_") + upper;
    return {};
}

EnterEdit enterEdit(QStringView line, int column, QStringView followingText, TextLanguage language)
{
    column = std::clamp(column, 0, int(line.size()));
    const QStringView before = line.left(column);
    const QStringView after = line.mid(column);
    const QString indent = leadingWhitespace(before).toString();

    EnterEdit edit;
    edit.text = QLatin1Char('\n') + indent;
    edit.cursorOffset = int(edit.text.size());

    const bool atEnd = after.trimmed().isEmpty();
    const std::optional<Opening> opening = atEnd ? openingOf(before, language) : std::nullopt;
    if (!opening)
        return edit;

    edit.removeAfter = int(after.size());
    const QString inner = opening->indentInside ? QString(kIndentWidth, QLatin1Char(' ')) : QString();
    edit.text += inner;
    edit.cursorOffset = int(edit.text.size());
    if (opening->closers.isEmpty())
        return edit;

    // Close the block only when it is not closed already.
    const QString firstCloser = opening->closers.first();
    bool closed = false;
    if (opening->indentInside) {
        const QStringView next = nextNonBlankLine(followingText);
        const int nextIndent = indentationOf(next);
        const int ownIndent = indentationOf(before);
        if (!next.isEmpty()
            && (nextIndent > ownIndent || (nextIndent == ownIndent && startsWithWord(next.trimmed(), firstCloser))))
            closed = true;
    } else {
        closed = containsWord(followingText, firstCloser);
    }
    if (closed)
        return edit;

    for (const QString &closer : opening->closers)
        edit.text += QLatin1Char('\n') + indent + (opening->lowerCase ? closer.toLower() : closer);
    return edit;
}

int closingKeywordIndent(QStringView line, QStringView previousLine, TextLanguage language)
{
    const QList<Word> words = significantWords(line);
    if (words.isEmpty() || !isClosingKeyword(words.first().upper))
        return -1;
    if (language == TextLanguage::IL && words.first().upper != QLatin1String("END_VAR")
        && words.first().upper != QLatin1String("END_STRUCT"))
        return -1;
    const int previousIndent = indentationOf(previousLine);
    const std::optional<Opening> opening = openingOf(previousLine, language);
    const int wanted = opening && opening->indentInside ? previousIndent : std::max(0, previousIndent - kIndentWidth);
    return wanted < indentationOf(line) ? wanted : -1;
}

} // namespace iec::editors
