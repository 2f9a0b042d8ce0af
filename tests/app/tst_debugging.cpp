// Breakpoints and stepping in the window: F9 and a click in the margin toggle a breakpoint on
// an ST line, the program halts there mid-cycle with the line in yellow and the status bar
// saying where, Step Over moves to the next line, a single cycle finishes the halted one.
#include "app/documentarea.h"
#include "app/mainwindow.h"
#include "app/messagespane.h"
#include "app/online/breakpointdialog.h"
#include "app/online/breakpointlines.h"
#include "app/online/debugcontroller.h"
#include "app/online/onlinecontroller.h"
#include "editors/common/diagramview.h"
#include "editors/cfc/cfceditor.h"
#include "editors/common/editorlanguage.h"
#include "editors/ld/ldeditor.h"
#include "editors/sfc/sfceditor.h"
#include "editors/text/codeeditor.h"
#include "editors/text/texteditorwidget.h"
#include "interpreter/frontend/iecreader.h"
#include "model/plcopen/reader.h"
#include "model/projectmodel.h"
#include "model/savedbreakpoints.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QLabel>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>

#include "../interpreter/graphical/diagram.h"

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
    void ladderNetworkBreakpoint();
    void sfcStepBreakpoint();
    void cfcElementBreakpoint();
    void propertiesDialog();
    void hitCountFromTheWindow();
    void callStackInTheMessages();
    void runToCursor();
    void linesFollowEdits_data();
    void linesFollowEdits();
    void breakpointsFollowTheirLines();
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
    QCOMPARE(window.statusBar()->currentMessage(), QString()); // "Halted in …" went with the halt
    QVERIFY(!window.debugger().stepOutAction()->isEnabled());
    online.logout();
    // The breakpoint stays with the body after logout.
    QCOMPARE(editor->breakpointLines(), QList<int>{3});

    // Saved with the project (our own addData) and back after opening it again.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("debug.xml"));
    QVERIFY(window.saveProject(path));
    QVERIFY(window.projectModel().project().addData.empty()); // the model itself is not changed
    window.projectModel().reset(model::Project{});
    QVERIFY(window.debugger().breakpoints().empty());
    const model::plcopen::ReadResult read = model::plcopen::readProjectFile(path);
    QCOMPARE(model::savedBreakpoints(read.project).size(), size_t(1));
    QCOMPARE(model::savedBreakpoints(read.project).front().pou, QStringLiteral("Main"));
    QCOMPARE(model::savedBreakpoints(read.project).front().line, 3);
    window.projectModel().reset(read.project);
    QCOMPARE(window.debugger().breakpoints().size(), size_t(1));
    QCOMPARE(window.debugger().breakpoints().front().place.line, 3);
    // A breakpoint switched off is kept and drawn hollow.
    QWidget *reopened = window.documents().openBody({window.projectModel().project().findPou(QStringLiteral("Main"))->id, model::BodyRef::Part::Pou, {}});
    editors::CodeEditor *again = reopened->findChild<editors::TextEditorWidget *>()->editor();
    const DebugController::StoredBreakpoint stored = window.debugger().breakpoints().front();
    interp::Breakpoint off = stored.settings;
    off.enabled = false;
    window.debugger().setBreakpointSettings(stored.body, stored.place, off);
    QCOMPARE(again->breakpointLines(), QList<int>{3});
    QCOMPARE(again->disabledBreakpointLines(), QList<int>{3});
}

