// Prints what diagnostics while typing cost in a project of 1,000 POUs (issue 18): the
// background compile (on its worker thread), the copy of the project the UI thread makes to start
// it, and the longest stall of the UI thread while someone types in an open body with pauses that
// let the compiles run (measured as the largest gap between ticks of a 2 ms timer, less the 2 ms).
#include "app/buildcontroller.h"
#include "app/documentarea.h"
#include "app/livediagnostics.h"
#include "app/mainwindow.h"
#include "editors/text/codeeditor.h"
#include "interpreter/frontend/iecreader.h"
#include "model/projectmodel.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QKeyEvent>
#include <QSettings>
#include <QTemporaryDir>
#include <QTextStream>
#include <QTimer>

#include <algorithm>

using namespace iec;

namespace {

// 1,000 POUs: 600 function blocks and 399 functions with ten lines of ST each, and a program that
// calls some of them, run by one task.
QString generatedSource(int pouCount)
{
    QString source;
    const int blocks = pouCount * 6 / 10;
    for (int i = 0; i < blocks; ++i) {
        source += QStringLiteral(
            "FUNCTION_BLOCK Block%1\nVAR_INPUT\n  In : INT;\n  Enable : BOOL;\nEND_VAR\nVAR_OUTPUT\n  Out : INT;\nEND_VAR\n"
            "VAR\n  Sum : DINT;\n  Count : INT;\n  Edge : R_TRIG;\nEND_VAR\n"
            "Edge(CLK := Enable);\nIF Edge.Q THEN\n  Count := Count + 1;\nEND_IF;\nSum := Sum + In;\n"
            "IF Count > 10 THEN\n  Count := 0;\n  Sum := 0;\nEND_IF;\nOut := In * 2 + Count;\nEND_FUNCTION_BLOCK\n")
                      .arg(i);
    }
    for (int i = blocks; i < pouCount - 1; ++i) {
        source += QStringLiteral("FUNCTION Scale%1 : REAL\nVAR_INPUT\n  Raw : INT;\n  Gain : REAL;\nEND_VAR\n"
                                 "VAR\n  Value : REAL;\nEND_VAR\nValue := INT_TO_REAL(Raw) * Gain;\n"
                                 "IF Value > 100.0 THEN\n  Value := 100.0;\nELSIF Value < 0.0 THEN\n  Value := 0.0;\nEND_IF;\n"
                                 "Scale%1 := Value;\nEND_FUNCTION\n")
                      .arg(i);
    }
    source += QStringLiteral("PROGRAM Main\nVAR\n  Count : INT;\n  B0 : Block0;\n  B1 : Block1;\n  Level : REAL;\nEND_VAR\n"
                             "Count := Count + 1;\nB0(In := Count, Enable := TRUE);\nB1(In := B0.Out);\n"
                             "Level := Scale%1(Count, 0.5);\nEND_PROGRAM\n"
                             "CONFIGURATION Config\n  RESOURCE Resource ON PLC\n"
                             "    TASK MainTask(INTERVAL := T#10ms, PRIORITY := 1);\n    PROGRAM Main WITH MainTask : Main;\n"
                             "  END_RESOURCE\nEND_CONFIGURATION\n")
                  .arg(blocks);
    return source;
}

void typeKey(QWidget *target, QChar character)
{
    const int key = character == QLatin1Char('\n') ? int(Qt::Key_Return) : int(character.toUpper().unicode());
    const QString text = character == QLatin1Char('\n') ? QStringLiteral("\r") : QString(character);
    QKeyEvent press(QEvent::KeyPress, key, Qt::NoModifier, text);
    QKeyEvent release(QEvent::KeyRelease, key, Qt::NoModifier, text);
    QCoreApplication::sendEvent(target, &press);
    QCoreApplication::sendEvent(target, &release);
}

} // namespace

