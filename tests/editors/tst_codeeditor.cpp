// The ST/IL CodeEditor driven as a user drives it: key events and the editor's own slots.
#include "editors/text/codeeditor.h"
#include "editors/text/codehighlighter.h"
#include "editors/text/findreplacebar.h"
#include "editors/text/inputassistant.h"
#include "editors/text/texteditorwidget.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QClipboard>
#include <QCompleter>
#include <QDialogButtonBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTextBlock>
#include <QToolTip>
#include <QTreeWidget>

using namespace iec::editors;

Q_DECLARE_METATYPE(iec::editors::TextLanguage)

namespace {

class FakeProvider : public CompletionProvider
{
public:
    QList<CompletionItem> variables() const override
    {
        return {{QStringLiteral("Tank"), CompletionItem::Kind::Variable, QStringLiteral("TankCtl"),
                    QStringLiteral("Local variables")},
            {QStringLiteral("Temp"), CompletionItem::Kind::Variable, QStringLiteral("REAL"),
                QStringLiteral("Local variables")},
            {QStringLiteral("gAlarm"), CompletionItem::Kind::Variable, QStringLiteral("BOOL"),
                QStringLiteral("Global variables")}};
    }
    QList<CompletionItem> members(const QString &path) const override
    {
        if (path == QLatin1String("Tank"))
            return {{QStringLiteral("Level"), CompletionItem::Kind::Member, QStringLiteral("REAL"), {}},
                {QStringLiteral("Valve"), CompletionItem::Kind::Member, QStringLiteral("BOOL"), {}}};
        return {};
    }
    QList<CompletionItem> pous() const override
    {
        return {{QStringLiteral("Scale"), CompletionItem::Kind::Function, QStringLiteral("Scale(X: REAL) : REAL"), {}},
            {QStringLiteral("TankCtl"), CompletionItem::Kind::FunctionBlock, {}, {}},
            {QStringLiteral("Main"), CompletionItem::Kind::Program, {}, {}}};
    }
};

void placeCursor(QPlainTextEdit &editor, int position, int anchor = -1)
{
    QTextCursor cursor = editor.textCursor();
    cursor.setPosition(anchor < 0 ? position : anchor);
    if (anchor >= 0)
        cursor.setPosition(position, QTextCursor::KeepAnchor);
    editor.setTextCursor(cursor);
}

void placeAtEndOfLine(QPlainTextEdit &editor, int line)
{
    const QTextBlock block = editor.document()->findBlockByNumber(line);
    placeCursor(editor, block.position() + block.length() - 1);
}

QList<QTextEdit::ExtraSelection> underlines(const CodeEditor &editor)
{
    QList<QTextEdit::ExtraSelection> result;
    for (const QTextEdit::ExtraSelection &selection : editor.extraSelections()) {
        if (selection.format.underlineStyle() == QTextCharFormat::WaveUnderline)
            result.append(selection);
    }
    return result;
}

} // namespace

class TestCodeEditor : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void blockCompletion_data();
    void blockCompletion();
    void blockCompletionIsOneUndoStep();
    void tabIndentsAndShiftTabOutdents();
    void bracketsAreMarked();
    void currentLineIsHighlighted();
    void gutterWidthFollowsLineCount();
    void commentToggleAndUndoInOneStep();
    void findNextPreviousAndOptions();
    void replaceAndReplaceAllInOneUndoStep();
    void findBarShortcuts();
    void diagnosticsUnderlineExactRanges();
    void diagnosticsFollowEditsAndShowTooltips();
    void foldingHidesAndShowsBlocks();
    void foldingSurvivesEditsAbove();
    void completionPopupForVariablesAndMembers();
    void completionInsertsASingleCandidateDirectly();
    void inputAssistantInsertsAnIlOperator();
    void inputAssistantCategories();
    void goToDefinitionSignal();
    void pasteDropsCharactersAFileCannotKeep();
    void textEditedIsDebouncedAndSkipsSetBodyText();
};

