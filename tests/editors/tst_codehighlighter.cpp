// The ST/IL highlighter: the format of every token kind at exact positions, and incremental
// re-highlighting (one edited line costs one block unless the comment state propagates).
#include "editors/text/codehighlighter.h"

#include <QTest>
#include <QTextBlock>
#include <QTextDocument>
#include <QTextLayout>

using namespace iec::editors;
using Style = CodeHighlighter::Style;

Q_DECLARE_METATYPE(iec::editors::TextLanguage)
Q_DECLARE_METATYPE(iec::editors::CodeHighlighter::Style)

namespace {

// The format the highlighter gave the character at `position` (a default format when none).
QTextCharFormat formatAt(const QTextDocument &document, int position)
{
    const QTextBlock block = document.findBlock(position);
    const int column = position - block.position();
    for (const QTextLayout::FormatRange &range : block.layout()->formats()) {
        if (range.start <= column && column < range.start + range.length)
            return range.format;
    }
    return {};
}

QString numbered(int count, const QString &pattern)
{
    QStringList lines;
    for (int i = 0; i < count; ++i)
        lines.append(pattern.arg(i));
    return lines.join(QLatin1Char('\n'));
}

} // namespace

class TestCodeHighlighter : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void formats_data();
    void formats();
    void wholeTokenIsFormatted();
    void stylesAreDistinct();
    void multiLineCommentState();
    void editingOneLineRehighlightsOneBlock();
    void openingACommentPropagatesAndClosingItStopsAgain();
    void switchingLanguageRehighlights();
};

void TestCodeHighlighter::formats_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("position");
    QTest::addColumn<TextLanguage>("language");
    QTest::addColumn<Style>("style");
    const auto ST = TextLanguage::ST;
    const auto IL = TextLanguage::IL;
    QTest::newRow("keyword") << "IF x THEN" << 0 << ST << Style::Keyword;
    QTest::newRow("keyword THEN") << "IF x THEN" << 7 << ST << Style::Keyword;
    QTest::newRow("identifier") << "IF x THEN" << 3 << ST << Style::Plain;
    QTest::newRow("blank") << "IF x THEN" << 2 << ST << Style::Plain;
    QTest::newRow("lower-case keyword") << "end_if;" << 2 << ST << Style::Keyword;
    QTest::newRow("METHOD") << "METHOD Add : INT" << 0 << ST << Style::Keyword;
    QTest::newRow("END_PROPERTY") << "END_PROPERTY" << 4 << ST << Style::Keyword;
    QTest::newRow("SUPER") << "SUPER^.Step(1);" << 1 << ST << Style::Keyword;
    QTest::newRow("GET on its line") << "GET" << 0 << ST << Style::Keyword;
    QTest::newRow("SET with a comment") << "  set (* write *)" << 3 << ST << Style::Keyword;
    QTest::newRow("get as a name") << "x := get;" << 6 << ST << Style::Plain;
    QTest::newRow("type name") << "x : INT;" << 5 << ST << Style::TypeName;
    QTest::newRow("integer") << "x := 42;" << 6 << ST << Style::Number;
    QTest::newRow("based integer") << "x := 16#FF;" << 9 << ST << Style::Number;
    QTest::newRow("real") << "x := 1.5E3;" << 7 << ST << Style::Number;
    QTest::newRow("time") << "t := T#1s500ms;" << 5 << ST << Style::TimeLiteral;
    QTest::newRow("date") << "d := D#2024-01-01;" << 10 << ST << Style::TimeLiteral;
    QTest::newRow("string") << "s := 'abc';" << 6 << ST << Style::String;
    QTest::newRow("wide string") << "s := \"abc\";" << 7 << ST << Style::String;
    QTest::newRow("direct address") << "x := %IX0.1;" << 8 << ST << Style::DirectAddress;
    QTest::newRow("assignment") << "x := 1;" << 2 << ST << Style::Operator;
    QTest::newRow("semicolon") << "x := 1;" << 6 << ST << Style::Operator;
    QTest::newRow("comment") << "x; (* note *)" << 6 << ST << Style::Comment;
    QTest::newRow("comment start") << "x; (* note *)" << 3 << ST << Style::Comment;
    QTest::newRow("line comment") << "x; // note" << 5 << ST << Style::Comment;
    QTest::newRow("pragma") << "{attribute 'x'} y;" << 3 << ST << Style::Pragma;
    QTest::newRow("error") << "x := @;" << 5 << ST << Style::Error;
    QTest::newRow("standard FB") << "t1 : TON;" << 5 << ST << Style::StandardPou;
    QTest::newRow("standard function") << "y := LIMIT(0, x, 9);" << 6 << ST << Style::StandardPou;
    QTest::newRow("ST operator word AND") << "a := b AND c;" << 8 << ST << Style::Keyword;
    QTest::newRow("IL operator is a name in ST") << "LD := 1;" << 0 << ST << Style::Plain;
    QTest::newRow("S is a name in ST") << "S := TRUE;" << 0 << ST << Style::Plain;
    QTest::newRow("IL operator in IL") << "LD x" << 0 << IL << Style::Keyword;
    QTest::newRow("IL conditional jump") << "JMPCN next" << 2 << IL << Style::Keyword;
    QTest::newRow("IL operand") << "LD x" << 3 << IL << Style::Plain;
    QTest::newRow("IL ADD is an operator") << "ADD 1" << 0 << IL << Style::Keyword;
    QTest::newRow("ADD is a function in ST") << "y := ADD(1, 2);" << 5 << ST << Style::StandardPou;
}

