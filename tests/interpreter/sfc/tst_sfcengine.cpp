// The SFC engine (interpreter/sfc): charts lowered to the VM, checked scan by scan with a 10 ms
// cycle. docs/sfc.md states the rules these tables check.
#include "sfctesting.h"

#include "interpreter/compiler/parser.h"
#include "interpreter/sfc/sfcstatus.h"

#include <QTest>

using namespace iec;
using namespace iec::interp;
using namespace iec::interp::sfctesting;

class TestSfcEngine : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void qualifiers_data();
    void qualifiers();
    void setAndReset();
    void timeVariableDuration();
    void twoTimedAssociationsAreAnError();
    void cycleOrder();
    void entryExitActiveCounts();
    void implicitVariables();
    void simplifiedStep();
    void branchPriority_data();
    void branchPriority();
    void parallelJoinWaitsForAllBranches();
    void minAndMaxTimes();
    void enableLimit();
    void flags();
    void tipMode();
    void chartInFunctionBlockHasOneStatePerInstance();
    void chartState();
    void chartStateOfAnAction();
    void chartInAChartInAnAction();
    void ilCondition();
    void ilActionRunsAsCalledAction();
};

namespace {

// Init --go--> S1 --NOT go--> Init; S1 controls action A (counts in n) and Boolean variable Out
// with the same qualifier.
QString qualifierChart(const QString &qualifier)
{
    return QStringLiteral(
        "PROGRAM Main\nVAR go : BOOL; n : INT; Out : BOOL; tDur : TIME := T#30ms; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO S1 := go; END_TRANSITION\n"
        "STEP S1: A(%1); Out(%1); END_STEP\n"
        "TRANSITION FROM S1 TO Init := NOT go; END_TRANSITION\n"
        "ACTION A: n := n + 1; END_ACTION\n"
        "END_PROGRAM\n")
        .arg(qualifier);
}

// go is TRUE before cycles 2..6: S1 is active in cycles 3..7 (20 ms .. 60 ms).
QStringList qualifierTrace(const QString &n, const QString &out)
{
    const QStringList counts = n.split(QLatin1Char(' '));
    const QStringList outs = out.split(QLatin1Char(' '));
    QStringList steps;
    for (int c = 0; c < counts.size(); ++c) {
        QString inputs = c == 1 ? QStringLiteral("go=TRUE") : c == 6 ? QStringLiteral("go=FALSE") : QString();
        steps << QStringLiteral("%1 => n=%2; Out=%3")
                     .arg(inputs, counts[c], outs[c] == QLatin1String("T") ? QStringLiteral("TRUE") : QStringLiteral("FALSE"));
    }
    return steps;
}

} // namespace

void TestSfcEngine::qualifiers_data()
{
    QTest::addColumn<QString>("qualifier");
    QTest::addColumn<QString>("counts"); // n after cycles 1..9
    QTest::addColumn<QString>("outs");   // Out after cycles 1..9
    // N: while active, plus one final run (CoDeSys) in the cycle after.
    QTest::newRow("N") << "N" << "0 0 1 2 3 4 5 6 6" << "F F T T T T T F F";
    QTest::newRow("none means N") << "" << "0 0 1 2 3 4 5 6 6" << "F F T T T T T F F";
    QTest::newRow("S") << "S" << "0 0 1 2 3 4 5 6 7" << "F F T T T T T T T";
    QTest::newRow("L") << "L, T#30ms" << "0 0 1 2 3 4 4 4 4" << "F F T T T F F F F";
    QTest::newRow("D") << "D, T#30ms" << "0 0 0 0 0 1 2 3 3" << "F F F F F T T F F";
    // P: in its activation cycle and, as the final run, in the next.
    QTest::newRow("P") << "P" << "0 0 1 2 2 2 2 2 2" << "F F T F F F F F F";
    QTest::newRow("SD") << "SD, T#30ms" << "0 0 0 0 0 1 2 3 4" << "F F F F F T T T T";
    QTest::newRow("DS") << "DS, T#30ms" << "0 0 0 0 0 1 2 3 4" << "F F F F F T T T T";
    QTest::newRow("SL") << "SL, T#30ms" << "0 0 1 2 3 4 4 4 4" << "F F T T T F F F F";
    QTest::newRow("P1") << "P1" << "0 0 1 1 1 1 1 1 1" << "F F T F F F F F F";
    QTest::newRow("P0") << "P0" << "0 0 0 0 0 0 0 1 1" << "F F F F F F F T F";
    QTest::newRow("D longer than the step") << "D, T#80ms" << "0 0 0 0 0 0 0 0 0" << "F F F F F F F F F";
    QTest::newRow("DS longer than the step") << "DS, T#80ms" << "0 0 0 0 0 0 0 0 0" << "F F F F F F F F F";
    QTest::newRow("SD longer than the step") << "SD, T#80ms" << "0 0 0 0 0 0 0 0 0" << "F F F F F F F F F";
}

