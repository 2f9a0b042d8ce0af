// bench_highlight: how fluid typing stays in a 5,000-line ST body.
//
// Prints the time of the initial highlight, then the time per keystroke (key event, incremental
// re-highlight, layout and repaint of the editor) in the middle of the body, and at the top
// where one keystroke opens a (* comment that swallows the whole body, typing inside it, and
// closing it again. Run it offscreen from a Release build:
//   QT_QPA_PLATFORM=offscreen build/h-editors-rel/bench/editors/bench_highlight
// `--screenshots DIR` also writes st_editor.png and il_editor.png of the editor into DIR.
#include "editors/text/codeeditor.h"
#include "editors/text/codehighlighter.h"
#include "editors/text/findreplacebar.h"
#include "editors/text/foldingregions.h"
#include "editors/text/texteditorwidget.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QPlainTextDocumentLayout>
#include <QTest>
#include <QTextBlock>
#include <QTextDocument>

#include <algorithm>
#include <cstdio>
#include <vector>

using namespace iec::editors;

namespace {

QString bigStBody(int lines)
{
    QStringList out;
    out << QStringLiteral("PROGRAM Plant") << QStringLiteral("VAR");
    for (int i = 0; i < 150; ++i)
        out << QStringLiteral("    Tank%1 : REAL := %1.5; (* level in m *)").arg(i);
    out << QStringLiteral("    Pump : ARRAY[1..16] OF BOOL;") << QStringLiteral("    Delay : TON;")
        << QStringLiteral("    Msg : STRING := 'ready';") << QStringLiteral("END_VAR");
    int n = 0;
    while (out.size() < lines - 1) {
        const int i = n++ % 150;
        out << QStringLiteral("IF Tank%1 > %2.0 AND NOT Pump[%3] THEN (* high level *)")
                   .arg(i)
                   .arg(i % 10)
                   .arg(i % 16 + 1)
            << QStringLiteral("    Pump[%1] := TRUE;").arg(i % 16 + 1)
            << QStringLiteral("    Delay(IN := TRUE, PT := T#%1s);").arg(i % 9 + 1)
            << QStringLiteral("ELSIF Tank%1 < 0.5 THEN").arg(i)
            << QStringLiteral("    Msg := CONCAT('low ', INT_TO_STRING(%1));").arg(i) << QStringLiteral("END_IF;")
            << QStringLiteral("FOR k := 1 TO 16 BY 2 DO")
            << QStringLiteral("    %QX0.%1 := Pump[k] OR %IX1.%1;").arg(i % 8) << QStringLiteral("END_FOR;")
            << QString();
    }
    while (out.size() > lines - 1)
        out.removeLast();
    out << QStringLiteral("END_PROGRAM");
    return out.join(QLatin1Char('\n'));
}

struct Stats {
    double mean = 0;
    double median = 0;
    double max = 0;
};

Stats stats(std::vector<double> ms)
{
    Stats s;
    if (ms.empty())
        return s;
    double sum = 0;
    for (double v : ms)
        sum += v;
    s.mean = sum / double(ms.size());
    std::sort(ms.begin(), ms.end());
    s.median = ms[ms.size() / 2];
    s.max = ms.back();
    return s;
}

// One key press as the user makes it, with the repaint it causes.
double keystroke(CodeEditor &editor, QChar key)
{
    QElapsedTimer timer;
    timer.start();
    QTest::keyClick(&editor, key.toLatin1());
    QApplication::processEvents(); // layout and paint of the viewport and gutter
    return double(timer.nsecsElapsed()) / 1e6;
}

std::vector<double> typeText(CodeEditor &editor, const QString &text)
{
    std::vector<double> ms;
    for (QChar c : text)
        ms.push_back(keystroke(editor, c));
    return ms;
}

void placeAt(CodeEditor &editor, int line, bool atEnd)
{
    const QTextBlock block = editor.document()->findBlockByNumber(line);
    QTextCursor cursor(block);
    if (atEnd)
        cursor.movePosition(QTextCursor::EndOfBlock);
    editor.setTextCursor(cursor);
    editor.centerCursor();
    QApplication::processEvents();
}

void print(const char *what, const Stats &s, int blocks = -1)
{
    std::printf("  %-46s mean %7.3f ms   median %7.3f ms   max %7.3f ms", what, s.mean, s.median, s.max);
    if (blocks >= 0)
        std::printf("   (%d blocks re-lexed)", blocks);
    std::printf("\n");
}

void screenshots(const QString &dir)
{
    QDir().mkpath(dir);
    const QString st = QStringLiteral("PROGRAM PLC_PRG\n"
                                      "VAR\n"
                                      "    Start AT %IX0.0 : BOOL;\n"
                                      "    Level : REAL := 0.0;   (* tank level in m *)\n"
                                      "    Fill : TON;\n"
                                      "    Msg : STRING := 'idle';\n"
                                      "END_VAR\n"
                                      "(* Fill the tank until it is full,\n"
                                      "   then report. *)\n"
                                      "Fill(IN := Start AND NOT Full, PT := T#5s);\n"
                                      "IF Fill.Q THEN\n"
                                      "    Level := LIMIT(0.0, Level + 0.25, 10.0);\n"
                                      "    Msg := 'filling';\n"
                                      "ELSIF Level >= 10.0 THEN\n"
                                      "    %QX0.1 := TRUE;\n"
                                      "END_IF;\n"
                                      "FOR i := 1 TO 8 BY 2 DO\n"
                                      "    Counts[i] := Counts[i] + 16#01;\n"
                                      "END_FOR;\n"
                                      "CASE State OF\n"
                                      "    0: State := 1;\n"
                                      "    1: Msg := 'done';\n"
                                      "END_CASE;\n"
                                      "Result := SQRT(Level * (Level + 2.0));\n"
                                      "END_PROGRAM\n");
    TextEditorWidget stWidget(TextLanguage::ST);
    stWidget.resize(760, 520);
    stWidget.show();
    CodeEditor *editor = stWidget.editor();
    editor->setBodyText(st);
    editor->setDiagnostics({{10, 26, 4, TextDiagnostic::Severity::Error, QStringLiteral("Unknown name 'Full'")},
        {18, 5, 6, TextDiagnostic::Severity::Warning, QStringLiteral("'Counts' is not declared")}});
    editor->fold(19); // the CASE block
    QTextCursor cursor(editor->document()->findBlockByNumber(23));
    cursor.setPosition(cursor.block().position() + 14); // on the "(" after SQRT: bracket match
    editor->setTextCursor(cursor);
    QApplication::processEvents();
    stWidget.grab().save(dir + QStringLiteral("/st_editor.png"));

    const QString il = QStringLiteral("(* When %IX0.0 is on, T1 and T2 make a pulse: 1 s off, 2 s on *)\n"
                                      "    LD      %IX0.0\n"
                                      "    ANDN    N\n"
                                      "    ST      T1.IN\n"
                                      "    CAL     T1(PT := T#1S)     (* 1 s off *)\n"
                                      "    LD      T1.Q\n"
                                      "    ST      M\n"
                                      "    LD      M\n"
                                      "    ST      T2.IN\n"
                                      "    CAL     T2(PT := T#2S)     (* 2 s on *)\n"
                                      "    LD      T2.Q\n"
                                      "    ST      N\n"
                                      "    JMPC    Done\n"
                                      "    LD      M\n"
                                      "    ST      %QX0.0\n"
                                      "Done:\n"
                                      "    RET\n");
    TextEditorWidget ilWidget(TextLanguage::IL);
    ilWidget.resize(760, 420);
    ilWidget.show();
    ilWidget.editor()->setBodyText(il);
    ilWidget.editor()->setDiagnostics({{13, 13, 4, TextDiagnostic::Severity::Error, QStringLiteral("Unknown label")}});
    ilWidget.findBar()->activate(true);
    ilWidget.findBar()->setFindText(QStringLiteral("T1"));
    ilWidget.findBar()->findNext();
    QApplication::processEvents();
    ilWidget.grab().save(dir + QStringLiteral("/il_editor.png"));
    std::printf("screenshots written to %s\n", qPrintable(dir));
}

} // namespace

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    const qsizetype shotIndex = args.indexOf(QStringLiteral("--screenshots"));
    if (shotIndex > 0 && shotIndex + 1 < args.size()) {
        screenshots(args[shotIndex + 1]);
        return 0;
    }

    const int lines = 5000;
    const QString text = bigStBody(lines);
    std::printf("bench_highlight: ST body of %d lines, %lld characters\n", lines, static_cast<long long>(text.size()));

    // 1. The highlighter alone on a document (no widget).
    {
        QTextDocument document;
        document.setDocumentLayout(new QPlainTextDocumentLayout(&document)); // as in the editor
        CodeHighlighter highlighter(TextLanguage::ST, &document);
        QElapsedTimer timer;
        timer.start();
        document.setPlainText(text);
        const double setText = double(timer.nsecsElapsed()) / 1e6;
        highlighter.resetHighlightedBlockCount();
        timer.restart();
        highlighter.rehighlight();
        const double rehighlight = double(timer.nsecsElapsed()) / 1e6;
        std::printf(
            "  initial highlight, document only:              %8.2f ms (setPlainText incl. highlight)\n", setText);
        std::printf("  full re-highlight of %d blocks:               %8.2f ms (%.2f us per line)\n",
            highlighter.highlightedBlockCount(), rehighlight, rehighlight * 1000.0 / lines);
    }

    // 2. The editor as the user sees it.
    CodeEditor editor(TextLanguage::ST);
    editor.resize(1000, 800);
    editor.show();
    QApplication::processEvents();
    QElapsedTimer timer;
    timer.start();
    editor.setBodyText(text);
    QApplication::processEvents();
    std::printf(
        "  open in the editor (text, highlight, folds, first paint): %6.2f ms\n", double(timer.nsecsElapsed()) / 1e6);
    timer.restart();
    editor.updateFoldRangesNow();
    std::printf("  folding ranges of the whole body (debounced, once per pause): %6.2f ms, %lld ranges\n",
        double(timer.nsecsElapsed()) / 1e6, static_cast<long long>(editor.foldRanges().size()));

    CodeHighlighter *highlighter = editor.highlighter();
    const QString word = QStringLiteral("abcdefghijklmnopqrstuvwxyz_x1y2z3abcdefghijklmnopqrstuvwxyz");

    std::printf("per keystroke (key event + incremental highlight + layout + repaint), %lld keys each:\n",
        static_cast<long long>(word.size()));
    placeAt(editor, lines / 2, true);
    highlighter->resetHighlightedBlockCount();
    const Stats middle = stats(typeText(editor, word));
    print("middle of the body (line 2500)", middle, highlighter->highlightedBlockCount());

    placeAt(editor, 0, false);
    highlighter->resetHighlightedBlockCount();
    const std::vector<double> open = typeText(editor, QStringLiteral("(*"));
    print("top: '(' then '*' opens a comment over all", stats(open), highlighter->highlightedBlockCount());
    std::printf("    the '*' keystroke alone: %.3f ms\n", open.back());
    highlighter->resetHighlightedBlockCount();
    const Stats inside = stats(typeText(editor, word));
    print("top, typing inside the open comment", inside, highlighter->highlightedBlockCount());
    highlighter->resetHighlightedBlockCount();
    const std::vector<double> close = typeText(editor, QStringLiteral("*)"));
    print("top: '*' then ')' closes the comment", stats(close), highlighter->highlightedBlockCount());
    std::printf("    the ')' keystroke alone: %.3f ms\n", close.back());

    placeAt(editor, lines / 2, true);
    std::vector<double> enters;
    for (int i = 0; i < 20; ++i) {
        QElapsedTimer t;
        t.start();
        QTest::keyClick(&editor, Qt::Key_Return);
        QApplication::processEvents();
        enters.push_back(double(t.nsecsElapsed()) / 1e6);
    }
    print("Enter in the middle (auto-indent, block check)", stats(enters));

    // Moving the cursor next to a bracket lexes a window of lines around it to find the partner.
    std::vector<double> moves;
    for (int line = 1000; line < 1200; line += 10) {
        const QTextBlock block = editor.document()->findBlockByNumber(line);
        const int bracket = int(block.text().indexOf(QLatin1Char('(')));
        if (bracket < 0)
            continue;
        QTextCursor cursor(block);
        cursor.setPosition(block.position() + bracket);
        QElapsedTimer t;
        t.start();
        editor.setTextCursor(cursor);
        QApplication::processEvents();
        moves.push_back(double(t.nsecsElapsed()) / 1e6);
    }
    print("cursor onto a bracket (match + repaint)", stats(moves));

    timer.restart();
    editor.flushPendingEdit();
    editor.updateFoldRangesNow();
    std::printf("  after a pause: folding update %.2f ms\n", double(timer.nsecsElapsed()) / 1e6);
    return 0;
}
