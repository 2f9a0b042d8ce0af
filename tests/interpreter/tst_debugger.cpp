// The runtime's debugger: breakpoints on lines, hit counts and conditions, halting mid-scan,
// stepping over, into and out of calls, and going on with the same results as without halting.
#include "interpreter/compiler/compiler.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/graphical/graphicallowering.h"
#include "interpreter/runtime/conditionexpression.h"
#include "interpreter/runtime/runtime.h"

#include "graphical/diagram.h"

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

// Lines:                  1              2                                3
const char *const kLoop = "PROGRAM Main\nVAR i : INT; sum : INT; END_VAR\nsum := 0;\n"
                          // 4                   5                  6           7
                          "FOR i := 1 TO 5 DO\n  sum := sum + i;\nEND_FOR;\nEND_PROGRAM\n";

// Lines 1-6 a function block, 7-12 the program that calls it.
const char *const kCalls = "FUNCTION_BLOCK Acc\nVAR_INPUT x : INT; END_VAR\nVAR_OUTPUT total : INT; END_VAR\n"
                           "total := total + x;\ntotal := total * 1;\nEND_FUNCTION_BLOCK\n"
                           "PROGRAM Main\nVAR a : Acc; n : INT; m : INT; END_VAR\nn := n + 1;\na(x := n);\nm := a.total;\nEND_PROGRAM\n";

Breakpoint at(const QString &pou, int line)
{
    Breakpoint b;
    b.at = {pou, line, -1};
    return b;
}

QString where(const Runtime &runtime)
{
    if (!runtime.halt())
        return QStringLiteral("-");
    return QStringLiteral("%1:%2").arg(runtime.halt()->at.pou).arg(runtime.halt()->at.line);
}

} // namespace

class TestDebugger : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void breakpointInALoopHaltsInEachIteration();
    void hitCountsAndConditions_data();
    void hitCountsAndConditions();
    void conditionThatCannotBeEvaluatedHalts();
    void steppingOverIntoAndOut();
    void stepPastTheLastLineEndsTheCycle();
    void haltingChangesNoResult();
    void endlessLoopStillHalts();
    void noBreakpointsMeansNoStops();
    void conditions_data();
    void conditions();
    void ladderNetworkHaltsOnceAndStepsByNetwork();
    void packedRungsRunTheSameWhenHalting();
    void sfcStepHaltsWhenItBecomesActive();
    void sfcTransitionHaltsWhenItFires();
    void cfcElementsAreOnePlaceEach();
};

void TestDebugger::breakpointInALoopHaltsInEachIteration()
{
    auto module = build(QString::fromLatin1(kLoop));
    QVERIFY(module);
    Runtime runtime(module);
    runtime.setBreakpoints({at(QStringLiteral("Main"), 5)});
    QVERIFY(!runtime.runCycle());
    for (int i = 1; i <= 5; ++i) {
        QVERIFY(runtime.isHalted());
        QCOMPARE(where(runtime), QStringLiteral("Main:5"));
        QCOMPARE(runtime.halt()->cycle, 1);
        QCOMPARE(runtime.halt()->breakpoint, 0);
        QCOMPARE(runtime.halt()->hits, i);
        QCOMPARE(runtime.read(QStringLiteral("Main.i")), QString::number(i));
        QCOMPARE(runtime.read(QStringLiteral("Main.sum")), QString::number(i * (i - 1) / 2));
        QCOMPARE(runtime.timeNs(), 0); // the clock stands still while halted
        QCOMPARE(runtime.resume(ResumeKind::Continue), i == 5);
    }
    QVERIFY(!runtime.isHalted());
    QCOMPARE(runtime.read(QStringLiteral("Main.sum")), QStringLiteral("15"));
    QCOMPARE(runtime.cycle(), 1);
    QCOMPARE(runtime.timeNs(), runtime.cycleNs());
    // The next cycle halts again, at the first iteration.
    QVERIFY(!runtime.runCycle());
    QCOMPARE(runtime.halt()->cycle, 2);
    QCOMPARE(runtime.read(QStringLiteral("Main.i")), QStringLiteral("1"));
}

