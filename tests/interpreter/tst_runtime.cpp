// The scan engine: runtime faults, restarts with RETAIN, tasks, forcing, names of variables.
#include "interpreter/compiler/compiler.h"
#include "interpreter/runtime/runtime.h"

#include <QTest>

using namespace iec::interp;

namespace {

std::shared_ptr<const Module> build(const QString &source, const CompileOptions &options = {})
{
    Diagnostics diagnostics;
    auto module = compileText(source, diagnostics, options);
    for (const Diagnostic &d : diagnostics.all())
        qWarning("%s", qPrintable(d.toString()));
    return module;
}

} // namespace

class TestRuntime : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void faults_data();
    void faults();
    void faultStopsOnlyTheProgram();
    void coldAndWarmRestart();
    void tasksRunByIntervalAndPriority();
    void singleTaskRunsOnRisingEdge();
    void configurationPassesProgramParameters();
    void programWithoutConfigurationRunsEveryCycle();
    void chosenProgram();
    void forcedVariablesKeepTheirValue();
    void symbolNames_data();
    void symbolNames();
    void writeRejectsBadLiterals();
    void writeRefusesValuesOutOfRange_data();
    void writeRefusesValuesOutOfRange();
};

void TestRuntime::faults_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<int>("cycles");
    QTest::addColumn<QString>("fault");
    QTest::newRow("division by zero") << QStringLiteral("PROGRAM Main\nVAR a : INT := 10; b : INT; n : INT; END_VAR\nn := n + 1;\nIF n = 3 THEN a := a / b; END_IF;\nEND_PROGRAM")
                                      << 5 << QStringLiteral("Main:4: Integer division by zero. (cycle 3)");
    QTest::newRow("modulo by zero") << QStringLiteral("PROGRAM Main\nVAR a : DINT := 10; b : DINT; END_VAR\na := a MOD b;\nEND_PROGRAM")
                                    << 1 << QStringLiteral("Main:3: Integer division by zero. (cycle 1)");
    QTest::newRow("index out of range") << QStringLiteral("PROGRAM Main\nVAR a : ARRAY[1..5] OF INT; i : INT; END_VAR\ni := i + 1;\na[i] := i;\nEND_PROGRAM")
                                        << 10 << QStringLiteral("Main:4: Array index out of range. (cycle 6)");
    QTest::newRow("index below range in a function")
        << QStringLiteral("FUNCTION Get : INT\nVAR_INPUT k : INT; END_VAR\nVAR t : ARRAY[0..3] OF INT; END_VAR\nGet := t[k];\nEND_FUNCTION\n"
                          "PROGRAM Main\nVAR x : INT; END_VAR\nx := Get(-1);\nEND_PROGRAM")
        << 1 << QStringLiteral("Get:4: Array index out of range. (cycle 1)");
    QTest::newRow("string overflow") << QStringLiteral("PROGRAM Main\nVAR s : STRING[4]; END_VAR\ns := CONCAT(s, 'ab');\nEND_PROGRAM")
                                     << 5 << QStringLiteral("Main:3: The text does not fit into the string variable. (cycle 3)");
    QTest::newRow("endless loop") << QStringLiteral("PROGRAM Main\nVAR i : INT; END_VAR\nWHILE TRUE DO\n  i := i + 1;\nEND_WHILE;\nEND_PROGRAM")
                                  << 1 << QStringLiteral("Main:3: The program ran too long in one cycle; is there an endless loop? (cycle 1)");
    QTest::newRow("endless loop with a counted test")
        << QStringLiteral("PROGRAM Main\nVAR i : INT; END_VAR\nWHILE i >= 0 DO\n  i := i + 0;\nEND_WHILE;\nEND_PROGRAM")
        << 1 << QStringLiteral("Main:3: The program ran too long in one cycle; is there an endless loop? (cycle 1)");
    QTest::newRow("index out of range from a computed index")
        << QStringLiteral("PROGRAM Main\nVAR a : ARRAY[0..3] OF DINT; i : DINT; x : DINT; END_VAR\ni := i + 1;\nx := a[i * 2 + 1];\nEND_PROGRAM")
        << 5 << QStringLiteral("Main:4: Array index out of range. (cycle 2)");
    QTest::newRow("subrange") << QStringLiteral("TYPE Percent : INT (0..100); END_TYPE\nPROGRAM Main\nVAR p : Percent; END_VAR\np := p + 40;\nEND_PROGRAM")
                              << 5 << QStringLiteral("Main:4: A value outside the subrange of its type was assigned. (cycle 3)");
    QTest::newRow("subrange below") << QStringLiteral("TYPE Small : DINT (-2..2); END_TYPE\nPROGRAM Main\nVAR s : Small; a : ARRAY[0..3] OF Small; k : DINT; END_VAR\nk := k - 1;\na[1] := k;\nEND_PROGRAM")
                                    << 5 << QStringLiteral("Main:5: A value outside the subrange of its type was assigned. (cycle 3)");
    QTest::newRow("fault in an action") << QStringLiteral("PROGRAM Main\nVAR a : INT; END_VAR\nDivide();\nACTION Divide:\n\na := 1 / a;\nEND_ACTION\nEND_PROGRAM")
                                        << 1 << QStringLiteral("Main.Divide:6: Integer division by zero. (cycle 1)");
    QTest::newRow("endless IL loop") << QStringLiteral("PROGRAM Main\nVAR i : INT; END_VAR\nL: LD i\nADD 1\nST i\nJMP L\nEND_PROGRAM")
                                     << 1 << QStringLiteral("Main:6: The program ran too long in one cycle; is there an endless loop? (cycle 1)");
}

