// Online mode: the runtime worker driven directly (one thread, deterministic), and the window's
// online controller in synchronous mode: login, single cycles, watch pane, write, force,
// release, compile errors, runtime faults, editing refused, editors restored at logout. One test
// runs the worker on its thread at full speed and waits on its signals.
#include "app/documentarea.h"
#include "app/mainwindow.h"
#include "app/messagespane.h"
#include "app/online/onlinecontroller.h"
#include "app/online/runtimeworker.h"
#include "app/online/watchpane.h"
#include "app/undostacks.h"
#include "editors/text/codeeditor.h"
#include "editors/text/texteditorwidget.h"
#include "interpreter/compiler/compiler.h"
#include "interpreter/frontend/iecreader.h"
#include "model/projectmodel.h"

#include <QCompleter>
#include <QDir>
#include <QLabel>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTreeView>

using namespace iec;
using namespace iec::app;

namespace {

const char *const kProgram = R"(PROGRAM Main
VAR
  Count : INT;
  Start : BOOL;
  Level : INT;
  Divisor : INT := 1;
  Quotient : INT;
END_VAR
Count := Count + 1;
IF Start THEN
  Level := Level + 10;
END_IF;
Quotient := 100 / Divisor;
END_PROGRAM
)";

std::shared_ptr<const interp::Module> compiled(const char *source)
{
    interp::Diagnostics diagnostics;
    auto module = interp::compileText(QString::fromUtf8(source), diagnostics);
    if (!module)
        qWarning() << diagnostics.all().size() << "diagnostics";
    return module;
}

model::Project projectFrom(const char *source)
{
    return interp::frontend::readIecText(QString::fromUtf8(source), QStringLiteral("Test")).project;
}

// The latest snapshot a worker published, collected without threads.
struct Collector {
    std::shared_ptr<const interp::RuntimeSnapshot> last;
    int count = 0;
    explicit Collector(RuntimeWorker &worker)
    {
        QObject::connect(&worker, &RuntimeWorker::snapshotReady, &worker,
            [this](std::shared_ptr<const interp::RuntimeSnapshot> snapshot) {
                last = std::move(snapshot);
                ++count;
            });
    }
    QString value(const QString &name) const { return last ? last->value(name) : QString(); }
};

} // namespace

class TestOnline : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void workerSingleCyclesPublishValues();
    void workerWriteAppliesOnceAtTheNextCycle();
    void workerForceHoldsUntilReleased();
    void workerWriteToAnInputVariableReachesTheProgram();
    void workerRejectsBadWrites_data();
    void workerRejectsBadWrites();
    void workerFaults_data();
    void workerFaults();
    void workerRunsNCyclesThenStops();
    void workerResets();
    void loginSingleCyclesAndWatchPane();
    void watchPaneWritesForcesAndReleases();
    void compileErrorBlocksLogin();
    void runtimeFaultLandsInTheMessagesPane();
    void loggerLinesLandInTheMessagesPane();
    void textEditorShowsValuesAndRefusesEditing();
    void logoutRestoresEditors();
    void addToWatchFromTheEditor();
    void writeAndForceKeysWorkFromTheEditor();
    void documentOpenedWhileOnlineAsksForItsValues();
    void watchCompletionOffersSymbols();
    void threadedRunStaysResponsiveAndStops();
    void windowOnlineRenders();

private:
    // A window with kProgram loaded, Main open, the controller in synchronous mode.
    std::unique_ptr<MainWindow> windowWithProgram(const char *source = kProgram);
    static editors::TextEditorWidget *textWidgetOf(MainWindow &window, const QString &pou);

    QTemporaryDir m_configHome;
};

void TestOnline::initTestCase()
{
    qputenv("XDG_CONFIG_HOME", m_configHome.path().toLocal8Bit());
    QCoreApplication::setOrganizationName(QStringLiteral("IEC Studio Tests"));
}

// ---- the worker on its own ----------------------------------------------------------------------