void TestCodeEditor::blockCompletion_data()
{
    QTest::addColumn<TextLanguage>("language");
    QTest::addColumn<QString>("initial");
    QTest::addColumn<int>("line"); // the cursor goes to the end of this line before typing
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("expected");
    QTest::addColumn<int>("cursorLine");
    QTest::addColumn<int>("cursorColumn");
    const auto ST = TextLanguage::ST;
    const auto IL = TextLanguage::IL;
    QTest::newRow("IF") << ST << "" << 0 << "IF x THEN"
                        << "IF x THEN\n    \nEND_IF" << 1 << 4;
    QTest::newRow("IF nested") << ST << "IF a THEN\n    \nEND_IF" << 1 << "IF b THEN"
                               << "IF a THEN\n    IF b THEN\n        \n    END_IF\nEND_IF" << 2 << 8;
    QTest::newRow("IF closed already") << ST << "IF x THEN\nEND_IF" << 0 << ""
                                       << "IF x THEN\n    \nEND_IF" << 1 << 4;
    QTest::newRow("CASE") << ST << "" << 0 << "CASE n OF"
                          << "CASE n OF\n    \nEND_CASE" << 1 << 4;
    QTest::newRow("FOR") << ST << "" << 0 << "FOR i := 1 TO 9 DO"
                         << "FOR i := 1 TO 9 DO\n    \nEND_FOR" << 1 << 4;
    QTest::newRow("WHILE") << ST << "" << 0 << "WHILE x DO"
                           << "WHILE x DO\n    \nEND_WHILE" << 1 << 4;
    QTest::newRow("REPEAT") << ST << "" << 0 << "REPEAT"
                            << "REPEAT\n    \nUNTIL\nEND_REPEAT" << 1 << 4;
    QTest::newRow("VAR") << ST << "" << 0 << "VAR"
                         << "VAR\n    \nEND_VAR" << 1 << 4;
    QTest::newRow("PROGRAM") << ST << "" << 0 << "PROGRAM Main"
                             << "PROGRAM Main\n\nEND_PROGRAM" << 1 << 0;
    QTest::newRow("FUNCTION_BLOCK") << ST << "" << 0 << "FUNCTION_BLOCK Fb"
                                    << "FUNCTION_BLOCK Fb\n\nEND_FUNCTION_BLOCK" << 1 << 0;
    QTest::newRow("TYPE STRUCT") << ST << "" << 0 << "TYPE M : STRUCT"
                                 << "TYPE M : STRUCT\n    \nEND_STRUCT\nEND_TYPE" << 1 << 4;
    QTest::newRow("auto-indent") << ST << "    x := 1;" << 0 << ""
                                 << "    x := 1;\n    " << 1 << 4;
    QTest::newRow("END_IF; dedents") << ST << "IF x THEN\n    y := 1;\n    " << 2 << "END_IF;"
                                     << "IF x THEN\n    y := 1;\nEND_IF;\n"
                                     << 3 << 0;
    QTest::newRow("ELSE dedents then indents") << ST << "IF x THEN\n    y := 1;\n    " << 2 << "ELSE"
                                               << "IF x THEN\n    y := 1;\nELSE\n    " << 3 << 4;
    QTest::newRow("IL has no IF block") << IL << "" << 0 << "IF x THEN"
                                        << "IF x THEN\n"
                                        << 1 << 0;
    QTest::newRow("IL VAR block") << IL << "" << 0 << "VAR"
                                  << "VAR\n    \nEND_VAR" << 1 << 4;
}

void TestCodeEditor::blockCompletion()
{
    QFETCH(TextLanguage, language);
    QFETCH(QString, initial);
    QFETCH(int, line);
    QFETCH(QString, typed);
    QFETCH(QString, expected);
    QFETCH(int, cursorLine);
    QFETCH(int, cursorColumn);
    CodeEditor editor(language);
    editor.setBodyText(initial);
    placeAtEndOfLine(editor, line);
    QTest::keyClicks(&editor, typed);
    QTest::keyClick(&editor, Qt::Key_Return);
    QCOMPARE(editor.toPlainText(), expected);
    QCOMPARE(editor.textCursor().blockNumber(), cursorLine);
    QCOMPARE(editor.textCursor().positionInBlock(), cursorColumn);
}

void TestCodeEditor::blockCompletionIsOneUndoStep()
{
    CodeEditor editor;
    editor.setBodyText(QStringLiteral("IF x THEN"));
    placeAtEndOfLine(editor, 0);
    QTest::keyClick(&editor, Qt::Key_Return);
    QCOMPARE(editor.toPlainText(), QStringLiteral("IF x THEN\n    \nEND_IF"));
    editor.undo();
    QCOMPARE(editor.toPlainText(), QStringLiteral("IF x THEN"));
    editor.redo();
    QCOMPARE(editor.toPlainText(), QStringLiteral("IF x THEN\n    \nEND_IF"));
}