void TestRuntime::faults()
{
    QFETCH(QString, source);
    QFETCH(int, cycles);
    QFETCH(QString, fault);
    const auto module = build(source);
    QVERIFY(module);
    Runtime runtime(module);
    runtime.vm().budgetPerRun = 100'000;
    runtime.runCycles(cycles);
    QVERIFY(runtime.fault().has_value());
    QCOMPARE(runtime.fault()->toString(), fault);
}

void TestRuntime::faultStopsOnlyTheProgram()
{
    const auto module = build(QStringLiteral("PROGRAM Main\nVAR a : INT; b : INT; n : INT; END_VAR\nn := n + 1;\na := a / b;\nEND_PROGRAM"));
    Runtime runtime(module);
    QVERIFY(!runtime.runCycle());
    QVERIFY(!runtime.runCycle()); // stays stopped
    QCOMPARE(runtime.read(QStringLiteral("Main.n")).value(), QStringLiteral("1"));
    runtime.coldRestart(); // and can start again
    QVERIFY(!runtime.fault());
    QCOMPARE(runtime.read(QStringLiteral("Main.n")).value(), QStringLiteral("0"));
}

void TestRuntime::coldAndWarmRestart()
{
    const auto module = build(QStringLiteral(
        "VAR_GLOBAL RETAIN g : INT; END_VAR\n"
        "FUNCTION_BLOCK Keeper VAR RETAIN kept : INT; END_VAR VAR lost : INT; END_VAR VAR_OUTPUT sum : INT; END_VAR\n"
        "kept := kept + 1; lost := lost + 1; sum := kept * 100 + lost; END_FUNCTION_BLOCK\n"
        "PROGRAM Main\nVAR RETAIN r : INT; END_VAR VAR n : INT; k : Keeper; END_VAR\nr := r + 1; n := n + 1; g := g + 2; k();\nEND_PROGRAM"));
    Runtime runtime(module);
    runtime.runCycles(3);
    QCOMPARE(runtime.read(QStringLiteral("Main.r")).value(), QStringLiteral("3"));
    QCOMPARE(runtime.read(QStringLiteral("Main.k.sum")).value(), QStringLiteral("303"));
    runtime.warmRestart();
    QCOMPARE(runtime.read(QStringLiteral("Main.r")).value(), QStringLiteral("3"));
    QCOMPARE(runtime.read(QStringLiteral("Main.n")).value(), QStringLiteral("0"));
    QCOMPARE(runtime.read(QStringLiteral("g")).value(), QStringLiteral("6"));
    runtime.runCycle();
    QCOMPARE(runtime.read(QStringLiteral("Main.k.sum")).value(), QStringLiteral("401"));
    runtime.coldRestart();
    QCOMPARE(runtime.read(QStringLiteral("Main.r")).value(), QStringLiteral("0"));
    QCOMPARE(runtime.read(QStringLiteral("g")).value(), QStringLiteral("0"));
    QCOMPARE(runtime.timeNs(), qint64{0});
}