void TestOnline::workerSingleCyclesPublishValues()
{
    RuntimeWorker worker(compiled(kProgram), 7, 10'000'000);
    Collector snapshots(worker);
    worker.setWatch({{QStringLiteral("Main.Count"), QStringLiteral("Main.Level"), QStringLiteral("Nope")}, {}});
    QCOMPARE(snapshots.count, 1);
    QCOMPARE(snapshots.value(QStringLiteral("Main.Count")), QStringLiteral("0"));
    QVERIFY(!snapshots.last->values.contains(QStringLiteral("Nope"))); // unknown names have no value
    for (int cycle = 1; cycle <= 3; ++cycle) {
        worker.singleCycle();
        QCOMPARE(snapshots.last->cycle, cycle);
        QCOMPARE(snapshots.last->modelRevision, quint64(7));
        QCOMPARE(snapshots.last->timeNs, cycle * 10'000'000LL);
        QCOMPARE(snapshots.last->running, false);
        QCOMPARE(snapshots.value(QStringLiteral("Main.Count")), QString::number(cycle));
        QCOMPARE(snapshots.value(QStringLiteral("Main.Level")), QStringLiteral("0"));
    }
    QCOMPARE(snapshots.count, 4);
}

void TestOnline::workerWriteAppliesOnceAtTheNextCycle()
{
    RuntimeWorker worker(compiled(kProgram), 0, 10'000'000);
    Collector snapshots(worker);
    worker.setWatch({{QStringLiteral("Main.Start"), QStringLiteral("Main.Level")}, {}});
    worker.write(QStringLiteral("Main.Start"), QStringLiteral("TRUE"));
    worker.publish();
    QCOMPARE(snapshots.value(QStringLiteral("Main.Start")), QStringLiteral("FALSE")); // not before the cycle
    worker.singleCycle();
    QCOMPARE(snapshots.value(QStringLiteral("Main.Start")), QStringLiteral("TRUE"));
    QCOMPARE(snapshots.value(QStringLiteral("Main.Level")), QStringLiteral("10"));
    worker.singleCycle(); // the variable keeps what was written; the write is not repeated
    QCOMPARE(snapshots.value(QStringLiteral("Main.Level")), QStringLiteral("20"));
    worker.write(QStringLiteral("Main.Level"), QStringLiteral("5"));
    worker.write(QStringLiteral("Main.Start"), QStringLiteral("FALSE"));
    worker.singleCycle();
    QCOMPARE(snapshots.value(QStringLiteral("Main.Level")), QStringLiteral("5"));
    worker.singleCycle();
    QCOMPARE(snapshots.value(QStringLiteral("Main.Level")), QStringLiteral("5"));
    QVERIFY(snapshots.last->forced.isEmpty());
}

void TestOnline::workerForceHoldsUntilReleased()
{
    RuntimeWorker worker(compiled(kProgram), 0, 10'000'000);
    Collector snapshots(worker);
    worker.setWatch({{QStringLiteral("Main.Count")}, {}});
    worker.force(QStringLiteral("Main.Count"), QStringLiteral("100"));
    QCOMPARE(snapshots.value(QStringLiteral("Main.Count")), QStringLiteral("100")); // at once
    QVERIFY(snapshots.last->isForced(QStringLiteral("main.count")));
    for (int cycle = 0; cycle < 3; ++cycle) {
        worker.singleCycle(); // Count := Count + 1 every cycle, yet the force wins
        QCOMPARE(snapshots.value(QStringLiteral("Main.Count")), QStringLiteral("100"));
    }
    worker.release(QStringLiteral("Main.Count"));
    QVERIFY(!snapshots.last->isForced(QStringLiteral("Main.Count")));
    worker.singleCycle();
    QCOMPARE(snapshots.value(QStringLiteral("Main.Count")), QStringLiteral("101"));
    worker.force(QStringLiteral("Main.Count"), QStringLiteral("7"));
    worker.releaseAll();
    QVERIFY(snapshots.last->forced.isEmpty());
    worker.singleCycle();
    QCOMPARE(snapshots.value(QStringLiteral("Main.Count")), QStringLiteral("8"));
}

