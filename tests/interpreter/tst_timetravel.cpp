// Going back in time and the trace recorder, in the runtime: the scan history gives back the
// exact state after any kept scan, resuming from it makes a new branch that runs like a fresh
// run with the same inputs, and the recorder keeps the samples around a trigger.
#include "interpreter/compiler/compiler.h"
#include "interpreter/runtime/runtime.h"
#include "interpreter/runtime/scanhistory.h"
#include "interpreter/runtime/traceformats.h"
#include "interpreter/runtime/tracerecorder.h"

#include <QTest>

using namespace iec;
using namespace iec::interp;

namespace {

std::shared_ptr<const Module> build(const QString &source)
{
    Diagnostics diagnostics;
    auto module = compileText(source, diagnostics);
    for (const Diagnostic &d : diagnostics.all())
        qWarning("%s", qPrintable(d.toString()));
    return module;
}

// A counter, a timer and a tank level that follow the input `fill`; a block of memory that
// never changes, so the history has something to leave out.
const char *const kPlant = "PROGRAM Main\n"
                           "VAR fill : BOOL; n : DINT; level : REAL; t : TON; done : BOOL; edge : BOOL;\n"
                           "    big : ARRAY[1..2000] OF INT; END_VAR\n"
                           "n := n + 1;\n"
                           "IF fill THEN level := level + 1.5; ELSIF level > 0.0 THEN level := level - 0.5; END_IF;\n"
                           "t(IN := fill, PT := T#200ms);\n"
                           "done := t.Q;\n"
                           "edge := (n MOD 10) >= 5;\n"
                           "END_PROGRAM\n";

// The input of cycle `cycle` in the runs below.
bool fillAt(int cycle)
{
    return (cycle / 37) % 2 == 1;
}

void runTo(Runtime &runtime, int lastCycle, std::vector<RuntimeState> *states = nullptr,
           ScanHistory *history = nullptr)
{
    while (runtime.cycle() < lastCycle) {
        const int next = runtime.cycle() + 1;
        QVERIFY(!runtime.write(QStringLiteral("Main.fill"), fillAt(next) ? QStringLiteral("TRUE") : QStringLiteral("FALSE")));
        QVERIFY(runtime.runCycle());
        if (states)
            states->push_back(runtime.state());
        if (history)
            history->record(runtime.state());
    }
}

bool sameState(const RuntimeState &a, const RuntimeState &b)
{
    return a.memory == b.memory && a.images[0] == b.images[0] && a.images[1] == b.images[1]
        && a.images[2] == b.images[2] && a.timeNs == b.timeNs && a.cycle == b.cycle && a.nextDue == b.nextDue
        && a.singleBefore == b.singleBefore;
}

} // namespace

class TestTimeTravel : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void historyGivesBackEveryKeptScan_data();
    void historyGivesBackEveryKeptScan();
    void historyDropsTheOldestScans();
    void historyStaysWithinItsByteLimit();
    void unchangedMemoryCostsLittle();
    void resumingFromAnEarlierScanMakesANewBranch();
    void recorderKeepsSamplesAroundTheTrigger_data();
    void recorderKeepsSamplesAroundTheTrigger();
    void recorderSamplesEveryNthCycleWhenTheConditionHolds();
    void recorderReportsWhatItCannotTrace();
    void recorderTruncatesWithTheHistory();
    void csvAndVcdOfRecordedRows();
};

void TestTimeTravel::historyGivesBackEveryKeptScan_data()
{
    QTest::addColumn<int>("cycle");
    for (const int cycle : {1, 2, 62, 63, 64, 65, 123, 127, 128, 129, 499, 500})
        QTest::addRow("scan %d", cycle) << cycle;
}

void TestTimeTravel::historyGivesBackEveryKeptScan()
{
    QFETCH(int, cycle);
    auto module = build(QString::fromLatin1(kPlant));
    QVERIFY(module);
    Runtime runtime(module);
    std::vector<RuntimeState> states;
    ScanHistory history;
    runTo(runtime, 500, &states, &history);
    QCOMPARE(history.firstCycle(), 1);
    QCOMPARE(history.lastCycle(), 500);
    const std::optional<RuntimeState> back = history.stateAt(cycle);
    QVERIFY(back);
    QVERIFY(sameState(*back, states[size_t(cycle - 1)]));
    QVERIFY(!history.stateAt(0));
    QVERIFY(!history.stateAt(501));
}