void TestSfcEngine::qualifiers()
{
    QFETCH(QString, qualifier);
    QFETCH(QString, counts);
    QFETCH(QString, outs);
    QCOMPARE(runTrace(qualifierChart(qualifier), qualifierTrace(counts, outs)), QString());
}

void TestSfcEngine::setAndReset()
{
    const QString chart = QStringLiteral(
        "PROGRAM Main\nVAR go : BOOL; stop : BOOL; n : INT; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO S1 := go; END_TRANSITION\n"
        "STEP S1: A(S); END_STEP\n"
        "TRANSITION FROM S1 TO S2 := TRUE; END_TRANSITION\n"
        "STEP S2: END_STEP\n"
        "TRANSITION FROM S2 TO S3 := stop; END_TRANSITION\n"
        "STEP S3: A(R); END_STEP\n"
        "TRANSITION FROM S3 TO Init := TRUE; END_TRANSITION\n"
        "ACTION A: n := n + 1; END_ACTION\n"
        "END_PROGRAM\n");
    QCOMPARE(runTrace(chart,
                 {QStringLiteral("=> n=0"), QStringLiteral("go=TRUE => n=0; S1._x=TRUE"), QStringLiteral("go=FALSE => n=1; S1.x=TRUE"),
                     QStringLiteral("=> n=2; S2.x=TRUE"), QStringLiteral("stop=TRUE => n=3; A.x=TRUE"),
                     // S3 resets A: its last run is the final one.
                     QStringLiteral("stop=FALSE => n=4; S3.x=TRUE; A.x=FALSE; _A.x=TRUE"), QStringLiteral("=> n=4; Init.x=TRUE; _A.x=FALSE"),
                     QStringLiteral("=> n=4")}),
        QString());
}

void TestSfcEngine::timeVariableDuration()
{
    // L with a TIME variable (textual SFC: A(L, tDur)) behaves as with the literal.
    QCOMPARE(runTrace(qualifierChart(QStringLiteral("L, tDur")), qualifierTrace(QStringLiteral("0 0 1 2 3 4 4 4 4"), QStringLiteral("F F T T T F F F F"))),
        QString());
    // The variable is read every cycle: 10 ms instead.
    QStringList trace = qualifierTrace(QStringLiteral("0 0 1 2 2 2 2 2 2"), QStringLiteral("F F T F F F F F F"));
    trace[0] = QStringLiteral("tDur=T#10ms") + trace[0];
    QCOMPARE(runTrace(qualifierChart(QStringLiteral("L, tDur")), trace), QString());
}

void TestSfcEngine::twoTimedAssociationsAreAnError()
{
    const QString chart = QStringLiteral(
        "PROGRAM Main\nVAR go : BOOL; SFCError : BOOL; SFCErrorStep : STRING; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO (S1, S2) := go; END_TRANSITION\n"
        "STEP S1: A(L, T#50ms); END_STEP\n"
        "STEP S2: A(D, T#20ms); END_STEP\n"
        "TRANSITION FROM (S1, S2) TO Init := NOT go; END_TRANSITION\n"
        "ACTION A: ; END_ACTION\n"
        "END_PROGRAM\n");
    QCOMPARE(runTrace(chart,
                 {QStringLiteral("=> SFCError=FALSE"), QStringLiteral("go=TRUE => SFCError=FALSE"),
                     QStringLiteral("=> SFCError=TRUE; SFCErrorStep='S2'; S1.x=TRUE; S2.x=TRUE")}),
        QString());
}

void TestSfcEngine::cycleOrder()
{
    // Each action appends its digit: exit 3 (Init) / 5 (S1), entry 1 (S1) / 6 (Init), active 2,
    // IEC action 4. Seed 001: exit actions, entry actions, active actions, then IEC actions.
    model::Project project = readText(QStringLiteral(
        "PROGRAM Main\nVAR go : BOOL; seq : LINT; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO S1 := go; END_TRANSITION\n"
        "STEP S1: A(N); END_STEP\n"
        "TRANSITION FROM S1 TO Init := NOT go; END_TRANSITION\n"
        "ACTION A: seq := seq * 10 + 4; END_ACTION\n"
        "ACTION En: seq := seq * 10 + 1; END_ACTION\n"
        "ACTION Act: seq := seq * 10 + 2; END_ACTION\n"
        "ACTION InitEx: seq := seq * 10 + 3; END_ACTION\n"
        "ACTION Ex: seq := seq * 10 + 5; END_ACTION\n"
        "ACTION InitEn: seq := seq * 10 + 6; END_ACTION\n"
        "END_PROGRAM\n"));
    editStep(project, QStringLiteral("Main"), QStringLiteral("Init"), [](model::StepOptions &o) {
        o.exitAction = QStringLiteral("InitEx");
        o.entryAction = QStringLiteral("InitEn");
    });
    editStep(project, QStringLiteral("Main"), QStringLiteral("S1"), [](model::StepOptions &o) {
        o.entryAction = QStringLiteral("En");
        o.activeAction = QStringLiteral("Act");
        o.exitAction = QStringLiteral("Ex");
    });
    QCOMPARE(runTrace(project,
                 {QStringLiteral("seq=0 => seq=6"), QStringLiteral("seq=0; go=TRUE => seq=0"), QStringLiteral("=> seq=3124"),
                     QStringLiteral("go=FALSE => seq=312424"), QStringLiteral("=> seq=312424564"),
                     QStringLiteral("=> seq=312424564")}),
        QString());
}