void TestOnline::workerWriteToAnInputVariableReachesTheProgram()
{
    // A variable at an input address is copied from the input image each cycle; a write to it
    // must reach the program anyway.
    RuntimeWorker worker(compiled(R"(PROGRAM Main
VAR
  Button AT %IX0.0 : BOOL;
  Presses : INT;
END_VAR
IF Button THEN Presses := Presses + 1; END_IF;
END_PROGRAM
)"), 0, 10'000'000);
    Collector snapshots(worker);
    worker.setWatch({{QStringLiteral("Main.Button"), QStringLiteral("Main.Presses")}, {}});
    worker.write(QStringLiteral("Main.Button"), QStringLiteral("TRUE"));
    worker.singleCycle();
    QCOMPARE(snapshots.value(QStringLiteral("Main.Button")), QStringLiteral("TRUE"));
    QCOMPARE(snapshots.value(QStringLiteral("Main.Presses")), QStringLiteral("1"));
    worker.singleCycle(); // the input keeps its value until written again
    QCOMPARE(snapshots.value(QStringLiteral("Main.Presses")), QStringLiteral("2"));
}

void TestOnline::workerRejectsBadWrites_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("literal");
    QTest::addColumn<QString>("mentions");
    QTest::newRow("unknown variable") << QStringLiteral("Main.Nope") << QStringLiteral("1") << QStringLiteral("Main.Nope");
    QTest::newRow("not an INT") << QStringLiteral("Main.Count") << QStringLiteral("hello") << QStringLiteral("Main.Count");
    QTest::newRow("not a BOOL") << QStringLiteral("Main.Start") << QStringLiteral("maybe") << QStringLiteral("Main.Start");
}

void TestOnline::workerRejectsBadWrites()
{
    QFETCH(QString, name);
    QFETCH(QString, literal);
    QFETCH(QString, mentions);
    RuntimeWorker worker(compiled(kProgram), 0, 10'000'000);
    Collector snapshots(worker);
    worker.setWatch({{QStringLiteral("Main.Count")}, {}});
    QSignalSpy failed(&worker, &RuntimeWorker::commandFailed);
    worker.write(name, literal);
    QCOMPARE(failed.size(), 1);
    QVERIFY2(failed.front().front().toString().contains(mentions), qPrintable(failed.front().front().toString()));
    worker.force(name, literal);
    QCOMPARE(failed.size(), 2);
    worker.singleCycle(); // nothing was queued
    QCOMPARE(snapshots.value(QStringLiteral("Main.Count")), QStringLiteral("1"));
    QVERIFY(snapshots.last->forced.isEmpty());
}

void TestOnline::workerFaults_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<int>("faultCycle");
    QTest::addColumn<int>("line");
    QTest::addColumn<int>("kind");
    QTest::newRow("division by zero in cycle 3") << QStringLiteral(R"(PROGRAM Main
VAR n : INT; q : INT; END_VAR
n := n + 1;
q := 10 / (3 - n);
END_PROGRAM
)") << 3 << 4 << int(interp::FaultKind::DivisionByZero);
    QTest::newRow("endless loop") << QStringLiteral(R"(PROGRAM Main
VAR n : INT; END_VAR
WHILE TRUE DO
  n := n + 1;
END_WHILE;
END_PROGRAM
)") << 1 << 3 << int(interp::FaultKind::BudgetExceeded);
}

