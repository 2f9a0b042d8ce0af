// Going back in time and the Trace pane in the main window, with the mixing-tank chart: 500
// scans, back to scan 123 with the history slider (the chart, the watch pane and the status
// bar show that scan, marked as history), Resume from Here with another input makes a new
// branch; a trace with an edge trigger keeps the samples around it, and its CSV and VCD
// exports hold the values `iecstudio-cli run --trace` writes for the same run.
#include "app/documentarea.h"
#include "app/mainwindow.h"
#include "app/online/historybar.h"
#include "app/online/onlinecontroller.h"
#include "app/online/tracepane.h"
#include "app/online/tracesettingsdialog.h"
#include "app/online/watchpane.h"
#include "editors/common/diagramitem.h"
#include "editors/common/diagramscene.h"
#include "editors/sfc/sfceditor.h"
#include "editors/sfc/sfcitems.h"
#include "model/plcopen/reader.h"
#include "model/projectmodel.h"

#include <QAction>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QProcess>
#include <QPushButton>
#include <QSlider>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace iec;
using namespace iec::app;

namespace {

const QString kExample = QStringLiteral(IEC_SOURCE_DIR "/resources/examples/mixing_tank.xml");

// The inputs of the run below, by cycle, as `--set NAME=VALUE@CYCLE` (a write before that cycle).
const QStringList kInputs{
    QStringLiteral("Tank.MixTime=T#1s@1"), QStringLiteral("Tank.SB1=TRUE@2"), QStringLiteral("Tank.SB1=FALSE@5"),
    QStringLiteral("Tank.L3=TRUE@30"),     QStringLiteral("Tank.L2=TRUE@60"), QStringLiteral("Tank.L1=TRUE@90"),
    QStringLiteral("Tank.L1=FALSE@250"),   QStringLiteral("Tank.L2=FALSE@270"), QStringLiteral("Tank.L3=FALSE@300")};

const QStringList kWatched{QStringLiteral("Tank.Y1"), QStringLiteral("Tank.Y2"), QStringLiteral("Tank.M"),
                           QStringLiteral("Tank.Y3"), QStringLiteral("Tank.StopRequested")};

QStringList activeSteps(const editors::sfc::SfcEditor &editor)
{
    QStringList names;
    for (editors::DiagramItem *item : editor.scene()->diagramItems()) {
        const auto *sfcItem = static_cast<editors::sfc::SfcItem *>(item);
        if (const auto *step = std::get_if<model::Step>(&sfcItem->element()); step && item->isActive())
            names.push_back(step->name);
    }
    return names;
}

QStringList watchedValues(WatchPane &watch)
{
    QStringList values;
    for (int row = 0; row < watch.model().rowCount(); ++row)
        values << watch.model().value(row);
    return values;
}

// Writes the inputs due before `cycle`, then runs it, as a user does with the watch pane.
void runCycle(OnlineController &online, int cycle)
{
    for (const QString &input : kInputs) {
        const int at = input.section(QLatin1Char('@'), 1).toInt();
        if (at != cycle)
            continue;
        const QString assignment = input.section(QLatin1Char('@'), 0, 0);
        online.write(assignment.section(QLatin1Char('='), 0, 0), assignment.section(QLatin1Char('='), 1));
    }
    online.singleCycle();
}

struct Window {
    MainWindow window;
    editors::sfc::SfcEditor *chart = nullptr;
};

std::unique_ptr<Window> openTank()
{
    auto opened = std::make_unique<Window>();
    MainWindow &window = opened->window;
    window.online().setThreaded(false);
    window.projectModel().reset(model::plcopen::readProjectFile(kExample).project);
    const model::Pou *main = window.projectModel().project().findPou(QStringLiteral("Main"));
    QWidget *document = window.documents().openBody({main->id, model::BodyRef::Part::Pou, {}});
    opened->chart = document->findChild<editors::sfc::SfcEditor *>();
    for (const QString &name : kWatched)
        window.watchPane().model().addName(name);
    return opened;
}

// A VCD's values over time: for each #time, every identifier's value from then on.
std::map<qint64, std::map<QString, QString>> vcdStates(const QString &text)
{
    std::map<qint64, std::map<QString, QString>> states;
    std::map<QString, QString> current;
    qint64 time = -1;
    bool inDefinitions = true;
    for (const QString &raw : text.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        const QString line = raw.trimmed();
        if (inDefinitions) {
            inDefinitions = !line.startsWith(QLatin1String("$enddefinitions"));
            continue;
        }
        if (line.startsWith(QLatin1Char('#'))) {
            if (time >= 0)
                states[time] = current;
            time = line.mid(1).toLongLong();
        } else if (line.startsWith(QLatin1Char('b')) || line.startsWith(QLatin1Char('r'))) {
            current[line.section(QLatin1Char(' '), 1)] = line.section(QLatin1Char(' '), 0, 0);
        } else if (!line.startsWith(QLatin1Char('$'))) {
            current[line.mid(1)] = line.left(1);
        }
    }
    if (time >= 0)
        states[time] = current;
    return states;
}

} // namespace