void TestDebugger::hitCountsAndConditions_data()
{
    QTest::addColumn<int>("rule");
    QTest::addColumn<int>("target");
    QTest::addColumn<QString>("condition");
    QTest::addColumn<QStringList>("halts"); // cycle/i at every halt over two cycles
    QTest::newRow("always") << int(HitRule::Always) << 1 << QString()
                            << QStringList{"1/1", "1/2", "1/3", "1/4", "1/5", "2/1", "2/2", "2/3", "2/4", "2/5"};
    QTest::newRow("the fourth hit") << int(HitRule::Equal) << 4 << QString() << QStringList{"1/4"};
    QTest::newRow("every third hit") << int(HitRule::MultipleOf) << 3 << QString() << QStringList{"1/3", "2/1", "2/4"};
    QTest::newRow("from the eighth hit") << int(HitRule::AtLeast) << 8 << QString() << QStringList{"2/3", "2/4", "2/5"};
    QTest::newRow("condition") << int(HitRule::Always) << 1 << QStringLiteral("i = 3") << QStringList{"1/3", "2/3"};
    QTest::newRow("condition on two variables") << int(HitRule::Always) << 1 << QStringLiteral("i >= 2 AND sum < 6")
                                                << QStringList{"1/2", "1/3", "2/2", "2/3"};
    QTest::newRow("hit count, then condition") << int(HitRule::AtLeast) << 4 << QStringLiteral("i MOD 2 = 1")
                                               << QStringList{"1/5", "2/1", "2/3", "2/5"};
}

void TestDebugger::hitCountsAndConditions()
{
    QFETCH(int, rule);
    QFETCH(int, target);
    QFETCH(QString, condition);
    QFETCH(QStringList, halts);
    auto module = build(QString::fromLatin1(kLoop));
    QVERIFY(module);
    Runtime runtime(module);
    Breakpoint b = at(QStringLiteral("Main"), 5);
    b.hitRule = HitRule(rule);
    b.hitTarget = target;
    b.condition = condition;
    runtime.setBreakpoints({b});
    QStringList seen;
    int guard = 0;
    while (runtime.cycle() < 2 || runtime.isHalted()) {
        runtime.runCycle();
        if (runtime.isHalted())
            seen << QStringLiteral("%1/%2").arg(runtime.halt()->cycle).arg(*runtime.read(QStringLiteral("Main.i")));
        QVERIFY(++guard < 100);
    }
    QCOMPARE(seen, halts);
    QCOMPARE(runtime.read(QStringLiteral("Main.sum")), QStringLiteral("15"));
    QCOMPARE(runtime.hitCounts(), std::vector<int>{10});
}

void TestDebugger::conditionThatCannotBeEvaluatedHalts()
{
    auto module = build(QString::fromLatin1(kLoop));
    QVERIFY(module);
    Runtime runtime(module);
    Breakpoint b = at(QStringLiteral("Main"), 5);
    b.condition = QStringLiteral("nothing > 1");
    runtime.setBreakpoints({b});
    QVERIFY(!runtime.runCycle());
    QVERIFY(runtime.isHalted());
    QCOMPARE(runtime.halt()->conditionProblem, QStringLiteral("There is no variable called nothing here."));
}