void TestSfcEngine::entryExitActiveCounts()
{
    model::Project project = readText(QStringLiteral(
        "PROGRAM Main\nVAR go : BOOL; ne : INT; nx : INT; na : INT; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO S1 := go; END_TRANSITION\n"
        "STEP S1: END_STEP\n"
        "TRANSITION FROM S1 TO Init := NOT go; END_TRANSITION\n"
        "ACTION En: ne := ne + 1; END_ACTION\n"
        "ACTION Ex: nx := nx + 1; END_ACTION\n"
        "ACTION Act: na := na + 1; END_ACTION\n"
        "END_PROGRAM\n"));
    editStep(project, QStringLiteral("Main"), QStringLiteral("S1"), [](model::StepOptions &o) {
        o.entryAction = QStringLiteral("En");
        o.exitAction = QStringLiteral("Ex");
        o.activeAction = QStringLiteral("Act");
    });
    QCOMPARE(runTrace(project,
                 {QStringLiteral("=> ne=0; nx=0; na=0"), QStringLiteral("go=TRUE => ne=0; na=0"), QStringLiteral("=> ne=1; na=1; nx=0"),
                     QStringLiteral("=> ne=1; na=2"), QStringLiteral("go=FALSE => ne=1; na=3; nx=0"), QStringLiteral("=> ne=1; na=3; nx=1"),
                     QStringLiteral("go=TRUE => ne=1; na=3; nx=1"), QStringLiteral("=> ne=2; na=4; nx=1")}),
        QString());
}

void TestSfcEngine::implicitVariables()
{
    const QString chart = QStringLiteral(
        "PROGRAM Main\nVAR go : BOOL; seen : BOOL; elapsed : TIME; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO S1 := go; END_TRANSITION\n"
        "STEP S1: A(N); END_STEP\n"
        "TRANSITION FROM S1 TO Init := S1.t >= T#20ms; END_TRANSITION\n"
        "ACTION A: seen := S1.x AND NOT Init.x; elapsed := S1.T; END_ACTION\n"
        "END_PROGRAM\n");
    QCOMPARE(runTrace(chart,
                 {QStringLiteral("=> Init.x=TRUE; Init._x=TRUE; S1.x=FALSE; S1._x=FALSE; A.x=FALSE"),
                     QStringLiteral("go=TRUE => Init.x=TRUE; Init._x=FALSE; S1.x=FALSE; S1._x=TRUE"),
                     QStringLiteral("go=FALSE => Init.X=FALSE; S1.X=TRUE; S1.t=T#0s; seen=TRUE; elapsed=T#0s; A.x=TRUE; _A.x=TRUE; _A._x=TRUE"),
                     QStringLiteral("=> S1.x=TRUE; S1.t=T#10ms; elapsed=T#10ms"),
                     QStringLiteral("=> S1.x=TRUE; S1._x=FALSE; S1.t=T#20ms; Init._x=TRUE"),
                     // Inactive: T keeps the time the step was active; A runs its final time.
                     QStringLiteral("=> S1.x=FALSE; S1.t=T#20ms; Init.x=TRUE; A.x=FALSE; _A.x=TRUE; _A._x=FALSE; seen=FALSE"),
                     QStringLiteral("=> _A.x=FALSE")}),
        QString());
}