void TestCodeEditor::tabIndentsAndShiftTabOutdents()
{
    CodeEditor editor;
    editor.setBodyText(QStringLiteral("a;\nb;\nc;"));
    placeCursor(editor, 1);
    QTest::keyClick(&editor, Qt::Key_Tab);
    QCOMPARE(editor.toPlainText(), QStringLiteral("a   ;\nb;\nc;"));
    editor.setBodyText(QStringLiteral("a;\nb;\nc;"));
    placeCursor(editor, 4, 0); // lines 0 and 1
    QTest::keyClick(&editor, Qt::Key_Tab);
    QCOMPARE(editor.toPlainText(), QStringLiteral("    a;\n    b;\nc;"));
    QTest::keyClick(&editor, Qt::Key_Backtab);
    QCOMPARE(editor.toPlainText(), QStringLiteral("a;\nb;\nc;"));
}

void TestCodeEditor::bracketsAreMarked()
{
    CodeEditor editor;
    editor.setBodyText(QStringLiteral("y := (a + b[1]) * 2; (* ( *)"));
    auto bracketPositions = [&editor] {
        QList<int> positions;
        for (const QTextEdit::ExtraSelection &selection : editor.extraSelections()) {
            if (selection.format.hasProperty(QTextFormat::BackgroundBrush)
                && !selection.format.property(QTextFormat::FullWidthSelection).toBool())
                positions.append(selection.cursor.selectionStart());
        }
        return positions;
    };
    placeCursor(editor, 5); // before "("
    QCOMPARE(bracketPositions(), (QList<int> {5, 14}));
    placeCursor(editor, 15); // after ")"
    QCOMPARE(bracketPositions(), (QList<int> {14, 5}));
    placeCursor(editor, 12); // after "[": the bracket before the cursor
    QCOMPARE(bracketPositions(), (QList<int> {11, 13}));
    placeCursor(editor, 8);
    QCOMPARE(bracketPositions(), QList<int> {});
    placeCursor(editor, 24); // the "(" inside the comment is not a bracket
    QCOMPARE(bracketPositions(), QList<int> {});
}

void TestCodeEditor::currentLineIsHighlighted()
{
    CodeEditor editor;
    editor.setBodyText(QStringLiteral("a;\nb;\nc;"));
    placeCursor(editor, 4);
    const QList<QTextEdit::ExtraSelection> selections = editor.extraSelections();
    QVERIFY(!selections.isEmpty());
    QVERIFY(selections.first().format.property(QTextFormat::FullWidthSelection).toBool());
    QCOMPARE(selections.first().cursor.blockNumber(), 1);
}

void TestCodeEditor::gutterWidthFollowsLineCount()
{
    CodeEditor editor;
    editor.resize(400, 300);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    auto *gutter = editor.findChild<QWidget *>(QStringLiteral("lineNumberArea"));
    QVERIFY(gutter);
    editor.setBodyText(QStringLiteral("a;\nb;"));
    const int small = editor.lineNumberAreaWidth();
    QCOMPARE(gutter->width(), small);
    editor.setBodyText(QString(QStringLiteral("x;\n")).repeated(12000));
    QVERIFY(editor.lineNumberAreaWidth() > small); // five digits instead of three
    QCOMPARE(gutter->width(), editor.lineNumberAreaWidth());
    QCOMPARE(editor.viewport()->geometry().left(), gutter->geometry().right() + 1);
}

void TestCodeEditor::commentToggleAndUndoInOneStep()
{
    CodeEditor editor;
    const QString original = QStringLiteral("a := 1;\n    b := 2;\nc := 3;");
    editor.setBodyText(original);
    placeCursor(editor, 12, 2); // from line 0 into line 1
    QTest::keyClick(&editor, Qt::Key_Slash, Qt::ControlModifier);
    QCOMPARE(editor.toPlainText(), QStringLiteral("(* a := 1; *)\n    (* b := 2; *)\nc := 3;"));
    QCOMPARE(editor.textCursor().selectedText(),
        QStringLiteral("(* a := 1; *)") + QChar::ParagraphSeparator + QStringLiteral("    (* b := 2; *)"));
    editor.toggleComment();
    QCOMPARE(editor.toPlainText(), original);
    editor.toggleComment();
    editor.undo();
    QCOMPARE(editor.toPlainText(), original);

    // Without a selection: the current line only.
    placeAtEndOfLine(editor, 2);
    editor.toggleComment();
    QCOMPARE(editor.toPlainText(), QStringLiteral("a := 1;\n    b := 2;\n(* c := 3; *)"));
    editor.undo();
    QCOMPARE(editor.toPlainText(), original);
}