void TestDebugger::steppingOverIntoAndOut()
{
    auto module = build(QString::fromLatin1(kCalls));
    QVERIFY(module);
    Runtime runtime(module);
    runtime.setBreakpoints({at(QStringLiteral("Main"), 9)});
    QVERIFY(!runtime.runCycle());
    QCOMPARE(where(runtime), QStringLiteral("Main:9"));
    QCOMPARE(runtime.halt()->stack.size(), size_t(1));
    QCOMPARE(runtime.halt()->stack[0].instance, QStringLiteral("Main"));
    QVERIFY(!runtime.resume(ResumeKind::StepOver));
    QCOMPARE(where(runtime), QStringLiteral("Main:10"));
    QCOMPARE(runtime.halt()->breakpoint, -1);
    QVERIFY(!runtime.resume(ResumeKind::StepInto));
    QCOMPARE(where(runtime), QStringLiteral("Acc:4"));
    QCOMPARE(runtime.halt()->stack.size(), size_t(2));
    QCOMPARE(runtime.halt()->stack[0].line, 10); // the call
    QCOMPARE(runtime.halt()->stack[1].instance, QStringLiteral("Main.a"));
    QCOMPARE(runtime.read(QStringLiteral("Main.a.x")), QStringLiteral("1"));
    QVERIFY(!runtime.resume(ResumeKind::StepOver));
    QCOMPARE(where(runtime), QStringLiteral("Acc:5"));
    QVERIFY(!runtime.resume(ResumeKind::StepOut));
    QCOMPARE(where(runtime), QStringLiteral("Main:11"));
    QCOMPARE(runtime.read(QStringLiteral("Main.m")), QStringLiteral("0"));
    // Stepping over the call runs it whole.
    QVERIFY(runtime.resume(ResumeKind::StepOver)); // the last line: the cycle ends
    QCOMPARE(runtime.read(QStringLiteral("Main.m")), QStringLiteral("1"));
    QVERIFY(!runtime.runCycle());
    QCOMPARE(where(runtime), QStringLiteral("Main:9"));
    QVERIFY(!runtime.resume(ResumeKind::StepOver));
    QVERIFY(!runtime.resume(ResumeKind::StepOver));
    QCOMPARE(where(runtime), QStringLiteral("Main:11"));
    QCOMPARE(runtime.read(QStringLiteral("Main.a.total")), QStringLiteral("3"));
}

// A step from the last line ends the cycle; Run (runCycle) then runs through, a step halts at
// the first line of the next cycle.
void TestDebugger::stepPastTheLastLineEndsTheCycle()
{
    auto module = build(QString::fromLatin1(kCalls));
    QVERIFY(module);
    Runtime runtime(module);
    runtime.setBreakpoints({at(QStringLiteral("Main"), 11)});
    QVERIFY(!runtime.runCycle());
    runtime.setBreakpoints({});
    QVERIFY(runtime.resume(ResumeKind::StepOver));
    QCOMPARE(runtime.cycle(), 1);
    QVERIFY(!runtime.isHalted());
    QVERIFY(runtime.runCycle()); // no breakpoint, no step: the cycle runs through
    QCOMPARE(runtime.cycle(), 2);
    QVERIFY(!runtime.resume(ResumeKind::StepOver)); // not halted: a step starts a cycle
    QCOMPARE(where(runtime), QStringLiteral("Main:9"));
    QCOMPARE(runtime.halt()->cycle, 3);
    QVERIFY(runtime.resume(ResumeKind::Continue));
    QVERIFY(!runtime.vm().hasStops());
}

// Halting at every line of every cycle and going on gives, cycle by cycle, the memory image of
// a run without the debugger.
void TestDebugger::haltingChangesNoResult()
{
    const QString source = QString::fromLatin1(kCalls) + QStringLiteral("PROGRAM Second\nVAR t : TON; q : BOOL; k : INT; END_VAR\n"
                                                                        "t(IN := NOT q, PT := T#30ms);\nq := t.Q;\n"
                                                                        "IF q THEN k := k + 1; END_IF;\nEND_PROGRAM\n"
                                                                        "CONFIGURATION C RESOURCE R ON PLC\n"
                                                                        "TASK Fast(INTERVAL := T#10ms, PRIORITY := 1);\n"
                                                                        "TASK Slow(INTERVAL := T#20ms, PRIORITY := 2);\n"
                                                                        "PROGRAM P1 WITH Fast : Main;\nPROGRAM P2 WITH Slow : Second;\n"
                                                                        "END_RESOURCE END_CONFIGURATION\n");
    auto module = build(source);
    QVERIFY(module);
    Runtime plain(module);
    Runtime halting(module);
    halting.setBreakpoints({at(QStringLiteral("Main"), 9), at(QStringLiteral("Acc"), 5), at(QStringLiteral("Second"), 16)});
    int halts = 0;
    for (int cycle = 1; cycle <= 12; ++cycle) {
        QVERIFY(plain.runCycle());
        bool done = halting.runCycle();
        while (!done) {
            QVERIFY(halting.isHalted());
            ++halts;
            done = halting.resume(halts % 3 == 0 ? ResumeKind::StepInto : ResumeKind::Continue);
        }
        QCOMPARE(halting.cycle(), cycle);
        QVERIFY(halting.vm().memory() == plain.vm().memory());
        QCOMPARE(halting.read(QStringLiteral("Second.k")), plain.read(QStringLiteral("Second.k")));
    }
    QVERIFY(halts >= 12 * 2 + 6);
    QCOMPARE(plain.read(QStringLiteral("Second.k")), QStringLiteral("1"));
}