void TestTimeTravel::historyDropsTheOldestScans()
{
    auto module = build(QString::fromLatin1(kPlant));
    QVERIFY(module);
    Runtime runtime(module);
    std::vector<RuntimeState> states;
    ScanHistory history(100);
    runTo(runtime, 500, &states, &history);
    QCOMPARE(history.size(), 100);
    QCOMPARE(history.firstCycle(), 401);
    QVERIFY(!history.contains(400));
    for (const int cycle : {401, 402, 447, 448, 449, 500})
        QVERIFY2(sameState(*history.stateAt(cycle), states[size_t(cycle - 1)]), qPrintable(QString::number(cycle)));
    history.setLimits(10, ScanHistory::kDefaultBytes);
    QCOMPARE(history.firstCycle(), 491);
    QVERIFY(sameState(*history.stateAt(491), states[490]));
}

void TestTimeTravel::historyStaysWithinItsByteLimit()
{
    auto module = build(QString::fromLatin1(kPlant));
    QVERIFY(module);
    Runtime runtime(module);
    const std::size_t limit = 64 * 1024;
    ScanHistory history(1000, limit);
    runTo(runtime, 300, nullptr, &history);
    QVERIFY2(history.bytesUsed() <= limit + runtime.vm().memory().size() * 2,
             qPrintable(QString::number(history.bytesUsed())));
    QVERIFY(history.size() > 1);
    QCOMPARE(history.lastCycle(), 300);
    QVERIFY(history.stateAt(history.firstCycle()));
}

void TestTimeTravel::unchangedMemoryCostsLittle()
{
    auto module = build(QString::fromLatin1(kPlant));
    QVERIFY(module);
    Runtime runtime(module);
    ScanHistory history;
    runTo(runtime, 1000, nullptr, &history);
    const std::size_t full = runtime.vm().memory().size() * 1000;
    // 16 full copies (one every 64 scans) and small change lists: under a tenth of 1,000 copies.
    QVERIFY2(history.bytesUsed() * 10 < full,
             qPrintable(QStringLiteral("%1 of %2").arg(history.bytesUsed()).arg(full)));
}

void TestTimeTravel::resumingFromAnEarlierScanMakesANewBranch()
{
    auto module = build(QString::fromLatin1(kPlant));
    QVERIFY(module);
    Runtime runtime(module);
    ScanHistory history;
    runTo(runtime, 500, nullptr, &history);

    // Back to scan 123, and from there the tank fills for 20 cycles whatever fillAt says.
    runtime.restore(*history.stateAt(123));
    QCOMPARE(runtime.cycle(), 123);
    QCOMPARE(*runtime.read(QStringLiteral("Main.n")), QStringLiteral("123"));
    Runtime fresh(module);
    runTo(fresh, 123);
    QVERIFY(sameState(runtime.state(), fresh.state()));
    for (int i = 0; i < 20; ++i) {
        for (Runtime *r : {&runtime, &fresh}) {
            QVERIFY(!r->write(QStringLiteral("Main.fill"), QStringLiteral("TRUE")));
            QVERIFY(r->runCycle());
        }
        history.record(runtime.state());
        QVERIFY(sameState(runtime.state(), fresh.state()));
    }
    QCOMPARE(history.lastCycle(), 143);
    QCOMPARE(history.size(), 143);
    QVERIFY(sameState(*history.stateAt(143), fresh.state()));
    // The scans before the branch are those of the first run.
    Runtime upTo100(module);
    runTo(upTo100, 100);
    QVERIFY(sameState(*history.stateAt(100), upTo100.state()));
    QCOMPARE(*runtime.read(QStringLiteral("Main.done")), QStringLiteral("TRUE")); // 200 ms of filling
}

void TestTimeTravel::recorderKeepsSamplesAroundTheTrigger_data()
{
    QTest::addColumn<int>("trigger");
    QTest::addColumn<double>("level");
    QTest::addColumn<int>("triggerCycle");
    // edge is TRUE in cycles 5-9, 15-19, ...: it rises in cycle 5, falls in cycle 10.
    QTest::newRow("rising edge") << int(TraceSettings::Trigger::Rising) << 0.5 << 5;
    QTest::newRow("falling edge") << int(TraceSettings::Trigger::Falling) << 0.5 << 10;
    QTest::newRow("level") << int(TraceSettings::Trigger::Level) << 0.5 << 5;
}