void TestSfcEngine::simplifiedStep()
{
    model::Project project = readText(QStringLiteral(
        "PROGRAM Main\nVAR go : BOOL; na : INT; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO S1 := go; END_TRANSITION\n"
        "STEP S1: END_STEP\n"
        "TRANSITION FROM S1 TO Init := NOT go; END_TRANSITION\n"
        "ACTION Act: na := na + 1; END_ACTION\n"
        "END_PROGRAM\n"));
    editStep(project, QStringLiteral("Main"), QStringLiteral("S1"), [](model::StepOptions &o) {
        o.simplified = true;
        o.activeAction = QStringLiteral("Act");
    });
    QCOMPARE(runTrace(project,
                 {QStringLiteral("=> S1=FALSE; _S1=FALSE; na=0"), QStringLiteral("go=TRUE => S1=FALSE; _S1=TRUE; na=0"),
                     QStringLiteral("=> S1=TRUE; _S1=TRUE; _timeS1=T#0s; na=1"), QStringLiteral("go=FALSE => S1=TRUE; _timeS1=T#10ms; na=2"),
                     QStringLiteral("=> S1=FALSE; na=2")}),
        QString());
}

void TestSfcEngine::branchPriority_data()
{
    QTest::addColumn<QString>("first");
    QTest::addColumn<QString>("second");
    QTest::addColumn<QString>("expected");
    QTest::newRow("left to right") << "" << "" << "SA.x=TRUE; SB.x=FALSE";
    QTest::newRow("explicit priority") << "(PRIORITY := 2)" << "(PRIORITY := 1)" << "SA.x=FALSE; SB.x=TRUE";
}

void TestSfcEngine::branchPriority()
{
    QFETCH(QString, first);
    QFETCH(QString, second);
    QFETCH(QString, expected);
    const QString chart = QStringLiteral(
        "PROGRAM Main\nVAR a : BOOL; b : BOOL; back : BOOL; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION %1 FROM Init TO SA := a; END_TRANSITION\n"
        "TRANSITION %2 FROM Init TO SB := b; END_TRANSITION\n"
        "STEP SA: END_STEP\nTRANSITION FROM SA TO Init := back; END_TRANSITION\n"
        "STEP SB: END_STEP\nTRANSITION FROM SB TO Init := back; END_TRANSITION\n"
        "END_PROGRAM\n")
                              .arg(first, second);
    QCOMPARE(runTrace(chart, {QStringLiteral("=> Init.x=TRUE"), QStringLiteral("a=TRUE; b=TRUE => Init.x=TRUE"), QStringLiteral("=> Init.x=FALSE; ") + expected}),
        QString());
    // Only b: B, whatever the priority.
    QCOMPARE(runTrace(chart, {QStringLiteral("b=TRUE => Init.x=TRUE"), QStringLiteral("=> SA.x=FALSE; SB.x=TRUE")}), QString());
}

void TestSfcEngine::parallelJoinWaitsForAllBranches()
{
    const QString chart = QStringLiteral(
        "PROGRAM Main\nVAR go : BOOL; a : BOOL; b : BOOL; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO (A1, B1) := go; END_TRANSITION\n"
        "STEP A1: END_STEP\nSTEP B1: END_STEP\n"
        "TRANSITION FROM A1 TO A2 := a; END_TRANSITION\n"
        "TRANSITION FROM B1 TO B2 := b; END_TRANSITION\n"
        "STEP A2: END_STEP\nSTEP B2: END_STEP\n"
        "TRANSITION FROM (A2, B2) TO Init := TRUE; END_TRANSITION\n"
        "END_PROGRAM\n");
    QCOMPARE(runTrace(chart,
                 {QStringLiteral("=> Init.x=TRUE"), QStringLiteral("go=TRUE => Init.x=TRUE"),
                     QStringLiteral("go=FALSE => Init.x=FALSE; A1.x=TRUE; B1.x=TRUE"),
                     QStringLiteral("a=TRUE => A1.x=TRUE; B1.x=TRUE"), QStringLiteral("=> A2.x=TRUE; B1.x=TRUE; A1.x=FALSE"),
                     QStringLiteral("=> A2.x=TRUE; B1.x=TRUE; Init.x=FALSE"), QStringLiteral("b=TRUE => A2.x=TRUE; B1.x=TRUE"),
                     QStringLiteral("=> A2.x=TRUE; B2.x=TRUE; B1.x=FALSE"), QStringLiteral("=> A2.x=FALSE; B2.x=FALSE; Init.x=TRUE")}),
        QString());
}

namespace {

// Init --go--> S1 --TRUE--> S2 --NOT go--> Init, S1 with a minimum and S2 with a maximum time.
model::Project limitChart(const QString &extraVars)
{
    model::Project project = readText(QStringLiteral(
        "PROGRAM Main\nVAR go : BOOL; %1 END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO S1 := go; END_TRANSITION\n"
        "STEP S1: END_STEP\n"
        "TRANSITION FROM S1 TO S2 := TRUE; END_TRANSITION\n"
        "STEP S2: END_STEP\n"
        "TRANSITION FROM S2 TO Init := NOT go; END_TRANSITION\n"
        "END_PROGRAM\n")
                                          .arg(extraVars));
    editStep(project, QStringLiteral("Main"), QStringLiteral("S1"), [](model::StepOptions &o) { o.minTime = QStringLiteral("T#30ms"); });
    editStep(project, QStringLiteral("Main"), QStringLiteral("S2"), [](model::StepOptions &o) { o.maxTime = QStringLiteral("T#20ms"); });
    return project;
}

} // namespace