void TestDebugger::endlessLoopStillHalts()
{
    auto module = build(QStringLiteral("PROGRAM Main\nVAR n : DINT; END_VAR\nWHILE TRUE DO\n  n := n + 1;\nEND_WHILE;\nEND_PROGRAM\n"));
    QVERIFY(module);
    Runtime runtime(module);
    runtime.vm().budgetPerRun = 1000;
    runtime.setBreakpoints({at(QStringLiteral("Main"), 4)});
    QVERIFY(!runtime.runCycle());
    for (int n = 0; n < 3; ++n) {
        QCOMPARE(where(runtime), QStringLiteral("Main:4"));
        QCOMPARE(runtime.read(QStringLiteral("Main.n")), QString::number(n));
        QVERIFY(!runtime.resume(ResumeKind::Continue));
    }
    runtime.setBreakpoints({});
    QVERIFY(!runtime.resume(ResumeKind::Continue));
    QVERIFY(!runtime.isHalted());
    QVERIFY(runtime.fault());
    QCOMPARE(runtime.fault()->kind, FaultKind::BudgetExceeded);
    QCOMPARE(runtime.fault()->line, 3); // an endless loop is reported at its WHILE
}

void TestDebugger::noBreakpointsMeansNoStops()
{
    auto module = build(QString::fromLatin1(kLoop));
    QVERIFY(module);
    Runtime runtime(module);
    QVERIFY(!runtime.vm().hasStops());
    runtime.setBreakpoints({at(QStringLiteral("Main"), 5)});
    QVERIFY(runtime.vm().hasStops());
    QVERIFY(!runtime.runCycle());
    runtime.setBreakpoints({});
    QVERIFY(runtime.vm().hasStops()); // still halted: a step may follow
    QVERIFY(runtime.resume(ResumeKind::Continue));
    QVERIFY(!runtime.vm().hasStops());
    // A breakpoint on a line without code is kept and never halts.
    runtime.setBreakpoints({at(QStringLiteral("Main"), 2)});
    QVERIFY(runtime.runCycle());
    QCOMPARE(runtime.breakpoints().size(), size_t(1));
}

void TestDebugger::conditions_data()
{
    QTest::addColumn<QString>("condition");
    QTest::addColumn<QString>("result"); // TRUE, FALSE, or the error
    QTest::newRow("comparison") << QStringLiteral("count = 7") << QStringLiteral("TRUE");
    QTest::newRow("arithmetic") << QStringLiteral("count * 2 + 1 > 15") << QStringLiteral("FALSE");
    QTest::newRow("real") << QStringLiteral("level > 2.25") << QStringLiteral("TRUE");
    QTest::newRow("bool") << QStringLiteral("NOT alarm OR count < 0") << QStringLiteral("TRUE");
    QTest::newRow("time") << QStringLiteral("delay >= T#1s500ms") << QStringLiteral("TRUE");
    QTest::newRow("string") << QStringLiteral("name = 'pump'") << QStringLiteral("TRUE");
    QTest::newRow("array element") << QStringLiteral("values[count - 5] = 20") << QStringLiteral("TRUE");
    QTest::newRow("global") << QStringLiteral("Limit = 100") << QStringLiteral("TRUE");
    QTest::newRow("instance name") << QStringLiteral("Main.count <> 7") << QStringLiteral("FALSE");
    QTest::newRow("number") << QStringLiteral("count + 1") << QStringLiteral("The condition must be TRUE or FALSE, not a number or a text.");
    QTest::newRow("syntax") << QStringLiteral("count = = 2") << QStringLiteral("This is not an expression: count = = 2");
    QTest::newRow("division by zero") << QStringLiteral("count / 0 > 1") << QStringLiteral("The condition divides by zero.");
    QTest::newRow("a call") << QStringLiteral("ABS(count) > 1")
                            << QStringLiteral("A condition can only read variables and compare them; it cannot call anything.");
}