void TestOnline::workerFaults()
{
    QFETCH(QString, source);
    QFETCH(int, faultCycle);
    QFETCH(int, line);
    QFETCH(int, kind);
    RuntimeWorker worker(compiled(source.toUtf8().constData()), 0, 10'000'000);
    worker.setBudget(10'000);
    Collector snapshots(worker);
    QSignalSpy faults(&worker, &RuntimeWorker::faulted);
    QSignalSpy stopped(&worker, &RuntimeWorker::stopped);
    worker.run();
    QVERIFY(worker.isRunning());
    worker.setSpeed(RunSpeed::AsFastAsPossible);
    QVERIFY(stopped.wait(5000));
    QCOMPARE(faults.size(), 1);
    const auto fault = faults.front().front().value<interp::RuntimeFault>();
    QCOMPARE(int(fault.kind), kind);
    QCOMPARE(fault.pou, QStringLiteral("Main"));
    QCOMPARE(fault.line, line);
    QCOMPARE(fault.cycle, faultCycle);
    QVERIFY(!worker.isRunning());
    QVERIFY(snapshots.last->fault.has_value());
    QCOMPARE(snapshots.last->running, false);
    worker.singleCycle(); // a faulted program stays stopped until a reset
    QCOMPARE(faults.size(), 1);
    worker.coldReset();
    QVERIFY(!snapshots.last->fault.has_value());
    QCOMPARE(snapshots.last->cycle, 0);
}

void TestOnline::workerRunsNCyclesThenStops()
{
    RuntimeWorker worker(compiled(kProgram), 0, 1'000'000);
    worker.setSpeed(RunSpeed::AsFastAsPossible);
    Collector snapshots(worker);
    worker.setWatch({{QStringLiteral("Main.Count")}, {}});
    QSignalSpy stopped(&worker, &RuntimeWorker::stopped);
    worker.run(250);
    QVERIFY(stopped.wait(5000));
    QCOMPARE(snapshots.last->cycle, 250);
    QCOMPARE(snapshots.value(QStringLiteral("Main.Count")), QStringLiteral("250"));
    QCOMPARE(snapshots.last->running, false);
}

void TestOnline::workerResets()
{
    RuntimeWorker worker(compiled(R"(PROGRAM Main
VAR RETAIN Kept : INT; END_VAR
VAR Lost : INT; END_VAR
Kept := Kept + 1; Lost := Lost + 1;
END_PROGRAM
)"), 0, 10'000'000);
    Collector snapshots(worker);
    worker.setWatch({{QStringLiteral("Main.Kept"), QStringLiteral("Main.Lost")}, {}});
    worker.singleCycle();
    worker.singleCycle();
    worker.setCycleTime(5'000'000); // applies at the next reset
    QCOMPARE(snapshots.last->cycleNs, 10'000'000LL);
    worker.warmReset();
    QCOMPARE(snapshots.last->cycle, 0);
    QCOMPARE(snapshots.last->cycleNs, 5'000'000LL);
    QCOMPARE(snapshots.value(QStringLiteral("Main.Kept")), QStringLiteral("2"));
    QCOMPARE(snapshots.value(QStringLiteral("Main.Lost")), QStringLiteral("0"));
    worker.singleCycle();
    QCOMPARE(snapshots.last->timeNs, 5'000'000LL);
    worker.coldReset();
    QCOMPARE(snapshots.value(QStringLiteral("Main.Kept")), QStringLiteral("0"));
}

// ---- the window -----------------------------------------------------------------------------------

std::unique_ptr<MainWindow> TestOnline::windowWithProgram(const char *source)
{
    auto window = std::make_unique<MainWindow>();
    window->online().setThreaded(false);
    window->projectModel().reset(projectFrom(source));
    const model::Pou *main = window->projectModel().project().findPou(QStringLiteral("Main"));
    if (main)
        window->documents().openBody({main->id, model::BodyRef::Part::Pou, {}});
    return window;
}

editors::TextEditorWidget *TestOnline::textWidgetOf(MainWindow &window, const QString &pou)
{
    const model::Pou *found = window.projectModel().project().findPou(pou);
    QWidget *document = found ? window.documents().documentFor({found->id, model::BodyRef::Part::Pou, {}}) : nullptr;
    return document ? document->findChild<editors::TextEditorWidget *>() : nullptr;
}

void TestOnline::loginSingleCyclesAndWatchPane()
{
    auto window = windowWithProgram();
    OnlineController &online = window->online();
    WatchPane &watch = window->watchPane();
    QVERIFY(watch.addVariable(QStringLiteral("Main.Count")));
    QVERIFY(watch.addVariable(QStringLiteral("Main.Level")));
    QVERIFY(!watch.addVariable(QStringLiteral("main.count"))); // once
    QVERIFY(!online.isOnline());

    QVERIFY(online.login());
    QVERIFY(online.isOnline());
    QCOMPARE(watch.model().value(0), QStringLiteral("0"));
    QCOMPARE(watch.model().data(watch.model().index(0, WatchModel::TypeColumn), Qt::DisplayRole).toString(),
             QStringLiteral("INT"));
    for (int cycle = 1; cycle <= 3; ++cycle) {
        online.singleCycle();
        QCOMPARE(online.latestSnapshot()->cycle, cycle);
        QCOMPARE(watch.model().value(0), QString::number(cycle));
        QCOMPARE(watch.model().value(1), QStringLiteral("0"));
        QVERIFY2(online.statusLabel()->text().contains(QStringLiteral("cycle %1").arg(cycle)),
                 qPrintable(online.statusLabel()->text()));
    }
    online.logout();
    QVERIFY(!online.isOnline());
    QCOMPARE(watch.model().value(0), QString()); // offline: no values, the names stay
    QCOMPARE(watch.model().names(), (QStringList{QStringLiteral("Main.Count"), QStringLiteral("Main.Level")}));
    QCOMPARE(online.statusLabel()->text(), QStringLiteral("Offline"));
}

void TestOnline::watchPaneWritesForcesAndReleases()
{
    auto window = windowWithProgram();
    OnlineController &online = window->online();
    WatchPane &watch = window->watchPane();
    watch.addVariable(QStringLiteral("Main.Start"));
    watch.addVariable(QStringLiteral("Main.Level"));
    watch.addVariable(QStringLiteral("Main.Count"));
    online.singleCycle(); // logs in and runs cycle 1
    QCOMPARE(online.latestSnapshot()->cycle, 1);

    // Write: applied once at the start of the next cycle.
    watch.model().setPrepared(0, QStringLiteral("TRUE"));
    watch.writePrepared();
    QCOMPARE(watch.model().prepared(0), QString());
    QCOMPARE(watch.model().value(0), QStringLiteral("FALSE"));
    online.singleCycle();
    QCOMPARE(watch.model().value(0), QStringLiteral("TRUE"));
    QCOMPARE(watch.model().value(1), QStringLiteral("10"));
    online.singleCycle();
    QCOMPARE(watch.model().value(1), QStringLiteral("20"));

    // Force: held every cycle, marked.
    watch.model().setPrepared(2, QStringLiteral("42"));
    watch.forcePrepared();
    QVERIFY(watch.model().isForced(2));
    QCOMPARE(watch.model().data(watch.model().index(2, WatchModel::ValueColumn), Qt::DisplayRole).toString(),
             QStringLiteral("42 (forced)"));
    for (int cycle = 0; cycle < 2; ++cycle) {
        online.singleCycle();
        QCOMPARE(watch.model().value(2), QStringLiteral("42"));
    }
    // Release the selected row.
    watch.view()->selectionModel()->select(watch.model().index(2, 0),
                                           QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    watch.releaseSelected();
    QVERIFY(!watch.model().isForced(2));
    online.singleCycle();
    QCOMPARE(watch.model().value(2), QStringLiteral("43"));
    // Nothing of this is in the model or on an undo stack.
    QVERIFY(window->undoStacks().isClean());
    QVERIFY(!window->hasUnsavedChanges());
}

void TestOnline::compileErrorBlocksLogin()
{
    auto window = windowWithProgram(R"(PROGRAM Main
VAR Count : INT; END_VAR
Count := Countr + 1;
END_PROGRAM
)");
    OnlineController &online = window->online();
    QVERIFY(!online.login());
    QVERIFY(!online.isOnline());
    online.singleCycle();
    QVERIFY(!online.isOnline());
    online.loginAndRun();
    QVERIFY(!online.isOnline());
    const MessageListModel &messages = window->messagesPane().model();
    QVERIFY(messages.count(Message::Severity::Error) >= 1);
    QCOMPARE(messages.message(0).pouName, QStringLiteral("Main"));
    QVERIFY(messages.message(0).text.contains(QStringLiteral("Countr")));
    QVERIFY(window->statusBar()->currentMessage().contains(QStringLiteral("errors")));
}

void TestOnline::runtimeFaultLandsInTheMessagesPane()
{
    auto window = windowWithProgram();
    OnlineController &online = window->online();
    WatchPane &watch = window->watchPane();
    watch.addVariable(QStringLiteral("Main.Divisor"));
    QSignalSpy faults(&online, &OnlineController::faultShown);
    online.singleCycle();
    watch.model().setPrepared(0, QStringLiteral("0"));
    watch.writePrepared();
    online.singleCycle();
    QCOMPARE(faults.size(), 1);
    QVERIFY(online.latestSnapshot()->fault.has_value());
    const MessageListModel &messages = window->messagesPane().model();
    QCOMPARE(messages.count(Message::Severity::Error), 1);
    const Message &message = messages.message(0);
    QCOMPARE(message.pouName, QStringLiteral("Main"));
    const model::Pou *main = window->projectModel().project().findPou(QStringLiteral("Main"));
    const QStringList bodyLines = main->body()->text().split(QLatin1Char('\n'));
    const int expectedLine = int(bodyLines.indexOf(QStringLiteral("Quotient := 100 / Divisor;"))) + 1;
    QVERIFY(expectedLine > 0);
    QCOMPARE(message.line, expectedLine);
    QVERIFY2(message.text.contains(QStringLiteral("cycle 2")), qPrintable(message.text));
    QVERIFY(online.statusLabel()->text().contains(QStringLiteral("FAULT")));
    // A reset clears the fault and its message.
    online.resetCold();
    QVERIFY(!online.latestSnapshot()->fault.has_value());
    QCOMPARE(messages.count(Message::Severity::Error), 0);
}

// Beremiz's LOGGER: what the program logs is listed in the Messages pane, at its level, each
// line once; a new login starts a new list.
void TestOnline::loggerLinesLandInTheMessagesPane()
{
    auto window = windowWithProgram("PROGRAM Main\nVAR l : LOGGER; n : INT; END_VAR\nn := n + 1;\n"
                                    "l(TRIG := n MOD 2 = 0, MSG := CONCAT('tick ', INT_TO_STRING(n)), LEVEL := WARNING);\nEND_PROGRAM\n");
    OnlineController &online = window->online();
    const MessageListModel &messages = window->messagesPane().model();
    for (int cycle = 0; cycle < 4; ++cycle)
        online.singleCycle();
    QStringList texts;
    for (int row = 0; row < messages.rowCount(); ++row)
        texts << messages.message(row).text;
    QCOMPARE(texts, QStringList({QStringLiteral("Program log: WARNING: tick 2 (cycle 2)"),
                                 QStringLiteral("Program log: WARNING: tick 4 (cycle 4)")}));
    QCOMPARE(messages.count(Message::Severity::Warning), 2);
    online.logout();
    QCOMPARE(messages.rowCount(), 2); // kept to be read after logout
    online.singleCycle();
    online.singleCycle();
    QCOMPARE(messages.rowCount(), 1);
    QCOMPARE(messages.message(0).text, QStringLiteral("Program log: WARNING: tick 2 (cycle 2)"));
}

void TestOnline::documentOpenedWhileOnlineAsksForItsValues()
{
    auto window = std::make_unique<MainWindow>();
    OnlineController &online = window->online();
    online.setThreaded(false);
    window->projectModel().reset(projectFrom(kProgram));
    online.singleCycle();
    QVERIFY(online.isOnline());
    QVERIFY(online.latestSnapshot()->values.isEmpty()); // no view asks for anything yet

    // Opened: the editor's names join the request at once (a snapshot of cycle 1 follows).
    const model::Pou *main = window->projectModel().project().findPou(QStringLiteral("Main"));
    QVERIFY(window->documents().openBody({main->id, model::BodyRef::Part::Pou, {}}));
    QCOMPARE(online.latestSnapshot()->cycle, 1);
    QCOMPARE(online.latestSnapshot()->value(QStringLiteral("Main.Count")), QStringLiteral("1"));
    online.singleCycle();
    QCOMPARE(online.latestSnapshot()->value(QStringLiteral("Main.Count")), QStringLiteral("2"));
    editors::CodeEditor *editor = textWidgetOf(*window, QStringLiteral("Main"))->editor();
    QVERIFY(editor->isOnline());

    // Closed: the next snapshots carry its names no more.
    window->documents().closeAll();
    QVERIFY(!online.latestSnapshot()->values.contains(QStringLiteral("Main.Count")));
    online.singleCycle();
    QCOMPARE(online.latestSnapshot()->cycle, 3);
    QVERIFY(online.latestSnapshot()->values.isEmpty());
}

void TestOnline::textEditorShowsValuesAndRefusesEditing()
{
    auto window = windowWithProgram();
    window->show();
    OnlineController &online = window->online();
    editors::TextEditorWidget *widget = textWidgetOf(*window, QStringLiteral("Main"));
    QVERIFY(widget);
    editors::CodeEditor *editor = widget->editor();
    QCOMPARE(widget->onlineInstance(), QStringLiteral("Main"));
    QVERIFY(widget->onlineNames().contains(QStringLiteral("Main.Count")));
    online.singleCycle();
    online.singleCycle();
    QVERIFY(editor->isOnline());
    QVERIFY(editor->isReadOnly());
    // The line "Count := Count + 1;" shows Count's value after its end.
    const QStringList lines = editor->toPlainText().split(QLatin1Char('\n'));
    const auto countLine = size_t(lines.indexOf(QStringLiteral("Count := Count + 1;")));
    QVERIFY(countLine < editor->onlineChips().size());
    QCOMPARE(editor->onlineChips()[countLine],
             (QList<editors::OnlineChip>{{QStringLiteral("Count"), QStringLiteral("2"), false}}));
    const auto ifLine = size_t(lines.indexOf(QStringLiteral("IF Start THEN")));
    QCOMPARE(editor->onlineChips()[ifLine],
             (QList<editors::OnlineChip>{{QStringLiteral("Start"), QStringLiteral("FALSE"), false}}));
    // A forced variable is marked in the editor too.
    online.force(QStringLiteral("Main.Start"), QStringLiteral("TRUE"));
    QCOMPARE(editor->onlineChips()[ifLine],
             (QList<editors::OnlineChip>{{QStringLiteral("Start"), QStringLiteral("TRUE"), true}}));

    // Typing, deleting, pasting are refused with a message; the text and the model stay.
    const QString before = editor->toPlainText();
    QSignalSpy refused(editor, &editors::CodeEditor::editRefused);
    editor->setFocus();
    QTest::keyClicks(editor, QStringLiteral("xyz"));
    QTest::keyClick(editor, Qt::Key_Backspace);
    QTest::keyClick(editor, Qt::Key_Return);
    QTest::keyClick(editor, Qt::Key_V, Qt::ControlModifier);
    editor->toggleComment();
    QCOMPARE(editor->toPlainText(), before);
    QCOMPARE(refused.size(), 7);
    QVERIFY(refused.front().front().toString().contains(QStringLiteral("Logout")));
    QVERIFY(widget->onlineBanner()->isVisible());
    QCOMPARE(widget->onlineBanner()->text(), editors::CodeEditor::onlineEditRefusal());
    window->documents().flushEdits();
    QCOMPARE(window->projectModel().project().findPou(QStringLiteral("Main"))->body()->text(), before);
    // Moving around still works.
    const int position = editor->textCursor().position();
    QTest::keyClick(editor, Qt::Key_Down);
    QVERIFY(editor->textCursor().position() != position);
    // The chips draw without trouble.
    QVERIFY(!editor->grab().isNull());
}

void TestOnline::logoutRestoresEditors()
{
    auto window = windowWithProgram();
    window->show();
    OnlineController &online = window->online();
    editors::TextEditorWidget *widget = textWidgetOf(*window, QStringLiteral("Main"));
    editors::CodeEditor *editor = widget->editor();
    QSignalSpy onlineChanged(&online, &OnlineController::onlineChanged);
    online.singleCycle();
    QVERIFY(editor->isOnline());
    QVERIFY(!editor->onlineChips().empty());
    online.logout();
    QCOMPARE(onlineChanged.size(), 2);
    QVERIFY(!editor->isOnline());
    QVERIFY(!editor->isReadOnly());
    QVERIFY(editor->onlineChips().empty());
    QVERIFY(!widget->onlineBanner()->isVisible());
    editor->setFocus();
    editor->moveCursor(QTextCursor::End);
    QTest::keyClicks(editor, QStringLiteral("(*x*)"));
    QVERIFY(editor->toPlainText().endsWith(QStringLiteral("(*x*)")));
    // A tab opened while online joins in at once; logging in again works.
    QVERIFY(online.login());
    QVERIFY(editor->isOnline());
}

void TestOnline::addToWatchFromTheEditor()
{
    auto window = windowWithProgram();
    editors::TextEditorWidget *widget = textWidgetOf(*window, QStringLiteral("Main"));
    Q_EMIT widget->editor()->addToWatchRequested(QStringLiteral("Level"));
    QCOMPARE(window->watchPane().model().names(), QStringList{QStringLiteral("Main.Level")});
}

// Write (Ctrl+F7), force (F7) and release (Alt+F7) reach the watch pane from wherever the focus
// is, as in CODESYS: a value prepared from an editor is written without clicking the pane first.
void TestOnline::writeAndForceKeysWorkFromTheEditor()
{
    auto window = windowWithProgram();
    window->show();
    QApplication::setActiveWindow(window.get());
    OnlineController &online = window->online();
    WatchPane &watch = window->watchPane();
    watch.addVariable(QStringLiteral("Main.Start"));
    watch.addVariable(QStringLiteral("Main.Count"));
    online.singleCycle();
    editors::TextEditorWidget *widget = textWidgetOf(*window, QStringLiteral("Main"));
    widget->editor()->setFocus();
    QVERIFY(QTest::qWaitForWindowActive(window.get()));
    watch.model().setPrepared(0, QStringLiteral("TRUE"));
    QTest::keyClick(widget->editor(), Qt::Key_F7, Qt::ControlModifier);
    QCOMPARE(watch.model().prepared(0), QString());
    online.singleCycle();
    QCOMPARE(watch.model().value(0), QStringLiteral("TRUE"));
    watch.model().setPrepared(1, QStringLiteral("42"));
    QTest::keyClick(widget->editor(), Qt::Key_F7);
    QVERIFY(watch.model().isForced(1));
    watch.view()->selectionModel()->select(watch.model().index(1, 0), QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    QTest::keyClick(widget->editor(), Qt::Key_F7, Qt::AltModifier);
    QVERIFY(!watch.model().isForced(1));
}

void TestOnline::watchCompletionOffersSymbols()
{
    const QStringList names = watchableNames(*compiled(R"(TYPE Tank : STRUCT Level : INT; Full : BOOL; END_STRUCT; END_TYPE
VAR_GLOBAL Alarm : BOOL; END_VAR
PROGRAM Main
VAR T : Tank; Timer : TON; END_VAR
T.Level := 1;
END_PROGRAM
)"));
    for (const char *expected : {"Alarm", "Main", "Main.T", "Main.T.Level", "Main.T.Full", "Main.Timer.Q", "Main.Timer.ET"})
        QVERIFY2(names.contains(QString::fromLatin1(expected)), expected);
    auto window = windowWithProgram();
    QVERIFY(window->online().login());
    QCompleter *completer = window->watchPane().completer();
    completer->setCompletionPrefix(QStringLiteral("main.le"));
    QCOMPARE(completer->currentCompletion(), QStringLiteral("Main.Level"));
}

void TestOnline::threadedRunStaysResponsiveAndStops()
{
    auto window = windowWithProgram();
    OnlineController &online = window->online();
    online.setThreaded(true);
    window->watchPane().addVariable(QStringLiteral("Main.Count"));
    online.setCycleTime(1'000'000);
    online.setSpeed(RunSpeed::AsFastAsPossible);
    QSignalSpy shown(&online, &OnlineController::snapshotShown);
    online.loginAndRun();
    QVERIFY(online.isOnline());
    // Snapshots arrive while it runs, at a bounded rate, with growing cycle counts.
    QTRY_VERIFY_WITH_TIMEOUT(online.latestSnapshot() && online.latestSnapshot()->running
                                 && online.latestSnapshot()->cycle > 1000,
                             10000);
    online.stop();
    QTRY_VERIFY_WITH_TIMEOUT(online.latestSnapshot() && !online.latestSnapshot()->running, 5000);
    const int stoppedAt = online.latestSnapshot()->cycle;
    QCOMPARE(online.latestSnapshot()->timeNs, stoppedAt * 1'000'000LL);
    QCOMPARE(window->watchPane().model().value(0), online.latestSnapshot()->value(QStringLiteral("Main.Count")));
    // At most about 20 snapshots a second reached the window, not one per cycle.
    QVERIFY2(shown.size() < stoppedAt / 10, qPrintable(QStringLiteral("%1 snapshots for %2 cycles").arg(shown.size()).arg(stoppedAt)));
    online.singleCycle();
    QTRY_COMPARE_WITH_TIMEOUT(online.latestSnapshot()->cycle, stoppedAt + 1, 5000);
    online.logout();
    QVERIFY(!online.isOnline());
}

// The window online, for looking at: IEC_SHOT_DIR=DIR saves DIR/mainwindow_online.png.
void TestOnline::windowOnlineRenders()
{
    auto window = windowWithProgram();
    window->resize(1280, 800);
    window->show();
    WatchPane &watch = window->watchPane();
    for (const char *name : {"Main.Count", "Main.Start", "Main.Level", "Main.Divisor", "Main.Quotient"})
        watch.addVariable(QString::fromLatin1(name));
    OnlineController &online = window->online();
    online.singleCycle();
    online.force(QStringLiteral("Main.Start"), QStringLiteral("TRUE"));
    for (int cycle = 0; cycle < 4; ++cycle)
        online.singleCycle();
    watch.model().setPrepared(3, QStringLiteral("4"));
    QCoreApplication::processEvents();
    const QImage image = window->grab().toImage();
    QVERIFY(!image.isNull());
    const QByteArray dir = qgetenv("IEC_SHOT_DIR");
    if (!dir.isEmpty())
        QVERIFY(image.save(QDir(QString::fromLocal8Bit(dir)).filePath(QStringLiteral("mainwindow_online.png"))));
}

QTEST_MAIN(TestOnline)
#include "tst_online.moc"