void TestRuntime::tasksRunByIntervalAndPriority()
{
    const auto module = build(QStringLiteral(
        "VAR_GLOBAL trace : DINT; END_VAR\n"
        "PROGRAM Fast VAR n : INT; END_VAR n := n + 1; trace := trace * 10 + 1; END_PROGRAM\n"
        "PROGRAM Slow VAR n : INT; END_VAR n := n + 1; trace := trace * 10 + 2; END_PROGRAM\n"
        "CONFIGURATION Plant\nRESOURCE Cpu ON PLC\n"
        "TASK T30(INTERVAL := T#30ms, PRIORITY := 1);\nTASK T10(INTERVAL := T#10ms, PRIORITY := 2);\n"
        "PROGRAM S WITH T30 : Slow;\nPROGRAM F WITH T10 : Fast;\nEND_RESOURCE\nEND_CONFIGURATION\n"));
    QVERIFY(module);
    Runtime runtime(module, 10'000'000);
    runtime.runCycles(4);
    QCOMPARE(runtime.read(QStringLiteral("F.n")).value(), QStringLiteral("4"));
    QCOMPARE(runtime.read(QStringLiteral("S.n")).value(), QStringLiteral("2")); // at 0 ms and 30 ms
    // Cycle 1: Slow (priority 1) before Fast; cycles 2, 3: Fast; cycle 4: Slow then Fast.
    QCOMPARE(runtime.read(QStringLiteral("trace")).value(), QStringLiteral("211121"));
}

void TestRuntime::singleTaskRunsOnRisingEdge()
{
    const auto module = build(QStringLiteral(
        "VAR_GLOBAL go : BOOL; count : INT; END_VAR\n"
        "PROGRAM Once count := count + 1; END_PROGRAM\n"
        "CONFIGURATION C\nTASK Event(SINGLE := go, PRIORITY := 1);\nPROGRAM P WITH Event : Once;\nEND_CONFIGURATION\n"));
    QVERIFY(module);
    Runtime runtime(module);
    runtime.runCycles(2);
    QCOMPARE(runtime.read(QStringLiteral("count")).value(), QStringLiteral("0"));
    QVERIFY(!runtime.write(QStringLiteral("go"), QStringLiteral("TRUE")));
    runtime.runCycles(3);
    QCOMPARE(runtime.read(QStringLiteral("count")).value(), QStringLiteral("1"));
    QVERIFY(!runtime.write(QStringLiteral("go"), QStringLiteral("FALSE")));
    runtime.runCycle();
    QVERIFY(!runtime.write(QStringLiteral("go"), QStringLiteral("TRUE")));
    runtime.runCycle();
    QCOMPARE(runtime.read(QStringLiteral("count")).value(), QStringLiteral("2"));
}

void TestRuntime::configurationPassesProgramParameters()
{
    const auto module = build(QStringLiteral(
        "VAR_GLOBAL limit : INT := 3; reached : BOOL; END_VAR\n"
        "PROGRAM Counter VAR_INPUT max : INT; END_VAR VAR_OUTPUT done : BOOL; END_VAR VAR n : INT; END_VAR\n"
        "n := n + 1; done := n >= max;\nEND_PROGRAM\n"
        "CONFIGURATION C\nTASK Main(INTERVAL := T#10ms, PRIORITY := 1);\nPROGRAM P WITH Main : Counter(max := limit, done => reached);\nEND_CONFIGURATION\n"));
    QVERIFY(module);
    Runtime runtime(module);
    runtime.runCycles(2);
    QCOMPARE(runtime.read(QStringLiteral("reached")).value(), QStringLiteral("FALSE"));
    runtime.runCycle();
    QCOMPARE(runtime.read(QStringLiteral("reached")).value(), QStringLiteral("TRUE"));
    QCOMPARE(runtime.read(QStringLiteral("P.max")).value(), QStringLiteral("3"));
}

void TestRuntime::programWithoutConfigurationRunsEveryCycle()
{
    const auto module = build(QStringLiteral("PROGRAM Main VAR n : INT; t : TIME; END_VAR n := n + 1; END_PROGRAM"));
    Runtime runtime(module, 5'000'000);
    runtime.runCycles(7);
    QCOMPARE(runtime.read(QStringLiteral("Main.n")).value(), QStringLiteral("7"));
    QCOMPARE(runtime.cycle(), 7);
    QCOMPARE(runtime.timeNs(), qint64{35'000'000});
}

void TestRuntime::chosenProgram()
{
    const QString source = QStringLiteral("PROGRAM A VAR n : INT; END_VAR n := 1; END_PROGRAM PROGRAM B VAR n : INT; END_VAR n := 2; END_PROGRAM");
    CompileOptions options;
    options.program = QStringLiteral("B");
    Runtime runtime(build(source, options));
    runtime.runCycle();
    QCOMPARE(runtime.read(QStringLiteral("B.n")).value(), QStringLiteral("2"));
    // A exists (other POUs may call it, as in CODESYS) but no task runs it.
    QCOMPARE(runtime.read(QStringLiteral("A.n")).value(), QStringLiteral("0"));
    Runtime first(build(source));
    first.runCycle();
    QCOMPARE(first.read(QStringLiteral("A.n")).value(), QStringLiteral("1"));
}

