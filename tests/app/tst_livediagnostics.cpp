// Diagnostics while typing: a typo typed into an open body is marked (and listed) within a
// second of the last key, fixing it clears the mark; the compile runs on a worker thread, a result
// for text that changed meanwhile is dropped, and graphical bodies get their messages through the
// hook the diagram editors connect to.
#include "app/buildcontroller.h"
#include "app/documentarea.h"
#include "app/livediagnostics.h"
#include "app/mainwindow.h"
#include "app/messagespane.h"
#include "editors/text/codeeditor.h"
#include "interpreter/frontend/iecreader.h"
#include "model/projectmodel.h"
#include "testsettings.h"

#include <QElapsedTimer>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using namespace iec;
using namespace iec::app;

namespace {

const char *const kSource = R"(PROGRAM Main
VAR
  Count : INT;
END_VAR
Count := Count + 1;
END_PROGRAM
PROGRAM Chart
VAR
  Go : BOOL;
END_VAR
INITIAL_STEP Init:
END_STEP
STEP Run:
END_STEP
TRANSITION FROM Init TO Run
  := Go;
END_TRANSITION
TRANSITION FROM Run TO Init
  := NOT Go;
END_TRANSITION
END_PROGRAM
)";

model::BodyRef bodyOf(const model::ProjectModel &model, const char *name)
{
    return {model.project().findPou(QString::fromLatin1(name))->id, model::BodyRef::Part::Pou, {}};
}

} // namespace

class TestLiveDiagnostics : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void typoIsMarkedWithinASecondAndFixingClearsIt();
    void resultForOlderTextIsDropped();
    void compileDoesNotHoldTheUiThread();
    void graphicalBodiesGetTheirMessages();

private:
    QTemporaryDir m_configHome;
};

void TestLiveDiagnostics::initTestCase()
{
    useTestSettings(m_configHome);
}

void TestLiveDiagnostics::typoIsMarkedWithinASecondAndFixingClearsIt()
{
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.projectModel().reset(interp::frontend::readIecText(QString::fromUtf8(kSource), QStringLiteral("T")).project);
    const model::BodyRef main = bodyOf(window.projectModel(), "Main");
    window.documents().openBody(main);
    editors::CodeEditor *editor = window.documents().textEditorFor(main);
    editor->setFocus();
    QSignalSpy published(&window.liveDiagnostics(), &LiveDiagnostics::published);
    // The opened project was compiled in the background already: nothing to mark.
    QVERIFY(published.wait(2000) || published.count() > 0);
    QVERIFY(editor->diagnostics().isEmpty());

    editor->moveCursor(QTextCursor::End);
    QTest::keyClick(editor, Qt::Key_Return);
    QTest::keyClicks(editor, QStringLiteral("Cuont := 2;"));
    QElapsedTimer sinceLastKey;
    sinceLastKey.start();
    QTRY_VERIFY_WITH_TIMEOUT(!editor->diagnostics().isEmpty(), 1000);
    QVERIFY2(sinceLastKey.elapsed() < 1000, qPrintable(QString::number(sinceLastKey.elapsed())));
    const editors::TextDiagnostic mark = editor->diagnostics().front();
    QCOMPARE(mark.line, 2);
    QCOMPARE(mark.column, 1);
    QCOMPARE(mark.length, 5);
    QVERIFY(window.messagesPane().model().count(Message::Severity::Error) >= 1);

    // Fixing it clears the mark and the message.
    QTextCursor cursor = editor->textCursor();
    cursor.movePosition(QTextCursor::StartOfBlock);
    cursor.movePosition(QTextCursor::Right, QTextCursor::KeepAnchor, 5);
    editor->setTextCursor(cursor);
    QTest::keyClicks(editor, QStringLiteral("Count"));
    QTRY_VERIFY_WITH_TIMEOUT(editor->diagnostics().isEmpty(), 1000);
    QCOMPARE(window.messagesPane().model().count(Message::Severity::Error), 0);
}

void TestLiveDiagnostics::resultForOlderTextIsDropped()
{
    MainWindow window;
    window.projectModel().reset(interp::frontend::readIecText(QString::fromUtf8(kSource), QStringLiteral("T")).project);
    LiveDiagnostics &live = window.liveDiagnostics();
    QSignalSpy published(&live, &LiveDiagnostics::published);
    QSignalSpy discarded(&live, &LiveDiagnostics::discarded);
    const model::BodyRef main = bodyOf(window.projectModel(), "Main");
    live.compileNow();
    const quint64 compiled = window.projectModel().revision();
    // The text changes before the result is taken in (results come back through the event loop).
    window.projectModel().setBodyText(main, QStringLiteral("Count := Undeclared;"));
    QVERIFY(discarded.wait(5000));
    QCOMPARE(discarded.front().front().toULongLong(), compiled);
    QCOMPARE(window.messagesPane().model().count(Message::Severity::Error), 0);
    // The change is compiled after the pause, and that result shows.
    QVERIFY(published.wait(5000));
    QCOMPARE(published.back().front().toULongLong(), window.projectModel().revision());
    QCOMPARE(published.back().at(1).toInt(), 1);
}

void TestLiveDiagnostics::compileDoesNotHoldTheUiThread()
{
    MainWindow window;
    window.projectModel().reset(interp::frontend::readIecText(QString::fromUtf8(kSource), QStringLiteral("T")).project);
    LiveDiagnostics &live = window.liveDiagnostics();
    QSignalSpy published(&live, &LiveDiagnostics::published);
    live.compileNow();
    QVERIFY(live.isCompiling()); // compileNow returned while the compile goes on elsewhere
    bool uiRan = false;
    QTimer::singleShot(0, [&] { uiRan = uiRan || published.isEmpty(); });
    QVERIFY(published.wait(5000));
    QVERIFY(uiRan); // the event loop ran before the result came
    QVERIFY(!live.isCompiling());
}

void TestLiveDiagnostics::graphicalBodiesGetTheirMessages()
{
    MainWindow window;
    model::Project project = interp::frontend::readIecText(QString::fromUtf8(kSource), QStringLiteral("T")).project;
    window.projectModel().reset(project);
    const model::BodyRef chart = bodyOf(window.projectModel(), "Chart");
    window.documents().openBody(chart);
    QSignalSpy hook(&window.buildController(), &BuildController::graphicalDiagnosticsChanged);
    QSignalSpy published(&window.liveDiagnostics(), &LiveDiagnostics::published);
    // A declaration the chart uses goes away: its conditions no longer compile.
    window.projectModel().setInterface(chart.pou, model::Interface {});
    QVERIFY(published.wait(5000));
    QVERIFY(!hook.isEmpty());
    const auto [ref, messages] = std::pair {hook.back().at(0).value<model::BodyRef>(), hook.back().at(1).value<QList<Message>>()};
    QCOMPARE(ref, chart);
    QVERIFY(!messages.isEmpty());
    QCOMPARE(messages.front().pouName, QStringLiteral("Chart"));
}

QTEST_MAIN(TestLiveDiagnostics)
#include "tst_livediagnostics.moc"