class TestTimeTravelWindow : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void backToScan123AndResumeWithAnotherInput();
    void traceWithAnEdgeTrigger();
    void traceSettingsAreKeptWithTheProject();
    void settingsDialog();
};

void TestTimeTravelWindow::backToScan123AndResumeWithAnotherInput()
{
    auto opened = openTank();
    MainWindow &window = opened->window;
    editors::sfc::SfcEditor *chart = opened->chart;
    QVERIFY(chart);
    OnlineController &online = window.online();
    QVERIFY(online.login());
    HistoryBar &bar = window.historyBar();
    QVERIFY(!bar.isHidden());

    std::map<int, std::pair<QStringList, QStringList>> seen; // scan -> active steps, watched values
    for (int cycle = 1; cycle <= 500; ++cycle) {
        runCycle(online, cycle);
        seen[cycle] = {activeSteps(*chart), watchedValues(window.watchPane())};
    }
    QCOMPARE(online.latestSnapshot()->cycle, 500);
    QCOMPARE(online.latestSnapshot()->history.firstCycle, 0);
    QCOMPARE(online.latestSnapshot()->history.lastCycle, 500);
    QCOMPARE(seen[123].first, QStringList{QStringLiteral("Mixing")});
    QCOMPARE(seen[500].first, QStringList{QStringLiteral("FillA")}); // drained, the next batch begins
    QVERIFY(bar.infoLabel()->text().startsWith(QStringLiteral("501 of at most 1000 scans kept, ")));

    // The slider back to scan 123, as a user drags it.
    QVERIFY(!bar.presentAction()->isEnabled());
    bar.slider()->setValue(123);
    const auto past = online.latestSnapshot();
    QCOMPARE(past->historyCycle, std::optional<int>(123));
    QCOMPARE(past->cycle, 123);
    QCOMPARE(past->presentCycle, 500);
    QCOMPARE(activeSteps(*chart), seen[123].first);
    QCOMPARE(watchedValues(window.watchPane()), seen[123].second);
    QVERIFY(!bar.banner()->isHidden());
    QCOMPARE(bar.banner()->text(), QStringLiteral("History: after scan 123 (the program is at 500)"));
    QVERIFY(online.statusLabel()->text().startsWith(QStringLiteral("ONLINE HISTORY | scan 123 of 500")));
    QCOMPARE(window.watchPane().model().headerData(WatchModel::ValueColumn, Qt::Horizontal, Qt::DisplayRole).toString(),
             QStringLiteral("Value after scan 123 (history)"));
    QVERIFY(bar.presentAction()->isEnabled());
    // Another scan, then the present again: nothing ran meanwhile.
    bar.slider()->setValue(400);
    QCOMPARE(activeSteps(*chart), seen[400].first);
    QCOMPARE(watchedValues(window.watchPane()), seen[400].second);
    bar.presentAction()->trigger();
    QVERIFY(!online.latestSnapshot()->historyCycle);
    QCOMPARE(watchedValues(window.watchPane()), seen[500].second);
    QVERIFY(bar.banner()->isHidden());

    // Resume from scan 123, with the stop button pressed this time.
    bar.slider()->setValue(123);
    bar.resumeAction()->trigger();
    QCOMPARE(online.latestSnapshot()->cycle, 123);
    QVERIFY(!online.latestSnapshot()->historyCycle);
    QCOMPARE(online.latestSnapshot()->history.lastCycle, 123);
    QCOMPARE(watchedValues(window.watchPane()), seen[123].second);
    online.write(QStringLiteral("Tank.SB2"), QStringLiteral("TRUE"));
    for (int cycle = 124; cycle <= 133; ++cycle)
        runCycle(online, cycle);
    QCOMPARE(online.latestSnapshot()->history.lastCycle, 133);
    QCOMPARE(*online.latestSnapshot()->values.find(QStringLiteral("Tank.StopRequested")), QStringLiteral("TRUE"));
    QCOMPARE(seen[133].second.at(4), QStringLiteral("FALSE")); // the first branch never stopped
    // The new branch is what history now holds.
    bar.slider()->setValue(130);
    QCOMPARE(*online.latestSnapshot()->values.find(QStringLiteral("Tank.StopRequested")), QStringLiteral("TRUE"));
    QCOMPARE(bar.slider()->maximum(), 133);
    online.logout();
    QVERIFY(bar.isHidden());
}