void TestRuntime::forcedVariablesKeepTheirValue()
{
    const auto module = build(QStringLiteral("PROGRAM Main VAR x : INT; y : INT; q AT %QX0.0 : BOOL; END_VAR x := x + 1; y := x; q := TRUE; END_PROGRAM"));
    Runtime runtime(module);
    QVERIFY(!runtime.force(QStringLiteral("Main.x"), QStringLiteral("10")));
    QVERIFY(!runtime.force(QStringLiteral("%QX0.0"), QStringLiteral("FALSE")));
    runtime.runCycles(3);
    QCOMPARE(runtime.read(QStringLiteral("Main.x")).value(), QStringLiteral("10"));
    QCOMPARE(runtime.read(QStringLiteral("Main.y")).value(), QStringLiteral("11"));
    QCOMPARE(runtime.read(QStringLiteral("%QX0.0")).value(), QStringLiteral("FALSE"));
    runtime.unforce(QStringLiteral("Main.x"));
    runtime.runCycle();
    QCOMPARE(runtime.read(QStringLiteral("Main.x")).value(), QStringLiteral("11"));
}

void TestRuntime::symbolNames_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("value");
    QTest::newRow("elementary") << QStringLiteral("Main.i") << QStringLiteral("-3");
    QTest::newRow("case insensitive") << QStringLiteral("main.I") << QStringLiteral("-3");
    QTest::newRow("fb member") << QStringLiteral("Main.Timer1.ET") << QStringLiteral("T#20ms");
    QTest::newRow("array element") << QStringLiteral("Main.a[2]") << QStringLiteral("20");
    QTest::newRow("two dimensions") << QStringLiteral("Main.m[1, 0]") << QStringLiteral("7");
    QTest::newRow("whole array") << QStringLiteral("Main.a") << QStringLiteral("[10, 20, 30]");
    QTest::newRow("struct") << QStringLiteral("Main.p") << QStringLiteral("(x := 1, y := 2)");
    QTest::newRow("bit of a word") << QStringLiteral("Main.w.9") << QStringLiteral("TRUE");
    QTest::newRow("string") << QStringLiteral("Main.s") << QStringLiteral("'it$'s'");
    QTest::newRow("real") << QStringLiteral("Main.r") << QStringLiteral("1.5");
    QTest::newRow("date and time") << QStringLiteral("Main.stamp") << QStringLiteral("DT#2024-05-06-07:08:09");
    QTest::newRow("enumeration") << QStringLiteral("Main.c") << QStringLiteral("Color#Blue");
    QTest::newRow("output image bit") << QStringLiteral("%QX0.1") << QStringLiteral("TRUE");
    QTest::newRow("output image word") << QStringLiteral("%QW1") << QStringLiteral("513");
    QTest::newRow("global") << QStringLiteral("Limit") << QStringLiteral("100");
}

void TestRuntime::symbolNames()
{
    QFETCH(QString, name);
    QFETCH(QString, value);
    const auto module = build(QStringLiteral(
        "TYPE Pt : STRUCT x : INT; y : INT; END_STRUCT; Color : (Red, Green, Blue); END_TYPE\n"
        "VAR_GLOBAL Limit : INT := 100; END_VAR\n"
        "PROGRAM Main VAR i : INT := -3; Timer1 : TON; a : ARRAY[1..3] OF INT := [10, 20, 30]; m : ARRAY[0..1, 0..1] OF INT := [1, 2, 7, 8];\n"
        "p : Pt := (x := 1, y := 2); w : WORD := 16#0200; s : STRING := 'it''s'; r : REAL := 1.5; stamp : DT := DT#2024-05-06-07:08:09;\n"
        "c : Color := Blue; o AT %QX0.1 : BOOL; ow AT %QW1 : WORD; END_VAR\n"
        "Timer1(IN := TRUE, PT := T#1s); o := TRUE; ow := 513;\nEND_PROGRAM").replace(QStringLiteral("'it''s'"), QStringLiteral("'it$'s'")));
    QVERIFY(module);
    Runtime runtime(module);
    runtime.runCycles(3);
    QCOMPARE(runtime.read(name).value_or(QStringLiteral("<none>")), value);
}