void TestDebugger::conditions()
{
    QFETCH(QString, condition);
    QFETCH(QString, result);
    auto module = build(QStringLiteral("VAR_GLOBAL Limit : INT := 100; END_VAR\n"
                                       "PROGRAM Main\nVAR count : INT := 7; level : REAL := 2.5; alarm : BOOL; delay : TIME := T#2s;\n"
                                       "name : STRING := 'pump'; values : ARRAY[1..3] OF INT := [10, 20, 30]; END_VAR\n"
                                       "count := count;\nEND_PROGRAM\n"));
    QVERIFY(module);
    Runtime runtime(module);
    const ConditionScope scope{*module, runtime.vm().memory().data(), {runtime.image('I').data(), runtime.image('Q').data(), runtime.image('M').data()},
                               QStringLiteral("Main")};
    const ConditionResult r = evaluateCondition(condition, scope);
    QCOMPARE(r.value ? QString::fromLatin1(*r.value ? "TRUE" : "FALSE") : r.error, result);
}

namespace {

std::shared_ptr<const Module> buildProject(const model::Project &project)
{
    Diagnostics diagnostics;
    auto module = frontend::compileProject(project, diagnostics);
    for (const Diagnostic &d : diagnostics.all())
        qWarning("%s", qPrintable(d.toString()));
    return module;
}

// Init --go--> Run --NOT go--> Init, with n counted while Run is active.
const char *const kChart = "PROGRAM Main\nVAR go : BOOL; n : INT; END_VAR\n"
                           "INITIAL_STEP Init: END_STEP\n"
                           "TRANSITION FROM Init TO Run := go; END_TRANSITION\n"
                           "STEP Run: Count(N); END_STEP\n"
                           "TRANSITION FROM Run TO Init := NOT go; END_TRANSITION\n"
                           "ACTION Count: n := n + 1; END_ACTION\n"
                           "END_PROGRAM\n";

model::Project chartProject()
{
    return frontend::readIecText(QString::fromLatin1(kChart), QStringLiteral("t")).project;
}

const std::vector<model::Element> &chartElements(const model::Project &project)
{
    return *project.findPou(QStringLiteral("Main"))->bodies.front().elements();
}

qint64 stepId(const model::Project &project, const QString &name)
{
    for (const model::Element &e : chartElements(project))
        if (const auto *step = std::get_if<model::Step>(&e); step && step->name == name)
            return qint64(step->localId);
    return -1;
}

// The transition below step `from` (wired to it).
qint64 transitionAfter(const model::Project &project, qint64 from)
{
    for (const model::Element &e : chartElements(project))
        if (const auto *t = std::get_if<model::Transition>(&e); t && t->connectionPointIn)
            for (const model::Connection &c : t->connectionPointIn->connections)
                if (qint64(c.refLocalId) == from)
                    return qint64(t->localId);
    return -1;
}

} // namespace