void TestTimeTravelWindow::traceWithAnEdgeTrigger()
{
    auto opened = openTank();
    MainWindow &window = opened->window;
    // Shown, as a user sees it: the PNG and PDF exports are pictures of the lanes on screen.
    window.resize(1400, 900);
    window.show();
    window.findChild<QDockWidget *>(QStringLiteral("traceDock"))->raise();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    OnlineController &online = window.online();
    TracePane &trace = window.tracePane();
    model::SavedTrace settings;
    settings.variables = {QStringLiteral("Tank.Y1"), QStringLiteral("Tank.Y2"), QStringLiteral("Tank.M"),
                          QStringLiteral("Tank.Mixing.T")};
    settings.capacity = 50;
    settings.trigger = 1; // rising edge
    settings.triggerVariable = QStringLiteral("Tank.M");
    settings.samplesAfterTrigger = 20;
    trace.setSettings(settings);
    QVERIFY(online.login());
    QCOMPARE(trace.statusText(), QStringLiteral("Waiting for the trigger on Tank.M: 1 sample(s) kept before it."));
    QCOMPARE(trace.chart()->laneCount(), 4);
    for (int cycle = 1; cycle <= 300; ++cycle)
        runCycle(online, cycle);

    // M rises when Mixing starts: L1 is written before cycle 90, the transition fires in it.
    const TraceData &data = trace.data();
    QCOMPARE(data.triggerCycle, std::optional<int>(91));
    QCOMPARE(int(data.rows.size()), 50);
    QCOMPARE(data.rows.front().cycle, 91 - 29);
    QCOMPARE(data.rows.back().cycle, 91 + 20);
    const auto literal = [&](int cycle, int variable) {
        const interp::TraceRow &row = data.rows[size_t(cycle - data.rows.front().cycle)];
        return interp::rowLiteral(row, size_t(variable), data.variables[size_t(variable)].ref);
    };
    QCOMPARE(literal(90, 2), QStringLiteral("FALSE"));
    QCOMPARE(literal(91, 2), QStringLiteral("TRUE"));
    QCOMPARE(literal(90, 1), QStringLiteral("TRUE")); // FillB until then
    QCOMPARE(literal(91, 1), QStringLiteral("FALSE"));
    QCOMPARE(literal(111, 3), QStringLiteral("T#200ms"));
    QCOMPARE(trace.statusText(),
             QStringLiteral("Triggered in cycle 91: done, 50 sample(s). Restart arms the trigger again."));

    // Cursors on the trigger and 20 cycles later: the readout and its difference.
    trace.chart()->setCursor(0, data.timeMs(29));
    trace.chart()->setCursor(1, data.timeMs(49));
    QCOMPARE(trace.readout()->item(1, 0)->text(), QStringLiteral("91"));
    QCOMPARE(trace.readout()->item(1, 1)->text(), QStringLiteral("111"));
    QCOMPARE(trace.readout()->item(0, 2)->text(), QStringLiteral("200"));
    QCOMPARE(trace.readout()->item(2 + 2, 0)->text(), QStringLiteral("TRUE"));
    QCOMPARE(trace.readout()->item(2 + 3, 2)->text(), QStringLiteral("200"));
    // Hiding a lane (the list's check box) hides it in the chart and the readout.
    trace.laneList()->item(1)->setCheckState(Qt::Unchecked);
    QCOMPARE(trace.chart()->laneCount(), 3);
    QCOMPARE(trace.readout()->rowCount(), 2 + 3);
    QCOMPARE(trace.settings().hidden, QStringList{QStringLiteral("Tank.Y2")});
    // Dragging Mixing.T to the top of the list (a row move) makes it the first lane and row.
    QVERIFY(trace.laneList()->model()->moveRow(QModelIndex(), 3, QModelIndex(), 0));
    QCOMPARE(trace.settings().variables.front(), QStringLiteral("Tank.Mixing.T"));
    QCOMPARE(trace.readout()->verticalHeaderItem(2)->text(), QStringLiteral("Tank.Mixing.T"));
    QCOMPARE(trace.readout()->verticalHeaderItem(3)->text(), QStringLiteral("Tank.Y1"));
    QCOMPARE(trace.chart()->laneCount(), 3);
    QCOMPARE(int(data.rows.size()), 50); // reordering shows differently, it records nothing anew

    // The exports against the CLI's trace of the same run.
    QTemporaryDir dir;
    QString error;
    for (const char *suffix : {"csv", "vcd", "png", "pdf"})
        QVERIFY2(trace.exportTo(dir.filePath(QStringLiteral("pane.") + QLatin1String(suffix)), error), qPrintable(error));
    QVERIFY(QImage(dir.filePath(QStringLiteral("pane.png"))).width() > 400);
    QVERIFY(QFileInfo(dir.filePath(QStringLiteral("pane.pdf"))).size() > 1000);
    QStringList cliArguments{QStringLiteral("run"), kExample, QStringLiteral("--cycles"), QStringLiteral("300"),
                             QStringLiteral("--cycle-time"), QStringLiteral("10ms")};
    for (const QString &input : kInputs)
        cliArguments << QStringLiteral("--set") << input;
    for (const QString &name : settings.variables)
        cliArguments << QStringLiteral("--watch") << name;
    for (const char *suffix : {"csv", "vcd"}) {
        QProcess cli;
        cli.start(QStringLiteral(IECSTUDIO_CLI),
                  cliArguments + QStringList{QStringLiteral("--trace"), dir.filePath(QStringLiteral("cli.") + QLatin1String(suffix))});
        QVERIFY(cli.waitForFinished(120'000));
        QCOMPARE(cli.exitCode(), 0);
    }
    const auto read = [&](const QString &name) {
        QFile file(dir.filePath(name));
        return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
    };
    const QStringList paneCsv = read(QStringLiteral("pane.csv")).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    const QStringList cliCsv = read(QStringLiteral("cli.csv")).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(paneCsv.size(), 1 + 50);
    QCOMPARE(paneCsv.front(), cliCsv.front()); // the header
    for (int i = 1; i < paneCsv.size(); ++i) {
        const int cycle = paneCsv[i].section(QLatin1Char(','), 0, 0).toInt();
        QCOMPARE(paneCsv[i], cliCsv[cycle]);
    }
    const auto paneVcd = vcdStates(read(QStringLiteral("pane.vcd")));
    const auto cliVcd = vcdStates(read(QStringLiteral("cli.vcd")));
    QCOMPARE(int(paneVcd.size()), 50);
    for (const auto &[time, values] : paneVcd) {
        QVERIFY2(cliVcd.count(time), qPrintable(QString::number(time)));
        QCOMPARE(values, cliVcd.at(time));
    }
    online.logout();
    QVERIFY(trace.statusText().startsWith(QStringLiteral("Offline: 50 sample(s) from the last session.")));
}

void TestTimeTravelWindow::traceSettingsAreKeptWithTheProject()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("tank.xml"));
    model::SavedTrace settings;
    settings.variables = {QStringLiteral("Tank.M"), QStringLiteral("Tank.Y1")};
    settings.hidden = {QStringLiteral("Tank.Y1")};
    settings.everyCycles = 2;
    settings.trigger = 2;
    settings.triggerVariable = QStringLiteral("Tank.M");
    settings.triggerLevel = 0.5;
    settings.samplesAfterTrigger = 7;
    settings.recordCondition = QStringLiteral("Tank.L3 AND NOT Tank.Y3");
    settings.historyScans = 250;
    {
        auto opened = openTank();
        opened->window.tracePane().setSettings(settings);
        QString error;
        QVERIFY2(opened->window.saveProject(path, &error), qPrintable(error));
    }
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QString xml = QString::fromUtf8(file.readAll());
    QVERIFY(xml.contains(QStringLiteral("https://iec-studio.org/trace")));
    MainWindow window;
    window.projectModel().reset(model::plcopen::readProjectFile(path).project);
    QCOMPARE(window.tracePane().settings(), settings);
    QCOMPARE(window.tracePane().laneList()->count(), 2);
    QCOMPARE(window.tracePane().laneList()->item(1)->checkState(), Qt::Unchecked);
    // The default configuration leaves no trace in the file.
    model::Project project = window.projectModel().project();
    model::setSavedTrace(project, model::SavedTrace());
    QVERIFY(std::none_of(project.addData.begin(), project.addData.end(), [](const model::AddDataEntry &entry) {
        return entry.name == QLatin1String(model::kTraceAddDataName);
    }));
}

