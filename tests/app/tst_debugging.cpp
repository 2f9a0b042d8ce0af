// Breakpoints and stepping in the window: F9 and a click in the margin toggle a breakpoint on
// an ST line, the program halts there mid-cycle with the line in yellow and the status bar
// saying where, Step Over moves to the next line, a single cycle finishes the halted one.
#include "app/documentarea.h"
#include "app/mainwindow.h"
#include "app/online/debugcontroller.h"
#include "app/online/onlinecontroller.h"
#include "editors/text/codeeditor.h"
#include "editors/text/texteditorwidget.h"
#include "interpreter/frontend/iecreader.h"
#include "model/projectmodel.h"

#include <QAction>
#include <QLabel>
#include <QStatusBar>
#include <QTest>
#include <QTextBlock>

using namespace iec;
using namespace iec::app;

namespace {

// Body lines: 1 Count, 2 IF, 3 Level, 4 END_IF, 5 Total.
const char *const kProgram = R"(PROGRAM Main
VAR
  Count : INT;
  Start : BOOL;
  Level : INT;
  Total : INT;
END_VAR
Count := Count + 1;
IF Start THEN
  Level := Level + 10;
END_IF;
Total := Count + Level;
END_PROGRAM
)";

} // namespace

class TestDebugging : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void shortcuts();
    void breakpointHaltsStepsAndFinishesTheCycle();
};

void TestDebugging::shortcuts()
{
    MainWindow window;
    DebugController &debug = window.debugger();
    QCOMPARE(debug.toggleBreakpointAction()->shortcut(), QKeySequence(Qt::Key_F9));
    QCOMPARE(debug.stepOverAction()->shortcut(), QKeySequence(Qt::Key_F10));
    QCOMPARE(debug.stepIntoAction()->shortcut(), QKeySequence(Qt::Key_F8));
    QCOMPARE(debug.stepOutAction()->shortcut(), QKeySequence(Qt::SHIFT | Qt::Key_F10));
    QVERIFY(!debug.stepOutAction()->isEnabled()); // not halted
}

void TestDebugging::breakpointHaltsStepsAndFinishesTheCycle()
{
    MainWindow window;
    window.online().setThreaded(false);
    window.projectModel().reset(interp::frontend::readIecText(QString::fromUtf8(kProgram), QStringLiteral("Test")).project);
    const model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
    QVERIFY(main);
    QWidget *document = window.documents().openBody({main->id, model::BodyRef::Part::Pou, {}});
    auto *widget = document->findChild<editors::TextEditorWidget *>();
    QVERIFY(widget);
    editors::CodeEditor *editor = widget->editor();
    QCOMPARE(editor->document()->findBlockByNumber(2).text().trimmed(), QStringLiteral("Level := Level + 10;"));

    // F9 on line 3, a click in the margin on line 1, and again on line 1 to take it away.
    editor->goToLine(3);
    window.debugger().toggleBreakpointAction()->trigger();
    QCOMPARE(editor->breakpointLines(), QList<int>{3});
    const int y = editor->cursorRect(QTextCursor(editor->document()->firstBlock())).center().y();
    editor->lineNumberAreaClicked(QPoint(3, y));
    QCOMPARE(editor->breakpointLines(), (QList<int>{3, 1}));
    editor->lineNumberAreaClicked(QPoint(3, y));
    QCOMPARE(editor->breakpointLines(), QList<int>{3});
    QCOMPARE(window.debugger().breakpoints().size(), size_t(1));

    OnlineController &online = window.online();
    QVERIFY(online.login());
    online.singleCycle(); // Start is FALSE: line 3 does not run
    QVERIFY(!online.latestSnapshot()->halt);
    QCOMPARE(editor->haltedLine(), 0);
    online.write(QStringLiteral("Main.Start"), QStringLiteral("TRUE"));
    online.singleCycle();
    const auto halted = online.latestSnapshot();
    QVERIFY(halted->halt);
    QCOMPARE(halted->halt->cycle, 2);
    QCOMPARE(halted->halt->at.line, 3);
    QCOMPARE(editor->haltedLine(), 3);
    QVERIFY2(window.statusBar()->currentMessage().startsWith(QStringLiteral("Halted in Main at line 3 (cycle 2).")),
             qPrintable(window.statusBar()->currentMessage()));
    QVERIFY2(online.statusLabel()->text().contains(QStringLiteral("HALT")), qPrintable(online.statusLabel()->text()));
    QVERIFY(window.debugger().stepOutAction()->isEnabled());

    // Step Over: line 4 has no code, so the next line is 5; Level was added on the way.
    window.debugger().stepOverAction()->trigger();
    QCOMPARE(online.latestSnapshot()->halt->at.line, 5);
    QCOMPARE(editor->haltedLine(), 5);
    // A single cycle finishes the halted one; the clock moves on only now.
    online.singleCycle();
    QVERIFY(!online.latestSnapshot()->halt);
    QCOMPARE(online.latestSnapshot()->cycle, 2);
    QCOMPARE(editor->haltedLine(), 0);
    QVERIFY(!window.debugger().stepOutAction()->isEnabled());
    online.logout();
    // The breakpoint stays with the body after logout.
    QCOMPARE(editor->breakpointLines(), QList<int>{3});
}

QTEST_MAIN(TestDebugging)
#include "tst_debugging.moc"