void TestCodeEditor::findNextPreviousAndOptions()
{
    TextEditorWidget widget;
    CodeEditor *editor = widget.editor();
    FindReplaceBar *bar = widget.findBar();
    editor->setBodyText(QStringLiteral("Level := Level + 1;\nLevelMax := 10;\nlevel := 0;"));
    placeCursor(*editor, 0);
    bar->setFindText(QStringLiteral("Level"));
    auto selection
        = [editor] { return std::pair(editor->textCursor().selectionStart(), editor->textCursor().selectionEnd()); };
    QVERIFY(bar->findNext());
    QCOMPARE(selection(), std::pair(0, 5));
    QVERIFY(bar->findNext());
    QCOMPARE(selection(), std::pair(9, 14));
    QVERIFY(bar->findNext());
    QCOMPARE(selection(), std::pair(20, 25)); // LevelMax: not whole words
    QVERIFY(bar->findNext());
    QCOMPARE(selection(), std::pair(36, 41)); // "level": case-insensitive
    QVERIFY(bar->findNext());
    QCOMPARE(selection(), std::pair(0, 5)); // wrapped
    QCOMPARE(bar->statusText(), QStringLiteral("Search wrapped"));
    QVERIFY(bar->findPrevious());
    QCOMPARE(selection(), std::pair(36, 41));

    bar->setCaseSensitive(true);
    bar->setWholeWords(true);
    placeCursor(*editor, 15);
    QVERIFY(bar->findNext());
    QCOMPARE(selection(), std::pair(0, 5)); // skips LevelMax and level, wraps
    bar->setFindText(QStringLiteral("Nothing"));
    QVERIFY(!bar->findNext());
    QCOMPARE(bar->statusText(), QStringLiteral("Not found"));
}

void TestCodeEditor::replaceAndReplaceAllInOneUndoStep()
{
    TextEditorWidget widget;
    CodeEditor *editor = widget.editor();
    FindReplaceBar *bar = widget.findBar();
    const QString original = QStringLiteral("Level := Level + 1;\nLevelMax := 10;\nlevel := 0;");
    editor->setBodyText(original);
    bar->setFindText(QStringLiteral("Level"));
    bar->setReplaceText(QStringLiteral("Height"));
    bar->setCaseSensitive(true);
    bar->setWholeWords(true);

    placeCursor(*editor, 0);
    QVERIFY(bar->findNext());
    bar->replace(); // replaces the match and moves on to the next
    QCOMPARE(editor->toPlainText(), QStringLiteral("Height := Level + 1;\nLevelMax := 10;\nlevel := 0;"));
    QCOMPARE(editor->textCursor().selectionStart(), 10);
    editor->undo();
    QCOMPARE(editor->toPlainText(), original);

    QCOMPARE(bar->replaceAll(), 2);
    QCOMPARE(editor->toPlainText(), QStringLiteral("Height := Height + 1;\nLevelMax := 10;\nlevel := 0;"));
    QCOMPARE(bar->statusText(), QStringLiteral("2 replaced"));
    editor->undo();
    QCOMPARE(editor->toPlainText(), original);
    editor->redo();
    QCOMPARE(editor->toPlainText(), QStringLiteral("Height := Height + 1;\nLevelMax := 10;\nlevel := 0;"));
    editor->undo();

    bar->setCaseSensitive(false);
    bar->setWholeWords(false);
    bar->setReplaceText(QStringLiteral("LevelLevel")); // contains the search text: must not loop
    QCOMPARE(bar->replaceAll(), 4);
    QCOMPARE(
        editor->toPlainText(), QStringLiteral("LevelLevel := LevelLevel + 1;\nLevelLevelMax := 10;\nLevelLevel := 0;"));
    editor->undo();
    QCOMPARE(editor->toPlainText(), original);
}