void TestTimeTravelWindow::settingsDialog()
{
    model::SavedTrace start;
    start.variables = {QStringLiteral("Main.A")};
    TraceSettingsDialog dialog(start);
    QVERIFY(!dialog.triggerVariableEdit()->isEnabled());
    dialog.variablesEdit()->setPlainText(QStringLiteral(" Main.A \n\nMain.B\nmain.b\n"));
    dialog.triggerBox()->setCurrentIndex(1);
    QVERIFY(dialog.triggerVariableEdit()->isEnabled());
    QVERIFY(!dialog.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
    QCOMPARE(dialog.problemLabel()->text(), QStringLiteral("Name the variable that triggers the recording."));
    dialog.triggerVariableEdit()->setText(QStringLiteral("Main.B"));
    dialog.conditionEdit()->setText(QStringLiteral("Main.A AND"));
    QVERIFY(!dialog.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
    dialog.conditionEdit()->setText(QStringLiteral("Main.A AND Main.B"));
    QVERIFY(dialog.buttons()->button(QDialogButtonBox::Ok)->isEnabled());
    const model::SavedTrace result = dialog.settings();
    QCOMPARE(result.variables, (QStringList{QStringLiteral("Main.A"), QStringLiteral("Main.B")}));
    QCOMPARE(result.trigger, 1);
    QCOMPARE(result.triggerVariable, QStringLiteral("Main.B"));
    QCOMPARE(result.recordCondition, QStringLiteral("Main.A AND Main.B"));
}

QTEST_MAIN(TestTimeTravelWindow)
#include "tst_timetravelwindow.moc"