// Two rungs on one shared left rail (as Beremiz draws them); the first has two coils in series.
void TestDebugger::ladderNetworkHaltsOnceAndStepsByNetwork()
{
    iec::testing::Diagram d;
    d.rail(1).contact(2, QStringLiteral("a"), {{1, {}}}).coil(3, QStringLiteral("x"), {{2, {}}}).coil(4, QStringLiteral("y"), {{3, {}}}, 600);
    d.contact(5, QStringLiteral("x"), {{1, {}}}, 0, 100).coil(6, QStringLiteral("z"), {{5, {}}}, 500, 100);
    auto module = buildProject(iec::testing::diagramProject(QStringLiteral("VAR a, x, y, z : BOOL; END_VAR"), model::BodyLanguage::LD, d));
    QVERIFY(module);
    Runtime runtime(module);
    QVERIFY(runtime.write(QStringLiteral("Main.a"), QStringLiteral("TRUE")) == std::nullopt);
    Breakpoint first;
    first.at = {QStringLiteral("Main"), 0, -1, {2, 3, 4}};
    runtime.setBreakpoints({first});
    QVERIFY(!runtime.runCycle());
    QCOMPARE(runtime.halt()->breakpoint, 0);
    const qint64 firstPlace = runtime.halt()->at.localId;
    QVERIFY2(firstPlace == 3 || firstPlace == 4, qPrintable(QString::number(firstPlace)));
    QCOMPARE(runtime.read(QStringLiteral("Main.x")), QStringLiteral("FALSE"));
    // Step over: the whole first rung ran, the program stands at the second.
    QVERIFY(!runtime.resume(ResumeKind::StepOver));
    QCOMPARE(runtime.halt()->at.localId, 6);
    QCOMPARE(runtime.halt()->breakpoint, -1);
    QCOMPARE(runtime.read(QStringLiteral("Main.x")), QStringLiteral("TRUE"));
    QCOMPARE(runtime.read(QStringLiteral("Main.y")), QStringLiteral("TRUE"));
    QCOMPARE(runtime.read(QStringLiteral("Main.z")), QStringLiteral("FALSE"));
    QVERIFY(runtime.resume(ResumeKind::StepOver)); // the last rung: the cycle ends
    QCOMPARE(runtime.read(QStringLiteral("Main.z")), QStringLiteral("TRUE"));
    // The breakpoint halts once per cycle, not once per coil.
    QVERIFY(!runtime.runCycle());
    QCOMPARE(runtime.halt()->hits, 2);
    QVERIFY(runtime.resume(ResumeKind::Continue));
    // A breakpoint on the second rung by one of its elements.
    Breakpoint second;
    second.at = {QStringLiteral("Main"), 0, 5, {5, 6}};
    runtime.setBreakpoints({second});
    QVERIFY(!runtime.runCycle());
    QCOMPARE(runtime.halt()->at.localId, 6);
}

// Ten rungs --[a]--[/b]--+--(o)  with  --[c]--[o of the rung before]-- in parallel: the compiler
// packs them into one RungBlock, which the debugger's code unpacks; every cycle the memory must
// be that of a run without breakpoints.
void TestDebugger::packedRungsRunTheSameWhenHalting()
{
    constexpr int kRungs = 10;
    iec::testing::Diagram d;
    QStringList names;
    for (int k = 0; k < kRungs; ++k) {
        const quint64 base = 10 * quint64(k) + 10;
        const double y = 60.0 * k;
        const QString n = QString::number(k);
        d.rail(base, y);
        d.contact(base + 1, QStringLiteral("a") + n, {{base, {}}}, 100, y);
        d.contact(base + 2, QStringLiteral("b") + n, {{base + 1, {}}}, 200, y, true);
        d.contact(base + 3, QStringLiteral("c") + n, {{base, {}}}, 100, y + 30);
        d.contact(base + 4, k == 0 ? QStringLiteral("c0") : QStringLiteral("o") + QString::number(k - 1), {{base + 3, {}}}, 200, y + 30);
        d.coil(base + 5, QStringLiteral("o") + n, {{base + 2, {}}, {base + 4, {}}}, 400, y);
        names << QStringLiteral("a") + n << QStringLiteral("b") + n << QStringLiteral("c") + n << QStringLiteral("o") + n;
    }
    auto module = buildProject(iec::testing::diagramProject(QStringLiteral("VAR %1 : BOOL; END_VAR").arg(names.join(QStringLiteral(", "))),
                                                            model::BodyLanguage::LD, d));
    QVERIFY(module);
    QVERIFY(std::ranges::any_of(module->code, [](const Instr &i) { return i.op == op::RungBlock; }));
    Runtime plain(module);
    Runtime halting(module);
    Breakpoint third;
    third.at = {QStringLiteral("Main"), 0, 35, {31, 32, 33, 34, 35}};
    halting.setBreakpoints({third});
    quint32 pattern = 12345;
    int halts = 0;
    for (int cycle = 1; cycle <= 20; ++cycle) {
        for (int k = 0; k < kRungs; ++k) {
            for (const char *input : {"a", "b", "c"}) {
                pattern = pattern * 1103515245u + 12345u;
                const QString name = QStringLiteral("Main.%1%2").arg(QLatin1String(input)).arg(k);
                const QString value = (pattern >> 16) & 1 ? QStringLiteral("TRUE") : QStringLiteral("FALSE");
                QVERIFY(!plain.write(name, value));
                QVERIFY(!halting.write(name, value));
            }
        }
        QVERIFY(plain.runCycle());
        bool done = halting.runCycle();
        while (!done) {
            ++halts;
            done = halting.resume(halts % 2 ? ResumeKind::StepOver : ResumeKind::Continue);
        }
        QVERIFY2(halting.vm().memory() == plain.vm().memory(), qPrintable(QStringLiteral("cycle %1").arg(cycle)));
    }
    QVERIFY(halts >= 20);
}