void TestRuntime::writeRejectsBadLiterals()
{
    Runtime runtime(build(QStringLiteral("PROGRAM Main VAR i : INT; t : TIME; s : STRING[3]; END_VAR END_PROGRAM")));
    QCOMPARE(runtime.write(QStringLiteral("Main.i"), QStringLiteral("abc")).value_or(QString()), QStringLiteral("'abc' is not a valid INT."));
    QCOMPARE(runtime.write(QStringLiteral("Main.t"), QStringLiteral("T#5x")).value_or(QString()), QStringLiteral("'T#5x' is not a valid TIME."));
    QCOMPARE(runtime.write(QStringLiteral("Main.s"), QStringLiteral("'abcd'")).value_or(QString()), QStringLiteral("The text is longer than the 3 characters of the string."));
    QCOMPARE(runtime.write(QStringLiteral("Main.nope"), QStringLiteral("1")).value_or(QString()), QStringLiteral("There is no variable called Main.nope."));
    QVERIFY(!runtime.write(QStringLiteral("Main.t"), QStringLiteral("T#1h2m")));
    QCOMPARE(runtime.read(QStringLiteral("Main.t")).value(), QStringLiteral("T#1h2m"));
}

void TestRuntime::writeRefusesValuesOutOfRange_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("literal");
    QTest::addColumn<QString>("problem"); // empty: accepted
    QTest::addColumn<QString>("value");   // read back after an accepted write
    QTest::newRow("INT too big") << "i" << "100000" << "100000 is out of the range of INT (-32768..32767)." << "0";
    QTest::newRow("INT max") << "i" << "32767" << "" << "32767";
    QTest::newRow("INT min") << "i" << "-32768" << "" << "-32768";
    QTest::newRow("INT below min") << "i" << "-32769" << "-32769 is out of the range of INT (-32768..32767)." << "0";
    QTest::newRow("INT bit pattern") << "i" << "16#FFFF" << "" << "-1";
    QTest::newRow("INT pattern too wide") << "i" << "16#1_0000" << "16#1_0000 does not fit the 16 bits of INT." << "0";
    QTest::newRow("SINT") << "si" << "128" << "128 is out of the range of SINT (-128..127)." << "0";
    QTest::newRow("USINT negative") << "us" << "-1" << "-1 is out of the range of USINT (0..255)." << "0";
    QTest::newRow("USINT max") << "us" << "255" << "" << "255";
    QTest::newRow("UDINT too big") << "ud" << "4294967296" << "4294967296 is out of the range of UDINT (0..4294967295)." << "0";
    QTest::newRow("LINT min") << "li" << "-9223372036854775808" << "" << "-9223372036854775808";
    QTest::newRow("LINT above max") << "li" << "9223372036854775808"
                                    << "9223372036854775808 is out of the range of LINT (-9223372036854775808..9223372036854775807)." << "0";
    QTest::newRow("ULINT max") << "ul" << "18446744073709551615" << "" << "18446744073709551615";
    QTest::newRow("BYTE") << "b" << "256" << "256 is out of the range of BYTE (0..255)." << "0";
    QTest::newRow("typed literal") << "i" << "INT#40000" << "INT#40000 is out of the range of INT (-32768..32767)." << "0";
    QTest::newRow("subrange") << "p" << "101" << "101 is out of the range of Pct (0..100)." << "0";
    QTest::newRow("subrange below") << "p" << "-1" << "-1 is out of the range of Pct (0..100)." << "0";
    QTest::newRow("REAL too big") << "r" << "1e40" << "1e40 is out of the range of REAL (about ±3.4E38)." << "0.0";
    QTest::newRow("LREAL holds it") << "lr" << "1e40" << "" << "1e+40";
    QTest::newRow("subrange inside") << "p" << "100" << "" << "100";
}

// The online watch writes what the user typed: a value the variable cannot hold is refused, not wrapped.
void TestRuntime::writeRefusesValuesOutOfRange()
{
    QFETCH(QString, name);
    QFETCH(QString, literal);
    QFETCH(QString, problem);
    QFETCH(QString, value);
    Runtime runtime(build(QStringLiteral(
        "TYPE Pct : INT(0..100); END_TYPE\n"
        "PROGRAM Main VAR i : INT; si : SINT; us : USINT; ud : UDINT; li : LINT; ul : ULINT; b : BYTE; p : Pct; r : REAL; lr : LREAL; END_VAR END_PROGRAM")));
    const QString variable = QStringLiteral("Main.") + name;
    QCOMPARE(runtime.write(variable, literal).value_or(QString()), problem);
    QCOMPARE(runtime.read(variable).value_or(QStringLiteral("<none>")), value);
}

QTEST_GUILESS_MAIN(TestRuntime)
#include "tst_runtime.moc"