void TestCodeHighlighter::formats()
{
    QFETCH(QString, text);
    QFETCH(int, position);
    QFETCH(TextLanguage, language);
    QFETCH(Style, style);
    QTextDocument document;
    document.documentLayout(); // a document only reports changes (and so gets highlighted) once it has a layout
    CodeHighlighter highlighter(language, &document);
    document.setPlainText(text);
    const QTextCharFormat actual = formatAt(document, position);
    const QTextCharFormat expected = CodeHighlighter::format(style);
    QCOMPARE(actual.foreground(), expected.foreground());
    QCOMPARE(actual.fontWeight(), expected.fontWeight());
    QCOMPARE(actual.fontItalic(), expected.fontItalic());
    QCOMPARE(actual.underlineStyle(), expected.underlineStyle());
}

void TestCodeHighlighter::wholeTokenIsFormatted()
{
    QTextDocument document;
    document.documentLayout(); // a document only reports changes (and so gets highlighted) once it has a layout
    CodeHighlighter highlighter(TextLanguage::ST, &document);
    document.setPlainText(QStringLiteral("x := 'it''s';"));
    const QList<QTextLayout::FormatRange> ranges = document.firstBlock().layout()->formats();
    const QTextCharFormat string = CodeHighlighter::format(Style::String);
    bool found = false;
    for (const QTextLayout::FormatRange &range : ranges) {
        if (range.format.foreground() == string.foreground()) {
            QCOMPARE(range.start, 5);
            QCOMPARE(range.length, 7);
            found = true;
        }
    }
    QVERIFY(found);
}

void TestCodeHighlighter::stylesAreDistinct()
{
    // Each coloured style must be told apart from plain text and from each other.
    QList<QBrush> seen {CodeHighlighter::format(Style::Plain).foreground()};
    for (Style style : {Style::Keyword, Style::TypeName, Style::Number, Style::TimeLiteral, Style::String,
             Style::DirectAddress, Style::Operator, Style::Comment, Style::Pragma, Style::Error, Style::StandardPou}) {
        const QBrush brush = CodeHighlighter::format(style).foreground();
        QVERIFY2(!seen.contains(brush), qPrintable(QString::number(int(style))));
        seen.append(brush);
    }
}

void TestCodeHighlighter::multiLineCommentState()
{
    QTextDocument document;
    document.documentLayout(); // a document only reports changes (and so gets highlighted) once it has a layout
    CodeHighlighter highlighter(TextLanguage::ST, &document);
    document.setPlainText(QStringLiteral("a := 1; (* open\nstill IF inside\n(* nested *) more\nclose *) b := 2;\nc;"));
    QList<int> states;
    for (QTextBlock block = document.begin(); block.isValid(); block = block.next())
        states.append(block.userState());
    QCOMPARE(states, (QList<int> {2, 2, 2, 0, 0}));
    // "IF" inside the comment is comment, "b" after it is plain, ":=" is an operator.
    QCOMPARE(formatAt(document, document.findBlockByNumber(1).position() + 6).foreground(),
        CodeHighlighter::format(Style::Comment).foreground());
    const int line3 = document.findBlockByNumber(3).position();
    QCOMPARE(formatAt(document, line3 + 2).foreground(), CodeHighlighter::format(Style::Comment).foreground());
    QCOMPARE(formatAt(document, line3 + 9).foreground(), CodeHighlighter::format(Style::Plain).foreground());
    QCOMPARE(formatAt(document, line3 + 11).foreground(), CodeHighlighter::format(Style::Operator).foreground());
}