void TestDebugger::sfcStepHaltsWhenItBecomesActive()
{
    const model::Project project = chartProject();
    const qint64 run = stepId(project, QStringLiteral("Run"));
    QVERIFY(run >= 0);
    auto module = buildProject(project);
    QVERIFY(module);
    Runtime runtime(module);
    Breakpoint b;
    b.at = {QStringLiteral("Main"), 0, run, {}};
    runtime.setBreakpoints({b});
    QStringList halts;
    for (int cycle = 1; cycle <= 8; ++cycle) {
        if (cycle == 2)
            runtime.write(QStringLiteral("Main.go"), QStringLiteral("TRUE"));
        if (cycle == 5)
            runtime.write(QStringLiteral("Main.go"), QStringLiteral("FALSE"));
        if (cycle == 7)
            runtime.write(QStringLiteral("Main.go"), QStringLiteral("TRUE"));
        if (!runtime.runCycle()) {
            QVERIFY(runtime.isHalted());
            QCOMPARE(runtime.halt()->at.localId, run);
            halts << QStringLiteral("%1:%2").arg(runtime.halt()->cycle).arg(*runtime.read(QStringLiteral("Main.n")));
            QVERIFY(runtime.resume(ResumeKind::Continue));
        }
        QCOMPARE(runtime.cycle(), cycle);
    }
    // go before cycle 2: the transition fires in cycle 2, Run is active from cycle 3 (its action
    // has not run yet when the program halts); Init again in cycle 6 (where Count runs a last
    // time), Run from cycle 8.
    QCOMPARE(halts, (QStringList{QStringLiteral("3:0"), QStringLiteral("8:4")})); // n: cycles 3-5 and the last run in 6
}

void TestDebugger::sfcTransitionHaltsWhenItFires()
{
    const model::Project project = chartProject();
    const qint64 back = transitionAfter(project, stepId(project, QStringLiteral("Run")));
    QVERIFY(back >= 0);
    auto module = buildProject(project);
    QVERIFY(module);
    Runtime runtime(module);
    Breakpoint b;
    b.at = {QStringLiteral("Main"), 0, back, {}};
    runtime.setBreakpoints({b});
    runtime.write(QStringLiteral("Main.go"), QStringLiteral("TRUE"));
    for (int cycle = 1; cycle <= 4; ++cycle)
        QVERIFY(runtime.runCycle()); // Run is active, NOT go is FALSE: nothing fires
    runtime.write(QStringLiteral("Main.go"), QStringLiteral("FALSE"));
    QVERIFY(!runtime.runCycle());
    QCOMPARE(runtime.halt()->cycle, 5);
    QCOMPARE(runtime.halt()->at.localId, back);
    QCOMPARE(runtime.hitCounts(), std::vector<int>{1});
    QVERIFY(runtime.resume(ResumeKind::Continue));
    QVERIFY(runtime.runCycle());
    QCOMPARE(runtime.hitCounts(), std::vector<int>{1});
}