// F9 on a network of the star-delta example: its band gets the dot, the program halts there
// with the band tinted, Step Over moves to the next network.
void TestDebugging::ladderNetworkBreakpoint()
{
    MainWindow window;
    window.online().setThreaded(false);
    model::plcopen::ReadResult read = model::plcopen::readProjectFile(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/star_delta.xml"));
    window.projectModel().reset(read.project);
    const model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
    QVERIFY(main);
    QWidget *document = window.documents().openBody({main->id, model::BodyRef::Part::Pou, {}});
    auto *ld = document->findChild<editors::ld::LdEditor *>();
    QVERIFY(ld);
    QVERIFY(ld->document().networks.size() >= 3);
    ld->setCursor(editors::ld::LdCursor::atNetwork(1));
    window.debugger().toggleBreakpointAction()->trigger();
    QCOMPARE(window.debugger().breakpoints().size(), size_t(1));
    QCOMPARE(ld->view()->breakpointMarks().size(), 1);
    const QRectF secondBand = ld->view()->breakpointMarks().front();
    // Switched off in its properties it is drawn hollow, and back.
    const DebugController::StoredBreakpoint stored = window.debugger().breakpoints().front();
    interp::Breakpoint off = stored.settings;
    off.enabled = false;
    window.debugger().setBreakpointSettings(stored.body, stored.place, off);
    QVERIFY(ld->view()->breakpointMarks().isEmpty());
    QCOMPARE(ld->view()->disabledBreakpointMarks(), QList<QRectF>{secondBand});
    window.debugger().setBreakpointSettings(stored.body, stored.place, stored.settings);
    QCOMPARE(ld->view()->breakpointMarks(), QList<QRectF>{secondBand});
    QVERIFY(ld->view()->disabledBreakpointMarks().isEmpty());

    OnlineController &online = window.online();
    QVERIFY(online.login());
    online.singleCycle();
    QVERIFY(online.latestSnapshot()->halt);
    QCOMPARE(online.latestSnapshot()->halt->cycle, 1);
    QCOMPARE(ld->view()->haltedMark(), secondBand);
    QVERIFY2(window.statusBar()->currentMessage().startsWith(QStringLiteral("Halted in Main at network 2 (cycle 1).")),
             qPrintable(window.statusBar()->currentMessage()));
    window.debugger().stepOverAction()->trigger();
    QVERIFY(online.latestSnapshot()->halt);
    QVERIFY(ld->view()->haltedMark().top() > secondBand.top());
    QVERIFY2(window.statusBar()->currentMessage().startsWith(QStringLiteral("Halted in Main at network 3 (cycle 1).")),
             qPrintable(window.statusBar()->currentMessage()));
    online.singleCycle();
    QVERIFY(!online.latestSnapshot()->halt);
    QVERIFY(ld->view()->haltedMark().isEmpty());
    // F9 again on the same network takes the breakpoint away.
    online.logout();
    ld->setCursor(editors::ld::LdCursor::atNetwork(1));
    window.debugger().toggleBreakpointAction()->trigger();
    QVERIFY(window.debugger().breakpoints().empty());
    QVERIFY(ld->view()->breakpointMarks().isEmpty());
}

// The mixing tank: a breakpoint on step FillA halts in the cycle after SB1 made the transition
// fire, with the step tinted and named in the status bar.
void TestDebugging::sfcStepBreakpoint()
{
    MainWindow window;
    window.online().setThreaded(false);
    window.projectModel().reset(model::plcopen::readProjectFile(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/mixing_tank.xml")).project);
    const model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
    QVERIFY(main);
    QWidget *document = window.documents().openBody({main->id, model::BodyRef::Part::Pou, {}});
    auto *chart = document->findChild<editors::sfc::SfcEditor *>();
    QVERIFY(chart);
    const quint64 fill = chart->stepId(QStringLiteral("FillA"));
    QVERIFY(fill != 0);
    chart->select({fill});
    window.debugger().toggleBreakpointAction()->trigger();
    QCOMPARE(chart->view()->breakpointMarks().size(), 1);

    OnlineController &online = window.online();
    QVERIFY(online.login());
    online.singleCycle();
    QVERIFY(!online.latestSnapshot()->halt);
    online.write(QStringLiteral("Tank.SB1"), QStringLiteral("TRUE"));
    online.singleCycle(); // the transition fires
    QVERIFY(!online.latestSnapshot()->halt);
    online.singleCycle(); // FillA is entered
    QVERIFY(online.latestSnapshot()->halt);
    QCOMPARE(online.latestSnapshot()->halt->cycle, 3);
    QCOMPARE(chart->view()->haltedMark(), chart->view()->breakpointMarks().front());
    QVERIFY2(window.statusBar()->currentMessage().startsWith(QStringLiteral("Halted in Main at step FillA (cycle 3).")),
             qPrintable(window.statusBar()->currentMessage()));
    online.singleCycle();
    QVERIFY(!online.latestSnapshot()->halt);
    online.singleCycle(); // FillA stays active: no halt
    QVERIFY(!online.latestSnapshot()->halt);
}

// A CFC: a + 1 -> b, (a + 1) * 2 -> c, numbered 1 to 4. F9 on the selected MUL box puts the
// breakpoint on it alone; the program halts before it runs, named by its number.
void TestDebugging::cfcElementBreakpoint()
{
    iec::testing::Diagram d;
    d.in(1, QStringLiteral("a")).in(3, QStringLiteral("1"), 0, 40);
    d.block(2, QStringLiteral("ADD"), QString(), {{QStringLiteral("IN1"), {{1}}}, {QStringLiteral("IN2"), {{3}}}},
            {QStringLiteral("OUT")});
    d.out(4, QStringLiteral("b"), {{2, QStringLiteral("OUT")}});
    d.in(6, QStringLiteral("2"), 0, 100);
    d.block(5, QStringLiteral("MUL"), QString(), {{QStringLiteral("IN1"), {{2, QStringLiteral("OUT")}}}, {QStringLiteral("IN2"), {{6}}}},
            {QStringLiteral("OUT")}, 300, 100);
    d.out(7, QStringLiteral("c"), {{5, QStringLiteral("OUT")}}, 500, 100);
    d.order(2, 1).order(4, 2).order(5, 3).order(7, 4);
    model::Project project = iec::testing::diagramProject(QStringLiteral("VAR a : INT := 5; b : INT; c : INT; END_VAR"),
                                                          model::BodyLanguage::FBD, d);
    model::Pou &pou = project.types.pous.back();
    pou.bodies.front().addData.push_back(
        {QString::fromLatin1(editors::kIecStudioCfcAddDataName), QStringLiteral("discard"), QString()});
    MainWindow window;
    window.online().setThreaded(false);
    window.projectModel().reset(project);
    const model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
    QWidget *document = window.documents().openBody({main->id, model::BodyRef::Part::Pou, {}});
    auto *cfc = document->findChild<editors::cfc::CfcEditor *>();
    QVERIFY(cfc);
    cfc->select({5});
    window.debugger().toggleBreakpointAction()->trigger();
    QCOMPARE(window.debugger().breakpoints().size(), size_t(1));
    QCOMPARE(window.debugger().breakpoints().front().place.elements, std::vector<qint64>{5});
    QCOMPARE(cfc->view()->breakpointMarks().size(), 1);

    OnlineController &online = window.online();
    QVERIFY(online.login());
    online.singleCycle();
    QVERIFY(online.latestSnapshot()->halt);
    QCOMPARE(online.latestSnapshot()->halt->at.localId, 5);
    QCOMPARE(cfc->view()->haltedMark(), cfc->view()->breakpointMarks().front());
    QVERIFY2(window.statusBar()->currentMessage().startsWith(QStringLiteral("Halted in Main at box 3 (MUL) (cycle 1).")),
             qPrintable(window.statusBar()->currentMessage()));
    window.debugger().stepOverAction()->trigger();
    QCOMPARE(online.latestSnapshot()->halt->at.localId, 7);
    QVERIFY2(window.statusBar()->currentMessage().startsWith(QStringLiteral("Halted in Main at output 4 (c) (cycle 1).")),
             qPrintable(window.statusBar()->currentMessage()));
}

void TestDebugging::propertiesDialog()
{
    interp::Breakpoint start;
    start.hitRule = interp::HitRule::Equal;
    start.hitTarget = 4;
    BreakpointDialog dialog(QStringLiteral("Main, line 3"), start, nullptr);
    QCOMPARE(dialog.hitRuleBox()->currentIndex(), int(interp::HitRule::Equal));
    QCOMPARE(dialog.hitTargetBox()->value(), 4);
    QVERIFY(dialog.hitTargetBox()->isEnabled());
    dialog.hitRuleBox()->setCurrentIndex(int(interp::HitRule::Always));
    QVERIFY(!dialog.hitTargetBox()->isEnabled());
    dialog.hitRuleBox()->setCurrentIndex(int(interp::HitRule::MultipleOf));
    dialog.hitTargetBox()->setValue(3);
    dialog.conditionEdit()->setText(QStringLiteral("Count = = 2"));
    QVERIFY(!dialog.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
    QCOMPARE(dialog.problemLabel()->text(), QStringLiteral("This is not an expression: Count = = 2"));
    dialog.conditionEdit()->setText(QStringLiteral(" Count = 2 "));
    QVERIFY(dialog.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
    dialog.enabledBox()->setChecked(false);
    const interp::Breakpoint result = dialog.settings();
    QCOMPARE(int(result.hitRule), int(interp::HitRule::MultipleOf));
    QCOMPARE(result.hitTarget, 3);
    QCOMPARE(result.condition, QStringLiteral("Count = 2"));
    QVERIFY(!result.enabled);
}

// A breakpoint on the first line that halts on its third hit only.
void TestDebugging::hitCountFromTheWindow()
{
    MainWindow window;
    window.online().setThreaded(false);
    window.projectModel().reset(interp::frontend::readIecText(QString::fromUtf8(kProgram), QStringLiteral("Test")).project);
    const model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
    const model::BodyRef body{main->id, model::BodyRef::Part::Pou, {}};
    window.documents().openBody(body);
    interp::Breakpoint settings;
    settings.hitRule = interp::HitRule::Equal;
    settings.hitTarget = 3;
    window.debugger().setBreakpointSettings(body, {1, -1, {}}, settings);
    OnlineController &online = window.online();
    QVERIFY(online.login());
    QStringList halts;
    for (int i = 0; i < 5; ++i) {
        online.singleCycle();
        if (online.latestSnapshot()->halt) {
            halts << QString::number(online.latestSnapshot()->halt->cycle);
            online.singleCycle(); // finishes the halted cycle
        }
    }
    QCOMPARE(halts, QStringList{QStringLiteral("3")});
    QCOMPARE(online.latestSnapshot()->cycle, 5);
}

// Halted inside a function block: the messages list the stack, innermost first.
void TestDebugging::callStackInTheMessages()
{
    const char *const source = "FUNCTION_BLOCK Acc\nVAR_INPUT x : INT; END_VAR\nVAR_OUTPUT total : INT; END_VAR\n"
                               "total := total + x;\nEND_FUNCTION_BLOCK\n"
                               "PROGRAM Main\nVAR a : Acc; n : INT; END_VAR\nn := n + 1;\na(x := n);\nEND_PROGRAM\n";
    MainWindow window;
    window.online().setThreaded(false);
    window.projectModel().reset(interp::frontend::readIecText(QString::fromUtf8(source), QStringLiteral("Test")).project);
    const model::Pou *acc = window.projectModel().project().findPou(QStringLiteral("Acc"));
    window.debugger().setBreakpointSettings({acc->id, model::BodyRef::Part::Pou, {}}, {1, -1, {}}, {});
    QVERIFY(window.online().login());
    window.online().singleCycle();
    QVERIFY(window.online().latestSnapshot()->halt);
    MessageListModel &messages = window.messagesPane().model();
    QStringList texts;
    for (int row = 0; row < messages.rowCount(); ++row)
        if (messages.message(row).text.startsWith(QStringLiteral("Halted in")) || messages.message(row).text.startsWith(QStringLiteral("Called from")))
            texts << QStringLiteral("%1 @%2:%3").arg(messages.message(row).text, messages.message(row).pouName).arg(messages.message(row).line);
    QCOMPARE(texts, (QStringList{QStringLiteral("Halted in Acc (instance Main.a) at line 1 (cycle 1). @Acc:1"),
                                 QStringLiteral("Called from Main at line 2. @Main:2")}));
    // The Acc editor came to the front with the line marked.
    auto *widget = window.documents().currentWidget()->findChild<editors::TextEditorWidget *>();
    QVERIFY(widget);
    QCOMPARE(widget->editor()->haltedLine(), 1);
    window.online().singleCycle();
    QVERIFY(!window.online().latestSnapshot()->halt);
    bool anyInfo = false;
    for (int row = 0; row < messages.rowCount(); ++row)
        anyInfo = anyInfo || messages.message(row).text.startsWith(QStringLiteral("Halted in"));
    QVERIFY(!anyInfo);
}

void TestDebugging::runToCursor()
{
    MainWindow window;
    window.online().setThreaded(false);
    window.projectModel().reset(interp::frontend::readIecText(QString::fromUtf8(kProgram), QStringLiteral("Test")).project);
    const model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
    QWidget *document = window.documents().openBody({main->id, model::BodyRef::Part::Pou, {}});
    editors::CodeEditor *editor = document->findChild<editors::TextEditorWidget *>()->editor();
    editor->goToLine(5);
    QCOMPARE(window.debugger().runToCursorAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_F10));
    window.debugger().runToCursorAction()->trigger();
    QTRY_VERIFY(window.online().latestSnapshot() && window.online().latestSnapshot()->halt);
    QCOMPARE(window.online().latestSnapshot()->halt->at.line, 5);
    QCOMPARE(window.online().latestSnapshot()->halt->cycle, 1);
    QCOMPARE(editor->haltedLine(), 5);
    QVERIFY(window.debugger().breakpoints().empty()); // no breakpoint stays behind
    QVERIFY(editor->breakpointLines().isEmpty());
    window.online().singleCycle(); // finishes cycle 1
    window.online().singleCycle(); // cycle 2 runs through
    QVERIFY(!window.online().latestSnapshot()->halt);
    QCOMPARE(window.online().latestSnapshot()->cycle, 2);
}

void TestDebugging::linesFollowEdits_data()
{
    QTest::addColumn<QString>("before");
    QTest::addColumn<QString>("after");
    QTest::addColumn<QList<int>>("lines"); // where lines 1..n of `before` go (0: deleted)
    QTest::newRow("nothing changed") << "a|b|c" << "a|b|c" << QList<int>{1, 2, 3};
    QTest::newRow("line inserted above") << "a|b|c" << "a|x|b|c" << QList<int>{1, 3, 4};
    QTest::newRow("line inserted at the top") << "a|b" << "x|a|b" << QList<int>{2, 3};
    QTest::newRow("line deleted") << "a|b|c|d" << "a|b|d" << QList<int>{1, 2, 0, 3};
    QTest::newRow("line edited") << "a|b|c" << "a|b2|c" << QList<int>{1, 2, 3};
    QTest::newRow("two lines become one") << "a|b|c|d" << "a|bc|d" << QList<int>{1, 2, 2, 3};
    QTest::newRow("line split") << "a|bc|d" << "a|b|c|d" << QList<int>{1, 2, 4};
    QTest::newRow("all replaced by an empty line") << "a|b" << "" << QList<int>{1, 1};
    QTest::newRow("same lines repeated") << "x|x|x" << "x|x" << QList<int>{1, 2, 0};
}

void TestDebugging::linesFollowEdits()
{
    QFETCH(QString, before);
    QFETCH(QString, after);
    QFETCH(QList<int>, lines);
    const QStringList from = before.split(QLatin1Char('|'));
    const QStringList to = after.split(QLatin1Char('|'));
    QList<int> got;
    for (int line = 1; line <= from.size(); ++line)
        got << lineAfterEdit(line, from, to);
    QCOMPARE(got, lines);
}

// A breakpoint stays on its statement while the text is edited, and goes with its line; undo
// brings it back where it was (the model's text is what it follows).
void TestDebugging::breakpointsFollowTheirLines()
{
    MainWindow window;
    window.projectModel().reset(interp::frontend::readIecText(QString::fromUtf8(kProgram), QStringLiteral("Test")).project);
    const model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
    QVERIFY(main);
    const model::BodyRef body {main->id, model::BodyRef::Part::Pou, {}};
    QWidget *document = window.documents().openBody(body);
    auto *widget = document->findChild<editors::TextEditorWidget *>();
    QVERIFY(widget);
    editors::CodeEditor *editor = widget->editor();
    editor->goToLine(3);
    window.debugger().toggleBreakpointAction()->trigger();
    editor->goToLine(5);
    window.debugger().toggleBreakpointAction()->trigger();
    QCOMPARE(editor->breakpointLines(), (QList<int>{3, 5}));

    // A line typed at the top: both move down.
    editor->goToLine(1);
    editor->moveCursor(QTextCursor::StartOfLine);
    QTest::keyClicks(editor, QStringLiteral("Count := 0;"));
    QTest::keyClick(editor, Qt::Key_Return);
    editor->flushPendingEdit();
    QCOMPARE(editor->breakpointLines(), (QList<int>{4, 6}));
    QCOMPARE(window.debugger().breakpoints().front().place.line, 4);
    QCOMPARE(editor->document()->findBlockByNumber(3).text().trimmed(), QStringLiteral("Level := Level + 10;"));

    // The line with the first breakpoint deleted: that breakpoint goes, the other moves up.
    editor->goToLine(4);
    editor->moveCursor(QTextCursor::StartOfLine);
    editor->moveCursor(QTextCursor::Down, QTextCursor::KeepAnchor);
    QTest::keyClick(editor, Qt::Key_Delete);
    editor->flushPendingEdit();
    QCOMPARE(editor->breakpointLines(), QList<int>{5});
    QCOMPARE(window.debugger().breakpoints().size(), size_t(1));

    // Undo brings the lines back, and the remaining breakpoint stays on its statement (the
    // deleted one is gone: breakpoints are no edit of the program).
    editor->undo();
    editor->flushPendingEdit();
    QCOMPARE(window.debugger().breakpoints().front().place.line, 6);
    editor->undo(); // the line break typed at the top
    editor->flushPendingEdit();
    QCOMPARE(window.debugger().breakpoints().front().place.line, 5);
    QCOMPARE(editor->breakpointLines(), QList<int>{5});
    QCOMPARE(editor->document()->findBlockByNumber(4).text().trimmed(), QStringLiteral("Total := Count + Level;"));
}

QTEST_MAIN(TestDebugging)
#include "tst_debugging.moc"