void TestCodeEditor::findBarShortcuts()
{
    TextEditorWidget widget;
    widget.show();
    QApplication::setActiveWindow(&widget);
    QVERIFY(QTest::qWaitForWindowActive(&widget));
    CodeEditor *editor = widget.editor();
    editor->setBodyText(QStringLiteral("alpha beta alpha"));
    editor->setFocus();
    placeCursor(*editor, 5, 0); // "alpha" selected
    QVERIFY(widget.findBar()->isHidden());
    QTest::keyClick(editor, Qt::Key_F, Qt::ControlModifier);
    QVERIFY(widget.findBar()->isVisible());
    QVERIFY(!widget.findBar()->isReplaceShown());
    QCOMPARE(widget.findBar()->findText(), QStringLiteral("alpha"));
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Return);
    QCOMPARE(editor->textCursor().selectionStart(), 11);
    QTest::keyClick(QApplication::focusWidget(), Qt::Key_Escape);
    QVERIFY(widget.findBar()->isHidden());
    QCOMPARE(QApplication::focusWidget(), editor);

    // F3 finds the next match from the editor; Ctrl+H opens the bar with the replace row.
    placeCursor(*editor, 0);
    QTest::keyClick(editor, Qt::Key_F3);
    QCOMPARE(editor->textCursor().selectionStart(), 0);
    QTest::keyClick(editor, Qt::Key_F3);
    QCOMPARE(editor->textCursor().selectionStart(), 11);
    QTest::keyClick(editor, Qt::Key_H, Qt::ControlModifier);
    QVERIFY(widget.findBar()->isVisible());
    QVERIFY(widget.findBar()->isReplaceShown());
}

void TestCodeEditor::diagnosticsUnderlineExactRanges()
{
    CodeEditor editor;
    editor.setBodyText(QStringLiteral("x := 1;\ny := ;\nz := 3"));
    editor.setDiagnostics({{2, 6, 1, TextDiagnostic::Severity::Error, QStringLiteral("Expression expected")},
        {1, 1, 1, TextDiagnostic::Severity::Warning, QStringLiteral("x is never read")},
        {3, 7, 0, TextDiagnostic::Severity::Error, QStringLiteral("';' expected")},
        {9, 1, 3, TextDiagnostic::Severity::Error, QStringLiteral("beyond the text")}});
    const QList<QTextEdit::ExtraSelection> marks = underlines(editor);
    QCOMPARE(marks.size(), 3);
    QCOMPARE(marks[0].cursor.selectionStart(), 13);
    QCOMPARE(marks[0].cursor.selectionEnd(), 14);
    QCOMPARE(marks[0].format.underlineColor(), QColor(0xe0, 0x1b, 0x1b));
    QCOMPARE(marks[1].cursor.selectionStart(), 0);
    QCOMPARE(marks[1].cursor.selectionEnd(), 1);
    QCOMPARE(marks[1].format.underlineColor(), QColor(0xe0, 0x9a, 0x00));
    QCOMPARE(marks[2].cursor.selectionStart(), 20); // after the end of "z := 3": its last character
    QCOMPARE(marks[2].cursor.selectionEnd(), 21);
    QCOMPARE(editor.diagnosticMessageAt(13), QStringLiteral("Expression expected"));
    QCOMPARE(editor.diagnosticMessageAt(12), QString());
    QCOMPARE(editor.diagnosticMessageAt(0), QStringLiteral("x is never read"));

    editor.setDiagnostics({});
    QVERIFY(underlines(editor).isEmpty());
}

void TestCodeEditor::diagnosticsFollowEditsAndShowTooltips()
{
    CodeEditor editor;
    editor.resize(500, 300);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    editor.setBodyText(QStringLiteral("x := 1;\ny := undefinedName;"));
    editor.setDiagnostics({{2, 6, 13, TextDiagnostic::Severity::Error, QStringLiteral("Unknown name")}});
    placeCursor(editor, 0);
    QTest::keyClick(&editor, Qt::Key_Return);
    const QList<TextDiagnostic> moved = editor.diagnostics();
    QCOMPARE(moved.size(), 1);
    QCOMPARE(moved[0].line, 3);
    QCOMPARE(moved[0].column, 6);
    QCOMPARE(moved[0].length, 13);

    // Hovering the underlined name shows the message.
    QTextCursor at(editor.document());
    at.setPosition(editor.document()->findBlockByNumber(2).position() + 8);
    const QPoint point = editor.cursorRect(at).center() + QPoint(2, 0);
    QHelpEvent help(QEvent::ToolTip, point, editor.viewport()->mapToGlobal(point));
    QApplication::sendEvent(editor.viewport(), &help);
    QCOMPARE(QToolTip::text(), QStringLiteral("Unknown name"));
    QToolTip::hideText();
}