void TestTimeTravel::recorderKeepsSamplesAroundTheTrigger()
{
    QFETCH(int, trigger);
    QFETCH(double, level);
    QFETCH(int, triggerCycle);
    auto module = build(QString::fromLatin1(kPlant));
    QVERIFY(module);
    Runtime runtime(module);
    TraceRecorder recorder;
    TraceSettings settings;
    settings.variables = {QStringLiteral("Main.n"), QStringLiteral("Main.edge")};
    settings.capacity = 8;
    settings.trigger = TraceSettings::Trigger(trigger);
    settings.triggerVariable = QStringLiteral("Main.edge");
    settings.triggerLevel = level;
    settings.samplesAfterTrigger = 3;
    QCOMPARE(recorder.configure(settings, runtime), QStringList());
    recorder.sample(runtime);
    QCOMPARE(recorder.status(), TraceRecorder::Status::WaitingForTrigger);
    for (int i = 0; i < 40; ++i) {
        QVERIFY(runtime.runCycle());
        recorder.sample(runtime);
    }
    QCOMPARE(recorder.status(), TraceRecorder::Status::Done);
    QCOMPARE(recorder.triggerCycle(), std::optional<int>(triggerCycle));
    // Eight samples: four before the trigger, the trigger, three after.
    QCOMPARE(int(recorder.rows().size()), 8);
    QCOMPARE(recorder.rows().front().cycle, triggerCycle - 4);
    QCOMPARE(recorder.rows().back().cycle, triggerCycle + 3);
    for (const TraceRow &row : recorder.rows()) {
        QCOMPARE(rowLiteral(row, 0, recorder.variables()[0].ref), QString::number(row.cycle));
        const bool high = row.cycle % 10 >= 5;
        QCOMPARE(rowLiteral(row, 1, recorder.variables()[1].ref), high ? QStringLiteral("TRUE") : QStringLiteral("FALSE"));
        QCOMPARE(row.timeNs, std::int64_t(row.cycle) * 10'000'000);
    }
}

void TestTimeTravel::recorderSamplesEveryNthCycleWhenTheConditionHolds()
{
    auto module = build(QString::fromLatin1(kPlant));
    QVERIFY(module);
    Runtime runtime(module);
    TraceRecorder recorder;
    TraceSettings settings;
    settings.variables = {QStringLiteral("Main.n")};
    settings.everyCycles = 3;
    settings.recordCondition = QStringLiteral("Main.n < 20 OR Main.n > 40");
    QCOMPARE(recorder.configure(settings, runtime), QStringList());
    for (int i = 0; i < 50; ++i) {
        QVERIFY(runtime.runCycle());
        recorder.sample(runtime);
        if (i == 44)
            recorder.setPaused(true);
    }
    QStringList cycles;
    for (const TraceRow &row : recorder.rows())
        cycles << rowLiteral(row, 0, recorder.variables()[0].ref);
    QCOMPARE(cycles.join(QLatin1Char(' ')), QStringLiteral("3 6 9 12 15 18 42 45"));
    QCOMPARE(recorder.status(), TraceRecorder::Status::Paused);
}

void TestTimeTravel::recorderReportsWhatItCannotTrace()
{
    auto module = build(QString::fromLatin1(kPlant));
    QVERIFY(module);
    Runtime runtime(module);
    TraceRecorder recorder;
    TraceSettings settings;
    settings.variables = {QStringLiteral("Main.nope"), QStringLiteral("Main.big"), QStringLiteral("Main.level"),
                          QStringLiteral("Main.big[3]")};
    const QStringList problems = recorder.configure(settings, runtime);
    QCOMPARE(problems.size(), 2);
    QVERIFY(problems[0].contains(QStringLiteral("Main.nope")));
    QVERIFY(problems[1].contains(QStringLiteral("Main.big")));
    QCOMPARE(int(recorder.variables().size()), 2);
    QVERIFY(runtime.runCycle());
    recorder.sample(runtime);
    QCOMPARE(rowNumber(recorder.rows().back(), 0, recorder.variables()[0].ref), 0.0);
}