void TestSfcEngine::minAndMaxTimes()
{
    const model::Project project = limitChart(QStringLiteral(
        "SFCError : BOOL; SFCErrorStep : STRING; SFCErrorPOU : STRING; SFCQuitError : BOOL;"));
    QCOMPARE(runTrace(project,
                 {QStringLiteral("=> Init.x=TRUE"), QStringLiteral("go=TRUE => S1._x=TRUE"),
                     // S1 waits for its minimum time although its transition is TRUE.
                     QStringLiteral("=> S1.x=TRUE; S1.t=T#0s"), QStringLiteral("=> S1.x=TRUE"), QStringLiteral("=> S1.x=TRUE"),
                     QStringLiteral("=> S1.x=TRUE; S1.t=T#30ms; S2._x=TRUE"),
                     QStringLiteral("=> S2.x=TRUE; SFCError=FALSE"), QStringLiteral("=> S2.t=T#10ms; SFCError=FALSE"),
                     QStringLiteral("=> S2.t=T#20ms; SFCError=FALSE"),
                     QStringLiteral("=> S2.t=T#30ms; SFCError=TRUE; SFCErrorStep='S2'; SFCErrorPOU='Main'"),
                     // SFCQuitError: the chart stands still and the error goes; afterwards the
                     // active steps' times start again.
                     QStringLiteral("SFCQuitError=TRUE => SFCError=FALSE; S2.x=TRUE; S2.t=T#30ms"),
                     QStringLiteral("SFCQuitError=FALSE => SFCError=FALSE; S2.t=T#0s"), QStringLiteral("=> S2.t=T#10ms"),
                     QStringLiteral("=> S2.t=T#20ms; SFCError=FALSE"), QStringLiteral("=> S2.t=T#30ms; SFCError=TRUE")}),
        QString());
}

void TestSfcEngine::enableLimit()
{
    // Declared SFCEnableLimit switches the time-out detection; FALSE (its default) ignores it.
    const model::Project project = limitChart(QStringLiteral("SFCError : BOOL; SFCEnableLimit : BOOL;"));
    const QStringList trace {QStringLiteral("go=TRUE"), QStringLiteral("=> S1._x=TRUE"), {}, {}, {}, {}, {},
        QStringLiteral("=> S2.t=T#20ms"), QStringLiteral("=> S2.t=T#30ms; SFCError=FALSE"),
        QStringLiteral("SFCEnableLimit=TRUE => S2.t=T#40ms; SFCError=TRUE")};
    QCOMPARE(runTrace(project, trace), QString());
}

void TestSfcEngine::flags()
{
    const QString chart = QStringLiteral(
        "PROGRAM Main\nVAR SFCInit : BOOL; SFCReset : BOOL; SFCPause : BOOL; SFCTrans : BOOL; SFCCurrentStep : STRING; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO S1 := TRUE; END_TRANSITION\n"
        "STEP S1: END_STEP\n"
        "TRANSITION FROM S1 TO S2 := TRUE; END_TRANSITION\n"
        "STEP S2: END_STEP\n"
        "TRANSITION FROM S2 TO Init := TRUE; END_TRANSITION\n"
        "END_PROGRAM\n");
    QCOMPARE(runTrace(chart,
                 {QStringLiteral("=> Init.x=TRUE; SFCTrans=TRUE; SFCCurrentStep='Init'"),
                     QStringLiteral("=> S1.x=TRUE; SFCCurrentStep='S1'"),
                     // SFCPause: nothing moves.
                     QStringLiteral("SFCPause=TRUE => S1.x=TRUE; S2.x=FALSE; SFCTrans=FALSE; SFCCurrentStep='S1'"),
                     QStringLiteral("SFCPause=FALSE => S2.x=TRUE; SFCTrans=TRUE; SFCCurrentStep='S2'"),
                     QStringLiteral("=> Init.x=TRUE; SFCCurrentStep='Init'"),
                     // SFCReset: back to Init, which runs (and leaves) in the same cycle.
                     QStringLiteral("SFCReset=TRUE => Init.x=TRUE; S1.x=FALSE; S1._x=TRUE; SFCCurrentStep='Init'"),
                     QStringLiteral("SFCReset=FALSE => S1.x=TRUE; Init.x=FALSE"),
                     // SFCInit: held before Init while TRUE.
                     QStringLiteral("SFCInit=TRUE => S1.x=FALSE; S2.x=FALSE; Init._x=TRUE; SFCTrans=FALSE"),
                     QStringLiteral("=> S1.x=FALSE; S2.x=FALSE; Init.x=FALSE"),
                     QStringLiteral("SFCInit=FALSE => Init.x=TRUE; SFCTrans=TRUE"), QStringLiteral("=> S1.x=TRUE")}),
        QString());
}