void TestCodeEditor::foldingHidesAndShowsBlocks()
{
    CodeEditor editor;
    editor.resize(400, 300);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    editor.setBodyText(
        QStringLiteral("VAR\n    a : INT;\nEND_VAR\nIF a > 0 THEN\n    a := 0;\n    b := 1;\nEND_IF\nc := 2;"));
    QCOMPARE(editor.foldRanges(), (QList<FoldRange> {{0, 2}, {3, 6}}));
    QVERIFY(editor.fold(3));
    QVERIFY(editor.isFolded(3));
    QVERIFY(!editor.isFolded(0));
    const QTextDocument *document = editor.document();
    QVERIFY(document->findBlockByNumber(3).isVisible());
    for (int line : {4, 5, 6})
        QVERIFY(!document->findBlockByNumber(line).isVisible());
    QVERIFY(document->findBlockByNumber(7).isVisible());
    // The line after the fold now sits right under the folded line.
    auto lineRect
        = [&editor, document](int line) { return editor.cursorRect(QTextCursor(document->findBlockByNumber(line))); };
    QCOMPARE(lineRect(7).top() - lineRect(3).top(), lineRect(3).height());

    // A click on the gutter marker unfolds.
    const int y = lineRect(3).center().y();
    editor.lineNumberAreaClicked(QPoint(editor.lineNumberAreaWidth() - 5, y));
    QVERIFY(!editor.isFolded(3));
    QVERIFY(document->findBlockByNumber(5).isVisible());

    // Moving the cursor into a folded range unfolds it.
    QVERIFY(editor.fold(0));
    editor.goToLine(2, 3);
    QVERIFY(!editor.isFolded(0));
    QCOMPARE(editor.textCursor().blockNumber(), 1);
    QVERIFY(!editor.fold(1)); // no range starts there
}

void TestCodeEditor::foldingSurvivesEditsAbove()
{
    CodeEditor editor;
    editor.setBodyText(QStringLiteral("x := 1;\nIF a THEN\n    b := 1;\nEND_IF"));
    QVERIFY(editor.fold(1));
    placeCursor(editor, 0);
    QTest::keyClick(&editor, Qt::Key_Return);
    // Before the debounced update the markers moved with the text; after it, too.
    QCOMPARE(editor.foldRanges(), (QList<FoldRange> {{2, 4}}));
    editor.updateFoldRangesNow();
    QCOMPARE(editor.foldRanges(), (QList<FoldRange> {{2, 4}}));
    QVERIFY(editor.isFolded(2));
    // Breaking the block removes the range and shows its lines.
    QTextCursor end(editor.document()->findBlockByNumber(4));
    end.insertText(QStringLiteral("x"));
    QCOMPARE(editor.document()->findBlockByNumber(4).text(), QStringLiteral("xEND_IF"));
    editor.updateFoldRangesNow();
    QVERIFY(editor.foldRanges().isEmpty());
    QVERIFY(editor.document()->findBlockByNumber(3).isVisible());
}

void TestCodeEditor::completionPopupForVariablesAndMembers()
{
    FakeProvider provider;
    CodeEditor editor;
    editor.setCompletionProvider(&provider);
    editor.resize(500, 300);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    editor.setBodyText(QStringLiteral("x := Ta"));
    placeAtEndOfLine(editor, 0);
    QTest::keyClick(&editor, Qt::Key_Space, Qt::ControlModifier);
    QAbstractItemView *popup = editor.completer()->popup();
    QVERIFY(popup->isVisible());
    QStringList shown;
    for (int row = 0; row < editor.completer()->completionModel()->rowCount(); ++row)
        shown.append(editor.completer()->completionModel()->index(row, 0).data().toString());
    QCOMPARE(shown, (QStringList {"TAN", "Tank", "TankCtl"}));

    // Typing narrows the list; Enter inserts the current entry.
    QTest::keyClick(&editor, Qt::Key_N);
    QTest::keyClick(&editor, Qt::Key_K);
    QCOMPARE(editor.completer()->completionCount(), 2);
    QTest::keyClick(popup, Qt::Key_Return);
    QCOMPARE(editor.toPlainText(), QStringLiteral("x := Tank"));
    QVERIFY(!popup->isVisible());

    // '.' opens the members.
    QTest::keyClick(&editor, Qt::Key_Period);
    QVERIFY(popup->isVisible());
    QCOMPARE(editor.completer()->completionCount(), 2);
    QTest::keyClick(popup, Qt::Key_Down);
    QTest::keyClick(popup, Qt::Key_Return);
    QCOMPARE(editor.toPlainText(), QStringLiteral("x := Tank.Valve"));

    // Escape closes without inserting.
    QTest::keyClick(&editor, Qt::Key_Semicolon);
    QTest::keyClick(&editor, Qt::Key_Space, Qt::ControlModifier);
    QVERIFY(popup->isVisible());
    QTest::keyClick(popup, Qt::Key_Escape);
    QVERIFY(!popup->isVisible());
    QCOMPARE(editor.toPlainText(), QStringLiteral("x := Tank.Valve;"));
}