void TestTimeTravel::recorderTruncatesWithTheHistory()
{
    auto module = build(QString::fromLatin1(kPlant));
    QVERIFY(module);
    Runtime runtime(module);
    TraceRecorder recorder;
    TraceSettings settings;
    settings.variables = {QStringLiteral("Main.n")};
    recorder.configure(settings, runtime);
    const quint64 generation = recorder.generation();
    for (int i = 0; i < 30; ++i) {
        QVERIFY(runtime.runCycle());
        recorder.sample(runtime);
    }
    QCOMPARE(recorder.appended(), quint64(30));
    recorder.truncateAfter(12);
    QCOMPARE(recorder.rows().back().cycle, 12);
    QCOMPARE(recorder.generation(), generation + 1);

    // Cut back after the trigger fired and the recording stopped: it records the rest again.
    TraceSettings triggered = settings;
    triggered.trigger = TraceSettings::Trigger::Rising;
    triggered.triggerVariable = QStringLiteral("Main.edge");
    triggered.samplesAfterTrigger = 6;
    recorder.configure(triggered, runtime); // at cycle 30; edge rises in cycles 35, 45, ...
    for (int i = 0; i < 20; ++i) {
        QVERIFY(runtime.runCycle());
        recorder.sample(runtime);
    }
    QCOMPARE(recorder.triggerCycle(), std::optional<int>(35));
    QCOMPARE(recorder.status(), TraceRecorder::Status::Done);
    QCOMPARE(recorder.rows().back().cycle, 41);
    recorder.truncateAfter(38);
    QCOMPARE(recorder.status(), TraceRecorder::Status::Triggered);
    for (int i = 0; i < 5; ++i) {
        QVERIFY(runtime.runCycle());
        recorder.sample(runtime);
    }
    QCOMPARE(recorder.status(), TraceRecorder::Status::Done);
    // Cycles 31-35 up to the trigger, 36-38 kept after it, and three more (51-53).
    QCOMPARE(int(recorder.rows().size()), 5 + 3 + 3);
    QCOMPARE(recorder.rows().back().cycle, 53);
}

// The writers give, for recorded rows, the files `iecstudio-cli run --trace` writes (tst_cli
// holds the CLI's side): a header, one CSV row per cycle, VCD values only when they change.
void TestTimeTravel::csvAndVcdOfRecordedRows()
{
    auto module = build(QStringLiteral("PROGRAM Main\nVAR n : INT; b : BOOL; r : REAL; t : TIME; END_VAR\n"
                                       "n := n + 1; b := NOT b; r := r + 0.5; t := t + T#1500ms;\nEND_PROGRAM\n"));
    QVERIFY(module);
    Runtime runtime(module);
    std::vector<TraceVariable> variables;
    for (const char *name : {"Main.n", "Main.b", "Main.r", "Main.t"})
        variables.push_back({QString::fromLatin1(name), *runtime.find(QString::fromLatin1(name))});
    std::vector<TraceRow> rows{captureRow(runtime, variables)};
    for (int i = 0; i < 2; ++i) {
        QVERIFY(runtime.runCycle());
        rows.push_back(captureRow(runtime, variables));
    }
    QString csv;
    QString vcd;
    {
        QTextStream csvOut(&csv);
        QTextStream vcdOut(&vcd);
        auto csvWriter = makeCsvWriter(csvOut, variables);
        auto vcdWriter = makeVcdWriter(vcdOut, variables, runtime.cycleNs(), QStringLiteral("test"));
        csvWriter->begin(rows[0]);
        vcdWriter->begin(rows[0]);
        for (size_t i = 1; i < rows.size(); ++i) {
            csvWriter->write(rows[i]);
            vcdWriter->write(rows[i]);
        }
    }
    QCOMPARE(csv, QStringLiteral("cycle,time_ms,Main.n,Main.b,Main.r,Main.t\n"
                                 "1,10,1,TRUE,0.5,T#1s500ms\n"
                                 "2,20,2,FALSE,1.0,T#3s\n"));
    QCOMPARE(vcd, QStringLiteral("$version test $end\n$timescale 1 us $end\n$scope module iecstudio $end\n"
                                 "$var wire 16 ! Main.n $end\n$var wire 1 \" Main.b $end\n"
                                 "$var real 64 # Main.r $end\n$var wire 64 $ Main.t $end\n"
                                 "$upscope $end\n$enddefinitions $end\n#0\n$dumpvars\n"
                                 "b0 !\n0\"\nr0 #\nb0 $\n$end\n"
                                 "#10000\nb1 !\n1\"\nr0.5 #\nb1011001011010000010111100000000 $\n"
                                 "#20000\nb10 !\n0\"\nr1 #\nb10110010110100000101111000000000 $\n"));
}

QTEST_GUILESS_MAIN(TestTimeTravel)
#include "tst_timetravel.moc"