void TestSfcEngine::tipMode()
{
    const QString chart = QStringLiteral(
        "PROGRAM Main\nVAR SFCTip : BOOL; SFCTipMode : BOOL; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO S1 := TRUE; END_TRANSITION\n"
        "STEP S1: END_STEP\n"
        "TRANSITION FROM S1 TO S2 := FALSE; END_TRANSITION\n"
        "STEP S2: END_STEP\n"
        "TRANSITION FROM S2 TO Init := TRUE; END_TRANSITION\n"
        "END_PROGRAM\n");
    // In inching mode only a rising edge of SFCTip passes the enabled transition (even a FALSE one).
    QCOMPARE(runTrace(chart,
                 {QStringLiteral("SFCTipMode=TRUE => Init.x=TRUE"), QStringLiteral("=> Init.x=TRUE"),
                     QStringLiteral("SFCTip=TRUE => Init.x=TRUE"), QStringLiteral("=> S1.x=TRUE"),
                     QStringLiteral("SFCTip=FALSE => S1.x=TRUE"), QStringLiteral("SFCTip=TRUE => S1.x=TRUE"),
                     QStringLiteral("=> S2.x=TRUE"), QStringLiteral("SFCTipMode=FALSE => S2.x=TRUE"), QStringLiteral("=> Init.x=TRUE")}),
        QString());
}

void TestSfcEngine::chartInFunctionBlockHasOneStatePerInstance()
{
    const QString source = QStringLiteral(
        "FUNCTION_BLOCK Seq\nVAR_INPUT go : BOOL; END_VAR\nVAR n : INT; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO S1 := go; END_TRANSITION\n"
        "STEP S1: A(N); END_STEP\n"
        "TRANSITION FROM S1 TO Init := NOT go; END_TRANSITION\n"
        "ACTION A: n := n + 1; END_ACTION\n"
        "END_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR a : Seq; b : Seq; ga : BOOL; gb : BOOL; END_VAR\n"
        "a(go := ga);\nb(go := gb);\n"
        "END_PROGRAM\n");
    QCOMPARE(runTrace(source,
                 {QStringLiteral("ga=TRUE => a.Init.x=TRUE; b.Init.x=TRUE"), QStringLiteral("=> a.S1.x=TRUE; b.S1.x=FALSE; a.n=1; b.n=0"),
                     QStringLiteral("gb=TRUE => a.S1.x=TRUE; b.S1.x=FALSE; a.n=2"),
                     QStringLiteral("ga=FALSE => a.S1.x=TRUE; b.S1.x=TRUE; a.n=3; b.n=1"),
                     QStringLiteral("=> a.S1.x=FALSE; a.Init.x=TRUE; b.S1.x=TRUE; a.n=4; b.n=2")}),
        QString());
}

// A chart in an action keeps its hidden variables under __sfc_ACTION_ (sfclowering.cpp); its state
// is read from there, and the POU's own body (ST) has none.
void TestSfcEngine::chartStateOfAnAction()
{
    const model::Project project = readText(QStringLiteral(
        "PROGRAM Main\nVAR n : INT; END_VAR\nSeq();\nACTION Seq:\nINITIAL_STEP Idle: END_STEP\nTRANSITION FROM Idle TO Fill := TRUE; END_TRANSITION\n"
        "STEP Fill: Count(N); END_STEP\nTRANSITION FROM Fill TO Idle := n >= 2; END_TRANSITION\nEND_ACTION\n"
        "ACTION Count:\nn := n + 1;\nEND_ACTION\nEND_PROGRAM\n"));
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(project, diagnostics);
    QVERIFY2(module, qPrintable(errorsOf(diagnostics)));
    Runtime runtime(module);
    QVERIFY(runtime.runCycles(2));
    const model::Pou &main = project.types.pous.front();
    QVERIFY(!sfc::chartState(runtime, main, QStringLiteral("Main")));
    QVERIFY(!sfc::chartState(runtime, main, QStringLiteral("Main"), QStringLiteral("Count")));
    const auto state = sfc::chartState(runtime, main, QStringLiteral("Main"), QStringLiteral("seq"));
    QVERIFY(state);
    QCOMPARE(state->action, QStringLiteral("seq"));
    QCOMPARE(state->steps.size(), size_t(2));
    QCOMPARE(state->steps[0].active, false);
    QCOMPARE(state->steps[1].active, true);
    QCOMPARE(state->steps[1].elapsedNs, std::int64_t(0)); // active since this cycle
    QCOMPARE(state->actions.size(), size_t(1));
    QCOMPARE(state->actions[0].name, QStringLiteral("Count"));
    QCOMPARE(state->actions[0].active, true);
    QCOMPARE(state->transitions.size(), size_t(2));
    QCOMPARE(state->transitions[1].condition, false); // n = 1
}