// A CFC: a + 1 -> b (order 1, 2), (a + 1) * 2 -> c (order 3, 4), written in the opposite order
// in the file. Each element is a place: a breakpoint on the MUL box halts before it runs, after
// b was written; Step Over goes from element to element in execution order. The same diagram as
// FBD is one network.
void TestDebugger::cfcElementsAreOnePlaceEach()
{
    iec::testing::Diagram d;
    d.in(6, QStringLiteral("2"), 0, 100).out(7, QStringLiteral("c"), {{5, QStringLiteral("OUT")}}, 500, 100);
    d.block(5, QStringLiteral("MUL"), QString(), {{QStringLiteral("IN1"), {{2, QStringLiteral("OUT")}}}, {QStringLiteral("IN2"), {{6}}}},
            {QStringLiteral("OUT")}, 300, 100);
    d.in(1, QStringLiteral("a")).in(3, QStringLiteral("1"), 0, 40);
    d.block(2, QStringLiteral("ADD"), QString(), {{QStringLiteral("IN1"), {{1}}}, {QStringLiteral("IN2"), {{3}}}},
            {QStringLiteral("OUT")});
    d.out(4, QStringLiteral("b"), {{2, QStringLiteral("OUT")}});
    d.order(2, 1).order(4, 2).order(5, 3).order(7, 4);
    model::Project project = iec::testing::diagramProject(QStringLiteral("VAR a : INT := 5; b : INT; c : INT; END_VAR"),
                                                          model::BodyLanguage::FBD, d);
    model::Project fbd = project;
    model::Pou &main = project.types.pous.back();
    QCOMPARE(main.name, QStringLiteral("Main"));
    main.bodies.front().addData.push_back(
        {QString::fromLatin1(graphical::kCfcMarkAddDataName), QStringLiteral("discard"), QString()});
    auto module = buildProject(project);
    QVERIFY(module);
    Runtime runtime(module);
    Breakpoint mul;
    mul.at = {QStringLiteral("Main"), 0, 5, {5}};
    runtime.setBreakpoints({mul});
    QVERIFY(!runtime.runCycle());
    QCOMPARE(runtime.halt()->at.localId, 5);
    QCOMPARE(*runtime.read(QStringLiteral("Main.b")), QStringLiteral("6"));
    QCOMPARE(*runtime.read(QStringLiteral("Main.c")), QStringLiteral("0"));
    QVERIFY(!runtime.resume(ResumeKind::StepOver));
    QCOMPARE(runtime.halt()->at.localId, 7);
    QVERIFY(runtime.resume(ResumeKind::StepOver));
    QCOMPARE(*runtime.read(QStringLiteral("Main.c")), QStringLiteral("12"));
    // Stepping through a whole cycle visits the elements in execution order.
    runtime.setBreakpoints({});
    QStringList visited;
    bool done = runtime.resume(ResumeKind::StepOver); // not halted: a cycle that halts at once
    while (!done) {
        visited << QString::number(runtime.halt()->at.localId);
        done = runtime.resume(ResumeKind::StepOver);
    }
    QCOMPARE(visited.join(QLatin1Char(' ')), QStringLiteral("2 4 5 7"));
    // As FBD, the wired elements are one network: the MUL box has no place of its own.
    auto asFbd = buildProject(fbd);
    QVERIFY(asFbd);
    Runtime network(asFbd);
    QVERIFY(network.codeAt(mul.at).empty());
    QVERIFY(!runtime.codeAt(mul.at).empty());
}

QTEST_GUILESS_MAIN(TestDebugger)
#include "tst_debugger.moc"