int main(int argc, char *argv[])
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QTemporaryDir settingsHome;
    qputenv("XDG_CONFIG_HOME", settingsHome.path().toLocal8Bit());
    QApplication application(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("IEC Studio Bench"));
    QSettings().setValue(QStringLiteral("ui/language"), QStringLiteral("en"));
    QTextStream out(stdout);

    const int pouCount = 1000;
    app::MainWindow window;
    window.resize(1200, 800);
    window.show();
    model::ProjectModel &projectModel = window.projectModel();
    projectModel.reset(interp::frontend::readIecText(generatedSource(pouCount), QStringLiteral("Bench")).project);
    app::LiveDiagnostics &live = window.liveDiagnostics();

    // The compile alone, three times, after the first (warm caches).
    std::vector<qint64> compiles;
    std::vector<qint64> snapshots;
    int errors = -1;
    QObject::connect(&live, &app::LiveDiagnostics::published, [&](quint64, int errorCount, int) {
        compiles.push_back(live.lastCompileMs());
        snapshots.push_back(live.lastSnapshotMs());
        errors = errorCount;
    });
    for (int round = 0; round < 4; ++round) {
        const size_t before = compiles.size();
        live.compileNow();
        while (compiles.size() == before)
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    }

    // Typing: 6 words of 8 characters, a pause of 700 ms after each (the compile runs), while a
    // 2 ms timer measures how long the UI thread is away.
    const model::Pou *main = projectModel.project().findPou(QStringLiteral("Main"));
    window.documents().openBody({main->id, model::BodyRef::Part::Pou, {}});
    editors::CodeEditor *editor = window.documents().textEditorFor({main->id, model::BodyRef::Part::Pou, {}});
    editor->setFocus();
    editor->moveCursor(QTextCursor::End);
    const QString typed = QStringLiteral("\nCount := Count + 1;\nLevel := Level * 2.0;\nCount := Count - 1;\n");
    QElapsedTimer clock;
    clock.start();
    qint64 lastTick = 0;
    qint64 longestGap = 0;
    qint64 longestKey = 0;
    QTimer ticker;
    ticker.setTimerType(Qt::PreciseTimer);
    QObject::connect(&ticker, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        if (lastTick > 0)
            longestGap = std::max(longestGap, now - lastTick);
        lastTick = now;
    });
    ticker.start(2);
    const size_t compilesBefore = compiles.size();
    int next = 0;
    QTimer typist;
    typist.setTimerType(Qt::PreciseTimer);
    QObject::connect(&typist, &QTimer::timeout, [&] {
        if (next >= typed.size()) {
            typist.stop();
            return;
        }
        QElapsedTimer key;
        key.start();
        typeKey(editor, typed[next]);
        longestKey = std::max(longestKey, key.nsecsElapsed());
        // A pause after each line lets the edit reach the model and the compile run.
        typist.setInterval(typed[next] == QLatin1Char('\n') ? 900 : 40);
        ++next;
    });
    typist.start(40);
    while (typist.isActive() || live.isCompiling() || clock.elapsed() < 1000)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    // The last result: the typed text compiled.
    const qint64 deadline = clock.elapsed() + 5000;
    while (compiles.size() == compilesBefore && clock.elapsed() < deadline)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    ticker.stop();

    std::vector<qint64> warm(compiles.begin() + 1, compiles.begin() + 4);
    std::sort(warm.begin(), warm.end());
    out << "diagnostics while typing, " << pouCount << " POUs (" << projectModel.project().types.pous.size()
        << " in the model), errors in the last result: " << errors << "\n"
        << "  background compile (worker thread), median of 3: " << warm[1] << " ms\n"
        << "  project copy on the UI thread to start it:        " << *std::max_element(snapshots.begin(), snapshots.end())
        << " ms (largest)\n"
        << "  compiles while typing:                             " << compiles.size() - compilesBefore << "\n"
        << "  longest key press (highlight, edit):               " << double(longestKey) / 1e6 << " ms\n"
        << "  longest UI stall while typing (2 ms ticks):        " << double(longestGap) / 1e6 - 2.0 << " ms\n";
    return 0;
}