// A chart POU whose step runs action Outer, a chart whose step runs Inner, a chart too: each
// action chart's state is read under its own name however deep it runs; a chart that runs itself
// is refused.
void TestSfcEngine::chartInAChartInAnAction()
{
    const QString source = QStringLiteral(
        "PROGRAM Main\nVAR go : BOOL; END_VAR\nINITIAL_STEP Run: Outer(N); END_STEP\nTRANSITION FROM Run TO Halt := go; END_TRANSITION\n"
        "STEP Halt: END_STEP\nTRANSITION FROM Halt TO Run := NOT go; END_TRANSITION\n"
        "ACTION Outer:\nINITIAL_STEP O1: Inner(N); END_STEP\nTRANSITION FROM O1 TO O2 := go; END_TRANSITION\n"
        "STEP O2: END_STEP\nTRANSITION FROM O2 TO O1 := TRUE; END_TRANSITION\nEND_ACTION\n"
        "ACTION Inner:\nINITIAL_STEP I1: END_STEP\nTRANSITION FROM I1 TO I2 := TRUE; END_TRANSITION\n"
        "STEP I2: END_STEP\nTRANSITION FROM I2 TO I1 := TRUE; END_TRANSITION\nEND_ACTION\nEND_PROGRAM\n");
    const model::Project project = readText(source);
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(project, diagnostics);
    QVERIFY2(module, qPrintable(errorsOf(diagnostics)));
    Runtime runtime(module);
    const model::Pou &main = project.types.pous.front();
    QStringList cycles;
    for (int cycle = 0; cycle < 3; ++cycle) {
        QVERIFY(runtime.runCycles(1));
        QString active;
        for (const char *action : {"", "Outer", "Inner"}) {
            const auto state = sfc::chartState(runtime, main, QStringLiteral("Main"), QLatin1String(action));
            QVERIFY2(state, action);
            for (const sfc::StepState &step : state->steps)
                active += step.active ? step.name : QString();
        }
        cycles << active;
    }
    QCOMPARE(cycles, QStringList({"RunO1I1", "RunO1I2", "RunO1I1"}));

    Diagnostics looping;
    QVERIFY(!frontend::compileProject(readText(QString(source).replace(QStringLiteral("INITIAL_STEP I1: END_STEP"),
                                                                 QStringLiteral("INITIAL_STEP I1: Outer(N); END_STEP"))),
        looping));
    QVERIFY2(errorsOf(looping).contains(QStringLiteral("is an SFC chart that contains itself.")), qPrintable(errorsOf(looping)));
}

void TestSfcEngine::chartState()
{
    const model::Project project = readText(qualifierChart(QStringLiteral("N")));
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(project, diagnostics);
    QVERIFY2(module, qPrintable(errorsOf(diagnostics)));
    Runtime runtime(module);
    QVERIFY(!sfc::chartState(runtime, project.types.pous.front(), QStringLiteral("Nobody")));
    QVERIFY(runtime.write(QStringLiteral("Main.go"), QStringLiteral("TRUE")) == std::nullopt);
    QVERIFY(runtime.runCycles(4));
    const auto state = sfc::chartState(runtime, project.types.pous.front(), QStringLiteral("Main"));
    QVERIFY(state);
    QCOMPARE(state->instance, QStringLiteral("Main"));
    QCOMPARE(state->steps.size(), size_t(2));
    QCOMPARE(state->steps[0].name, QStringLiteral("Init"));
    QCOMPARE(state->steps[0].active, false);
    QCOMPARE(state->steps[1].name, QStringLiteral("S1"));
    QCOMPARE(state->steps[1].active, true);
    QCOMPARE(state->steps[1].elapsedNs, std::int64_t(20'000'000));
    QCOMPARE(state->actions.size(), size_t(2));
    QCOMPARE(state->actions[0].name, QStringLiteral("A"));
    QCOMPARE(state->actions[0].active, true);
    QCOMPARE(state->actions[1].name, QStringLiteral("Out"));
    QCOMPARE(state->transitions.size(), size_t(2));
    const auto programs = sfc::programChartStates(runtime, project);
    QCOMPARE(programs.size(), size_t(1));
    QCOMPARE(programs.front().steps[1].active, true);

    // The same state through a layout built once; conditions are read where the chart left them.
    QCOMPARE(state->actions[1].active, true);
    QCOMPARE(state->transitions[0].condition, false); // Init is not active: its transition is not evaluated
    QCOMPARE(state->transitions[1].condition, false); // NOT go
    const auto layout = sfc::chartLayout(project.types.pous.front());
    QVERIFY(layout);
    QCOMPARE(layout->transitions.size(), size_t(2));
    QCOMPARE(state->transitions[0].localId, layout->transitions[0]);
    QCOMPARE(state->transitions[1].localId, layout->transitions[1]);
    QVERIFY(!sfc::chartState(runtime, *layout, QStringLiteral("Nobody")));
    QVERIFY(runtime.write(QStringLiteral("Main.go"), QStringLiteral("FALSE")) == std::nullopt);
    QVERIFY(runtime.runCycles(1));
    const auto fired = sfc::chartState(runtime, *layout, QStringLiteral("Main"));
    QVERIFY(fired);
    QCOMPARE(fired->pou, QStringLiteral("Main"));
    QCOMPARE(fired->steps[1].active, true); // the step changes in the next cycle
    QCOMPARE(fired->transitions[0].condition, false);
    QCOMPARE(fired->transitions[1].condition, true);
    QVERIFY(runtime.runCycles(1));
    const auto back = sfc::chartState(runtime, *layout, QStringLiteral("Main"));
    QVERIFY(back);
    QCOMPARE(back->steps[0].active, true);
    QCOMPARE(back->steps[1].active, false);
    QCOMPARE(back->steps[1].elapsedNs, std::int64_t(0));
    QCOMPARE(back->actions[0].active, false);
    QCOMPARE(back->transitions[1].condition, false);
}