void TestCodeEditor::completionInsertsASingleCandidateDirectly()
{
    FakeProvider provider;
    CodeEditor editor;
    editor.setCompletionProvider(&provider);
    editor.setBodyText(QStringLiteral("y := SQR"));
    placeAtEndOfLine(editor, 0);
    QTest::keyClick(&editor, Qt::Key_Space, Qt::ControlModifier);
    QCOMPARE(editor.toPlainText(), QStringLiteral("y := SQRT"));
    editor.setBodyText(QStringLiteral("gAl"));
    placeAtEndOfLine(editor, 0);
    editor.showCompletion();
    QCOMPARE(editor.toPlainText(), QStringLiteral("gAlarm"));
}

void TestCodeEditor::inputAssistantInsertsAnIlOperator()
{
    FakeProvider provider;
    CodeEditor editor(TextLanguage::IL);
    editor.setCompletionProvider(&provider);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    editor.setBodyText(QStringLiteral("LD Temp\n"));
    placeCursor(editor, 8);
    QTest::keyClick(&editor, Qt::Key_F2);
    InputAssistantDialog *dialog = editor.inputAssistant();
    QVERIFY(dialog);
    QVERIFY(dialog->isVisible());
    QCOMPARE(dialog->category(), InputAssistantDialog::Category::Operators);
    QVERIFY(dialog->selectItem(QStringLiteral("ANDN(")));
    auto *tree = dialog->findChild<QTreeWidget *>();
    QVERIFY(tree);
    QTest::keyClick(tree, Qt::Key_Return);
    QCOMPARE(editor.toPlainText(), QStringLiteral("LD Temp\nANDN("));
    QVERIFY(!dialog->isVisible());
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    QVERIFY(!editor.inputAssistant()); // closed and deleted

    // An operand replaces the selection.
    placeCursor(editor, 7, 3);
    editor.openInputAssistant();
    dialog = editor.inputAssistant();
    dialog->setCategory(InputAssistantDialog::Category::Operands);
    QVERIFY(dialog->selectItem(QStringLiteral("gAlarm")));
    auto *buttons = dialog->findChild<QDialogButtonBox *>();
    QVERIFY(buttons);
    buttons->button(QDialogButtonBox::Ok)->click();
    QCOMPARE(editor.toPlainText(), QStringLiteral("LD gAlarm\nANDN("));
}

void TestCodeEditor::inputAssistantCategories()
{
    FakeProvider provider;
    InputAssistantDialog il(TextLanguage::IL, &provider);
    const QStringList operators = il.itemTexts();
    for (const char *op :
        {"LD", "LDN", "ST", "STN", "S", "R", "AND", "ANDN(", "OR", "XOR", "ADD", "SUB", "MUL", "DIV", "GT", "GE", "EQ",
            "NE", "LE", "LT", "JMP", "JMPC", "JMPCN", "CAL", "CALC", "CALCN", "RET", "RETC", "RETCN", ")"})
        QVERIFY2(operators.contains(QLatin1String(op)), op);
    il.setCategory(InputAssistantDialog::Category::Operands);
    QCOMPARE(il.itemTexts(), (QStringList {"Tank", "Temp", "gAlarm", "TRUE", "FALSE"}));
    il.setCategory(InputAssistantDialog::Category::Functions);
    QVERIFY(il.itemTexts().contains(QStringLiteral("LIMIT")));
    QVERIFY(il.itemTexts().contains(QStringLiteral("INT_TO_REAL")));
    QCOMPARE(il.itemTexts().last(), QStringLiteral("Scale"));
    QVERIFY(!il.itemTexts().contains(QStringLiteral("TON")));
    il.setCategory(InputAssistantDialog::Category::FunctionBlocks);
    QCOMPARE(il.itemTexts(),
        (QStringList {
            "SR", "RS", "R_TRIG", "F_TRIG", "CTU", "CTD", "CTUD", "TP", "TON", "TOF", "RTC", "UNPACK", "HYSTERESIS",
            "LIMITALARM", "BLINK", "GEN", "LIN_TRAFO", "DERIVATIVE", "INTEGRAL", "STATISTICS_INT", "STATISTICS_REAL",
            "VARIANCE", "CHARCURVE", "RAMP_INT", "RAMP_REAL", "PD", "PID", "PID_FIXCYCLE", "LOGGER", "TankCtl",
            "Main"}));
    il.setFilter(QStringLiteral("ct"));
    QCOMPARE(il.itemTexts(), (QStringList {"CTU", "CTD", "CTUD", "TankCtl"}));

    InputAssistantDialog st(TextLanguage::ST, nullptr);
    QCOMPARE(st.itemTexts().first(), QStringLiteral(":="));
    QVERIFY(!st.itemTexts().contains(QStringLiteral("LD")));
}

