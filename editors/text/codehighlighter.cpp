#include "editors/text/codehighlighter.h"

#include "editors/text/standardlibrary.h"

#include <QTextDocument>

#include <algorithm>

#include <array>

namespace iec::editors {

namespace {

QTextCharFormat makeFormat(const QColor &color, bool bold = false, bool italic = false)
{
    QTextCharFormat format;
    format.setForeground(color);
    if (bold)
        format.setFontWeight(QFont::Bold);
    if (italic)
        format.setFontItalic(true);
    return format;
}

const std::array<QTextCharFormat, 12> &formats()
{
    using S = CodeHighlighter::Style;
    static const std::array<QTextCharFormat, 12> table = [] {
        std::array<QTextCharFormat, 12> t;
        t[size_t(S::Plain)] = QTextCharFormat();
        t[size_t(S::Keyword)] = makeFormat(QColor(0x00, 0x33, 0xb3), true);
        t[size_t(S::TypeName)] = makeFormat(QColor(0x00, 0x80, 0x80));
        t[size_t(S::Number)] = makeFormat(QColor(0x17, 0x50, 0xeb));
        t[size_t(S::TimeLiteral)] = makeFormat(QColor(0x87, 0x10, 0x94));
        t[size_t(S::String)] = makeFormat(QColor(0xa3, 0x15, 0x15));
        t[size_t(S::DirectAddress)] = makeFormat(QColor(0xb0, 0x5a, 0x00), true);
        t[size_t(S::Operator)] = makeFormat(QColor(0x50, 0x50, 0x50));
        t[size_t(S::Comment)] = makeFormat(QColor(0x3f, 0x7f, 0x3f), false, true);
        t[size_t(S::Pragma)] = makeFormat(QColor(0x80, 0x80, 0x80));
        QTextCharFormat error = makeFormat(QColor(0xc0, 0x00, 0x00));
        error.setUnderlineStyle(QTextCharFormat::WaveUnderline);
        error.setUnderlineColor(QColor(0xc0, 0x00, 0x00));
        t[size_t(S::Error)] = error;
        t[size_t(S::StandardPou)] = makeFormat(QColor(0x6f, 0x42, 0xc1));
        return t;
    }();
    return table;
}

bool isStKeywordToo(QStringView word)
{
    // IL operators that are also ST operators keep their keyword colour in ST.
    for (const char *w : {"AND", "OR", "XOR", "NOT", "MOD"}) {
        if (word.compare(QLatin1String(w), Qt::CaseInsensitive) == 0)
            return true;
    }
    return false;
}

// Words of edition 3 and CODESYS the lexer leaves as names, because a program may also use them
// as names ("Method := 1"): coloured as keywords all the same, as CODESYS colours them.
bool isContextualKeyword(QStringView word)
{
    for (const char *w : {"METHOD", "END_METHOD", "PROPERTY", "END_PROPERTY", "END_GET", "END_SET", "INTERFACE",
             "END_INTERFACE", "EXTENDS", "IMPLEMENTS", "THIS", "SUPER", "ABSTRACT", "FINAL", "PUBLIC", "PRIVATE",
             "PROTECTED", "INTERNAL", "POINTER", "REFERENCE"}) {
        if (word.compare(QLatin1String(w), Qt::CaseInsensitive) == 0)
            return true;
    }
    return false;
}

} // namespace

CodeHighlighter::CodeHighlighter(TextLanguage language, QTextDocument *document)
    : QSyntaxHighlighter(document)
    , m_language(language)
{ }

void CodeHighlighter::setLanguage(TextLanguage language)
{
    if (language == m_language)
        return;
    m_language = language;
    rehighlight();
}

QTextCharFormat CodeHighlighter::format(Style style)
{
    return formats()[size_t(style)];
}

CodeHighlighter::Style CodeHighlighter::styleOf(interp::TokenKind kind, QStringView word) const
{
    using K = interp::TokenKind;
    switch (kind) {
    case K::Identifier:
        if (isContextualKeyword(word))
            return Style::Keyword;
        return findStandardPou(word) ? Style::StandardPou : Style::Plain;
    case K::Keyword:
        if (m_language == TextLanguage::ST && interp::isIlOperator(word) && !isStKeywordToo(word))
            return findStandardPou(word) ? Style::StandardPou : Style::Plain;
        return Style::Keyword;
    case K::TypeName:
        return Style::TypeName;
    case K::IntegerLiteral:
    case K::RealLiteral:
        return Style::Number;
    case K::TimeLiteral:
    case K::DateTimeLiteral:
        return Style::TimeLiteral;
    case K::StringLiteral:
    case K::WStringLiteral:
        return Style::String;
    case K::DirectAddress:
        return Style::DirectAddress;
    case K::Operator:
        return Style::Operator;
    case K::Comment:
        return Style::Comment;
    case K::Pragma:
        return Style::Pragma;
    case K::Error:
        return Style::Error;
    }
    return Style::Plain;
}

int CodeHighlighter::encode(interp::LexState state)
{
    return state.commentDepth * 2 + (state.inPragma ? 1 : 0);
}

interp::LexState CodeHighlighter::decode(int blockState)
{
    if (blockState < 0)
        return {};
    interp::LexState state;
    state.commentDepth = blockState / 2;
    state.inPragma = (blockState % 2) != 0;
    return state;
}

interp::LexState CodeHighlighter::stateAfter(const QTextBlock &block)
{
    return block.isValid() ? decode(block.userState()) : interp::LexState();
}

void CodeHighlighter::highlightBlock(const QString &text)
{
    ++m_highlightedBlocks;
    interp::LexState state = decode(previousBlockState());
    const QStringView view(text);
    const std::vector<interp::Token> tokens = interp::tokenize(view, state);
    // GET and SET open a property's accessors on a line of their own; anywhere else they are names.
    const bool accessorLine
        = std::ranges::count_if(tokens, [](const interp::Token &t) { return t.kind != interp::TokenKind::Comment; }) == 1;
    for (const interp::Token &token : tokens) {
        const QStringView word = view.mid(token.offset, token.length);
        const bool accessor = accessorLine && token.kind == interp::TokenKind::Identifier
            && (word.compare(u"GET", Qt::CaseInsensitive) == 0 || word.compare(u"SET", Qt::CaseInsensitive) == 0);
        const Style style = accessor ? Style::Keyword : styleOf(token.kind, word);
        if (style != Style::Plain)
            setFormat(token.offset, token.length, formats()[size_t(style)]);
    }
    setCurrentBlockState(encode(state));
}

} // namespace iec::editors