void TestSfcEngine::ilCondition()
{
    const QString chart = QStringLiteral(
        "PROGRAM Main\nVAR a : BOOL; b : BOOL; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO S1:\n LD a\n ANDN b\nEND_TRANSITION\n"
        "STEP S1: END_STEP\n"
        "TRANSITION FROM S1 TO Init := FALSE; END_TRANSITION\n"
        "END_PROGRAM\n");
    QCOMPARE(runTrace(chart, {QStringLiteral("a=TRUE; b=TRUE => Init.x=TRUE"), QStringLiteral("b=FALSE => Init.x=TRUE"), QStringLiteral("=> S1.x=TRUE")}),
        QString());
}

// IL cannot be inlined into the chart: the action is compiled as Main.A and the chart calls it.
// With N it runs while S1 is active plus the final run, exactly like the ST action above.
void TestSfcEngine::ilActionRunsAsCalledAction()
{
    const QString chart = QStringLiteral(
        "PROGRAM Main\nVAR go : BOOL; n : INT; ne : INT; Out : BOOL; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO S1 := go; END_TRANSITION\n"
        "STEP S1: A(N); Out(N); END_STEP\n"
        "TRANSITION FROM S1 TO Init := NOT go; END_TRANSITION\n"
        "ACTION A:\n LD n\n ADD 1\n ST n\nEND_ACTION\n"
        "ACTION En:\n LD ne\n ADD 10\n ST ne\nEND_ACTION\n"
        "END_PROGRAM\n");
    model::Project project = readText(chart);
    const model::Pou &pou = project.types.pous.front();
    QCOMPARE(int(pou.actions.size()), 2);
    QCOMPARE(int(pou.actions.front().body.language()), int(model::BodyLanguage::IL));
    QCOMPARE(runTrace(project, qualifierTrace(QStringLiteral("0 0 1 2 3 4 5 6 6"), QStringLiteral("F F T T T T T F F"))), QString());
    // The same IL action as a step's entry action too: called, compiled once.
    editStep(project, QStringLiteral("Main"), QStringLiteral("S1"), [](model::StepOptions &o) { o.entryAction = QStringLiteral("En"); });
    QCOMPARE(runTrace(project, {QStringLiteral("=> ne=0; n=0"), QStringLiteral("go=TRUE => ne=0"), QStringLiteral("=> ne=10; n=1"),
                                   QStringLiteral("=> ne=10; n=2")}),
        QString());

    // Straight from .st text (iecstudio-cli run chart.st): the parsed IL body is called as well.
    Diagnostics diagnostics;
    frontend::ProjectUnit unit {parseUnit(chart, diagnostics), false};
    const auto module = frontend::compileUnit(unit, diagnostics);
    QVERIFY2(module, qPrintable(errorsOf(diagnostics)));
    Runtime runtime(module);
    QVERIFY(!runtime.write(QStringLiteral("Main.go"), QStringLiteral("TRUE")));
    QVERIFY(runtime.runCycles(4));
    QCOMPARE(runtime.read(QStringLiteral("Main.n")).value_or(QString()), QStringLiteral("3"));
    QCOMPARE(errorsOf(diagnostics), QString());
}

QTEST_GUILESS_MAIN(TestSfcEngine)
#include "tst_sfcengine.moc"