// Ctrl+V of text with control characters (a NUL once cut a saved body short): they are dropped,
// tabs and line breaks stay, and the paste is one undo step.
void TestCodeEditor::pasteDropsCharactersAFileCannotKeep()
{
    CodeEditor editor;
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    editor.setBodyText(QStringLiteral("x := 1;"));
    placeCursor(editor, 7);
    QApplication::clipboard()->setText(QStringLiteral("\n\ty := 2;\x01 (* a") + QChar(0) + QStringLiteral("b\x1b *)") + QChar(0xFFFF));
    QTest::keyClick(&editor, Qt::Key_V, Qt::ControlModifier);
    QCOMPARE(editor.toPlainText(), QStringLiteral("x := 1;\n\ty := 2; (* ab *)"));
    editor.undo();
    QCOMPARE(editor.toPlainText(), QStringLiteral("x := 1;"));
}

void TestCodeEditor::goToDefinitionSignal()
{
    CodeEditor editor;
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    editor.setBodyText(QStringLiteral("a := 1;\nx := Tank.Level + Temp;"));
    QSignalSpy spy(&editor, &CodeEditor::definitionRequested);
    placeCursor(editor, 8 + 12); // inside "Level"
    QTest::keyClick(&editor, Qt::Key_F12);
    QCOMPARE(spy.size(), 1);
    QCOMPARE(spy[0][0].toString(), QStringLiteral("Tank.Level"));
    QCOMPARE(spy[0][1].toInt(), 2);
    QCOMPARE(spy[0][2].toInt(), 11);

    // Ctrl+click on "Temp".
    QTextCursor at(editor.document());
    at.setPosition(8 + 19);
    QTest::mouseClick(editor.viewport(), Qt::LeftButton, Qt::ControlModifier, editor.cursorRect(at).center());
    QCOMPARE(spy.size(), 2);
    QCOMPARE(spy[1][0].toString(), QStringLiteral("Temp"));
    QCOMPARE(spy[1][2].toInt(), 19);

    placeCursor(editor, 8 + 15 + 2); // on "+": nothing to resolve
    editor.requestDefinition();
    QCOMPARE(spy.size(), 2);
}

void TestCodeEditor::textEditedIsDebouncedAndSkipsSetBodyText()
{
    CodeEditor editor;
    QSignalSpy spy(&editor, &CodeEditor::textEdited);
    editor.setBodyText(QStringLiteral("x := 1;"));
    editor.flushPendingEdit();
    QCOMPARE(spy.size(), 0);
    placeAtEndOfLine(editor, 0);
    QTest::keyClicks(&editor, QStringLiteral(" y"));
    QCOMPARE(spy.size(), 0); // still waiting for a quiet moment
    editor.flushPendingEdit();
    QCOMPARE(spy.size(), 1);
    editor.flushPendingEdit();
    QCOMPARE(spy.size(), 1);
    // setBodyText starts a fresh undo history.
    editor.setBodyText(QStringLiteral("z;"));
    QVERIFY(!editor.document()->isUndoAvailable());
    editor.flushPendingEdit();
    QCOMPARE(spy.size(), 1);
}

QTEST_MAIN(TestCodeEditor)
#include "tst_codeeditor.moc"