void TestCodeHighlighter::editingOneLineRehighlightsOneBlock()
{
    QTextDocument document;
    document.documentLayout(); // a document only reports changes (and so gets highlighted) once it has a layout
    CodeHighlighter highlighter(TextLanguage::ST, &document);
    document.setPlainText(numbered(100, QStringLiteral("x%1 := x%1 + 1;")));
    QCOMPARE(formatAt(document, document.lastBlock().position() + 4).foreground(),
        CodeHighlighter::format(Style::Operator).foreground());

    highlighter.resetHighlightedBlockCount();
    QTextCursor cursor(document.findBlockByNumber(50));
    cursor.insertText(QStringLiteral("IF a THEN "));
    QCOMPARE(highlighter.highlightedBlockCount(), 1);
    QCOMPARE(formatAt(document, document.findBlockByNumber(50).position()).foreground(),
        CodeHighlighter::format(Style::Keyword).foreground());

    // A whole comment on one line leaves the state at its end unchanged: still one block.
    highlighter.resetHighlightedBlockCount();
    cursor.insertText(QStringLiteral("(* done *)"));
    QCOMPARE(highlighter.highlightedBlockCount(), 1);
}

void TestCodeHighlighter::openingACommentPropagatesAndClosingItStopsAgain()
{
    QTextDocument document;
    document.documentLayout(); // a document only reports changes (and so gets highlighted) once it has a layout
    CodeHighlighter highlighter(TextLanguage::ST, &document);
    document.setPlainText(numbered(100, QStringLiteral("y%1 := %1;")));

    highlighter.resetHighlightedBlockCount();
    QTextCursor open(document.findBlockByNumber(10));
    open.insertText(QStringLiteral("(*"));
    QCOMPARE(highlighter.highlightedBlockCount(), 90); // lines 10..99 now start inside the comment
    QCOMPARE(document.findBlockByNumber(9).userState(), 0);
    QCOMPARE(document.findBlockByNumber(10).userState(), 2);
    QCOMPARE(document.lastBlock().userState(), 2);
    QCOMPARE(formatAt(document, document.findBlockByNumber(60).position()).foreground(),
        CodeHighlighter::format(Style::Comment).foreground());

    // Typing inside the open comment changes no state: one block again.
    highlighter.resetHighlightedBlockCount();
    QTextCursor inside(document.findBlockByNumber(40));
    inside.insertText(QStringLiteral("zz"));
    QCOMPARE(highlighter.highlightedBlockCount(), 1);

    // Closing it at the end of line 20 re-lexes lines 20..99, then the states agree again.
    highlighter.resetHighlightedBlockCount();
    QTextCursor close(document.findBlockByNumber(20));
    close.movePosition(QTextCursor::EndOfBlock);
    close.insertText(QStringLiteral("*)"));
    QCOMPARE(highlighter.highlightedBlockCount(), 80);
    QCOMPARE(document.findBlockByNumber(19).userState(), 2);
    QCOMPARE(document.findBlockByNumber(20).userState(), 0);
    QCOMPARE(formatAt(document, document.findBlockByNumber(60).position()).foreground(),
        CodeHighlighter::format(Style::Plain).foreground());
}

void TestCodeHighlighter::switchingLanguageRehighlights()
{
    QTextDocument document;
    document.documentLayout(); // a document only reports changes (and so gets highlighted) once it has a layout
    CodeHighlighter highlighter(TextLanguage::ST, &document);
    document.setPlainText(QStringLiteral("LD x"));
    QCOMPARE(formatAt(document, 0).foreground(), CodeHighlighter::format(Style::Plain).foreground());
    highlighter.setLanguage(TextLanguage::IL);
    QCOMPARE(formatAt(document, 0).foreground(), CodeHighlighter::format(Style::Keyword).foreground());
}

QTEST_MAIN(TestCodeHighlighter)
#include "tst_codehighlighter.moc"
