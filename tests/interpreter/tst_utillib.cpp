// The CoDeSys 2.3 Util blocks and Beremiz's RTC and LOGGER (interpreter/compiler/utillib.cpp,
// docs/stdlib.md), scan by scan. Values marked "manual" are the examples of the CoDeSys 2.3
// manual (appendix D, "The library UTIL.lib"); the others follow the definitions in stdlib.md.
#include "tracerunner.h"

#include <QTest>

using namespace iec::interp;
using namespace iec::interp::testing;
using namespace iec::interp::testing::table;

class TestUtilLib : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void functions_data();
    void functions() { check(); }
    void blocks_data();
    void blocks() { check(); }
    void controllers_data();
    void controllers() { check(); }
    void realTimeClock();
    void logger();
    void vendorLibraryBlocks_data();
    void vendorLibraryBlocks();
    void svgHmiVariablesRunAsPlainVariables();
    void unusedLibraryCostsNothing();
};

void TestUtilLib::functions_data()
{
    columns();
    // Manual: EXTRACT(81, 4) is TRUE (81 = 2#1010001), EXTRACT(33, 0) TRUE; PUTBIT(38, 4, TRUE)
    // = 54 and PUTBIT(38, 1, FALSE) = 36.
    expr("extract and putbit", "a : BOOL; b : BOOL; c : BOOL; d : DWORD; e : DWORD;",
         "a := EXTRACT(X := 81, N := 4); b := EXTRACT(X := 33, N := 0); c := EXTRACT(81, 1); d := PUTBIT(38, 4, TRUE); e := PUTBIT(38, 1, FALSE);",
         "a=TRUE; b=TRUE; c=FALSE; d=54; e=36");
    expr("pack", "b : BYTE;", "b := PACK(B0 := TRUE, B2 := TRUE, B7 := TRUE);", "b=133");
    // Manual: BCD_TO_INT(73) = 49, BCD_TO_INT(151) = 97, BCD_TO_INT(15) = -1 (not BCD);
    // INT_TO_BCD(49) = 73, INT_TO_BCD(100) = 255 (cannot be converted).
    expr("bcd", "a : INT; b : INT; c : INT; d : BYTE; e : BYTE; f : BYTE;",
         "a := BCD_TO_INT(73); b := BCD_TO_INT(151); c := BCD_TO_INT(15); d := INT_TO_BCD(49); e := INT_TO_BCD(100); f := INT_TO_BCD(-1);",
         "a=49; b=97; c=-1; d=73; e=255; f=255");
}

void TestUtilLib::blocks_data()
{
    columns();
    row("unpack", "VAR u : UNPACK; END_VAR\nu(B := 16#A5);", {"=> u.B0=TRUE; u.B1=FALSE; u.B2=TRUE; u.B5=TRUE; u.B6=FALSE; u.B7=TRUE"});
    // OUT is TRUE below LOW and FALSE above HIGH, and keeps its value between them.
    row("hysteresis", "VAR h : HYSTERESIS; x : INT; END_VAR\nh(IN := x, HIGH := 20, LOW := 10);",
        {"x=5 => h.OUT=TRUE", "x=15 => h.OUT=TRUE", "x=25 => h.OUT=FALSE", "x=15 => h.OUT=FALSE", "x=9 => h.OUT=TRUE"});
    row("limitalarm", "VAR l : LIMITALARM; x : INT; END_VAR\nl(IN := x, HIGH := 20, LOW := 10);",
        {"x=25 => l.O=TRUE; l.U=FALSE; l.IL=FALSE", "x=15 => l.O=FALSE; l.U=FALSE; l.IL=TRUE", "x=5 => l.O=FALSE; l.U=TRUE; l.IL=FALSE"});
    row("lin_trafo", "VAR t : LIN_TRAFO; END_VAR\nt(IN := 5.0, IN_MIN := 0.0, IN_MAX := 10.0, OUT_MIN := 0.0, OUT_MAX := 100.0);",
        {"=> t.OUT=50.0; t.ERROR=FALSE"});
    row("lin_trafo with an empty range", "VAR t : LIN_TRAFO; END_VAR\nt(IN := 5.0, IN_MIN := 3.0, IN_MAX := 3.0, OUT_MIN := 1.0, OUT_MAX := 100.0);",
        {"=> t.ERROR=TRUE"});
    row("statistics_int", "VAR s : STATISTICS_INT; x : INT; r : BOOL; END_VAR\ns(IN := x, RESET := r);",
        {"x=5 => s.MN=5; s.MX=5; s.AVG=5", "x=10 => s.MN=5; s.MX=10; s.AVG=7", "x=3 => s.MN=3; s.MX=10; s.AVG=6",
         "r=TRUE => s.MN=32767; s.MX=-32768; s.AVG=0"});
    row("statistics_real", "VAR s : STATISTICS_REAL; x : REAL; END_VAR\ns(IN := x);", {"x=1.5 => s.AVG=1.5", "x=-0.5 => s.MN=-0.5; s.MX=1.5; s.AVG=0.5"});
    // 2, 4, 4, 4, 5, 5, 7, 9: mean 5, the squared distances sum to 32, 32 / 8 = 4.
    row("variance", "VAR v : VARIANCE; x : REAL; END_VAR\nv(IN := x);",
        {"x=2.0", "x=4.0", "x=4.0", "x=4.0", "x=5.0", "x=5.0", "x=7.0", "x=9.0 => v.OUT=4.0"});
    // 2.0 for 0.5 s, three times: 3.0.
    row("integral", "VAR i : INTEGRAL; END_VAR\ni(IN := 2.0, TM := 500);", {"=> i.OUT=1.0", "=> i.OUT=2.0", "=> i.OUT=3.0; i.OVERFLOW=FALSE"});
    // A ramp of 1 per call every 100 ms: 10 per second, once four values are known.
    row("derivative", "VAR d : DERIVATIVE; x : REAL; END_VAR\nd(IN := x, TM := 100); x := x + 1.0;",
        {"=> d.OUT=0.0", "", "", "=> d.OUT=10.0", "=> d.OUT=10.0"});
    // At most 3 up and 5 down per call (TIMEBASE T#0s).
    row("ramp_int per call", "VAR r : RAMP_INT; x : INT; END_VAR\nr(IN := x, ASCEND := 3, DESCEND := 5);",
        {"x=0 => r.OUT=0", "x=10 => r.OUT=3", "=> r.OUT=6", "=> r.OUT=9", "=> r.OUT=10", "x=0 => r.OUT=5", "=> r.OUT=0"});
    // 100 per second at a 10 ms cycle: 1 per cycle.
    row("ramp_real per time", "VAR r : RAMP_REAL; x : REAL; END_VAR\nr(IN := x, ASCEND := 100.0, DESCEND := 100.0, TIMEBASE := T#1s);",
        {"x=0.0 => r.OUT=0.0", "x=5.0 => r.OUT=1.0", "=> r.OUT=2.0"});
    // TRUE for 30 ms, FALSE for 20 ms, at a 10 ms cycle.
    row("blink", "VAR b : BLINK; on : BOOL := TRUE; END_VAR\nb(ENABLE := on, TIMELOW := T#20ms, TIMEHIGH := T#30ms);",
        {"=> b.OUT=TRUE", "=> b.OUT=TRUE", "=> b.OUT=TRUE", "=> b.OUT=FALSE", "=> b.OUT=FALSE", "=> b.OUT=TRUE", "on=FALSE => b.OUT=TRUE"});
    row("gen rectangle over calls", "VAR g : GEN; END_VAR\ng(MODE := RECTANGLE, BASE := FALSE, CYCLES := 4, AMPLITUDE := 100);",
        {"=> g.OUT=100", "=> g.OUT=100", "=> g.OUT=-100", "=> g.OUT=-100", "=> g.OUT=100"});
    row("gen sawtooth over time", "VAR g : GEN; END_VAR\ng(MODE := SAWTOOTH_RISE, BASE := TRUE, PERIOD := T#40ms, AMPLITUDE := 100);",
        {"=> g.OUT=-100", "=> g.OUT=-50", "=> g.OUT=0", "=> g.OUT=50", "=> g.OUT=-100"});
    row("charcurve", "VAR c : CHARCURVE; p : ARRAY[0..10] OF POINT := [(X := 0, Y := 0), (X := 10, Y := 100), (X := 20, Y := 150)]; x : INT; n : BYTE := 3; END_VAR\n"
                     "c(IN := x, N := n, P := p);",
        {"x=5 => c.OUT=50; c.ERR=0", "x=15 => c.OUT=125; c.ERR=0", "x=25 => c.OUT=150; c.ERR=2", "n=1 => c.ERR=4"});
}

void TestUtilLib::controllers_data()
{
    columns();
    // P only: Y = KP * (SET_POINT - ACTUAL) + Y_OFFSET.
    row("pid as p", "VAR c : PID; END_VAR\nc(ACTUAL := 4.0, SET_POINT := 10.0, KP := 2.0, Y_OFFSET := 1.0);", {"=> c.Y=13.0; c.LIMITS_ACTIVE=FALSE"});
    row("pid limited", "VAR c : PID; END_VAR\nc(ACTUAL := 4.0, SET_POINT := 10.0, KP := 2.0, Y_MIN := 0.0, Y_MAX := 10.0);", {"=> c.Y=10.0; c.LIMITS_ACTIVE=TRUE"});
    // PI with TN 1 s: the error 1 adds 0.01 per 10 ms cycle (the first call starts the clock).
    row("pid integral", "VAR c : PID; END_VAR\nc(ACTUAL := 0.0, SET_POINT := 1.0, KP := 1.0, TN := 1.0);", {"=> c.Y=1.0", "=> c.Y=1.01", "=> c.Y=1.02"});
    row("pid_fixcycle", "VAR c : PID_FIXCYCLE; END_VAR\nc(ACTUAL := 0.0, SET_POINT := 1.0, KP := 1.0, TN := 1.0, CYCLE := 0.1);", {"=> c.Y=1.0", "=> c.Y=1.1"});
    row("pid manual", "VAR c : PID; END_VAR\nc(ACTUAL := 0.0, SET_POINT := 1.0, KP := 1.0, MANUAL := TRUE, Y_MANUAL := 42.0);", {"=> c.Y=42.0"});
    // PD: the error falls by 1 per 10 ms (-100 per second), times TV 0.5 s: -50, plus the error.
    row("pd", "VAR c : PD; x : REAL; END_VAR\nc(ACTUAL := x, SET_POINT := 10.0, KP := 1.0, TV := 0.5); x := x + 1.0;", {"=> c.Y=10.0", "=> c.Y=-41.0", "=> c.Y=-42.0"});
}

void TestUtilLib::realTimeClock()
{
    CompileOptions options;
    options.cycleNs = 1'000'000'000; // one second per cycle
    // The virtual clock starts at 1970-01-01; with IN it counts on from PDT.
    QCOMPARE(runTrace(QStringLiteral("VAR r : RTC; go : BOOL; END_VAR\nr(IN := go, PDT := DT#2024-05-01-12:00:00);"),
                      {"=> r.CDT=DT#1970-01-01-00:00:00; r.Q=FALSE", "=> r.CDT=DT#1970-01-01-00:00:01", "go=TRUE => r.CDT=DT#2024-05-01-12:00:00; r.Q=TRUE",
                       "=> r.CDT=DT#2024-05-01-12:00:01"},
                      options),
             QString());
}

void TestUtilLib::logger()
{
    Diagnostics diagnostics;
    const auto module = compileText(QStringLiteral("PROGRAM Main\nVAR l : LOGGER; n : INT; END_VAR\nn := n + 1;\n"
                                                   "l(TRIG := n MOD 2 = 0, MSG := CONCAT('tick ', INT_TO_STRING(n)), LEVEL := WARNING);\nEND_PROGRAM\n"),
                                    diagnostics);
    QVERIFY2(module, qPrintable(errorsOf(diagnostics)));
    Runtime runtime(module);
    QVERIFY(runtime.runCycles(5));
    QStringList lines;
    for (const Runtime::LogEntry &e : runtime.takeLog())
        lines << e.toString();
    // A message on each rising edge of TRIG only.
    QCOMPARE(lines, QStringList({"WARNING: tick 2 (cycle 2)", "WARNING: tick 4 (cycle 4)"}));
    QVERIFY(runtime.takeLog().empty());
}

void TestUtilLib::vendorLibraryBlocks_data()
{
    QTest::addColumn<QString>("first");  // the block Client uses first
    QTest::addColumn<QString>("second"); // one more block of the same library
    QTest::addColumn<QString>("library");
    const auto row = [](const char *name, const char *first, const char *second, const char *library) {
        QTest::newRow(name) << QString::fromLatin1(first) << QString::fromLatin1(second) << QString::fromLatin1(library);
    };
    row("OpenPLC TCP", "TCP_SEND", "TCP_CONNECT", "the OpenPLC TCP socket library");
    row("OpenPLC UDP", "UDP_SEND", "UDP_RECEIVE", "the OpenPLC UDP socket library");
    row("MQTT", "MQTT_PUBLISH", "MQTT_CONNECT", "an MQTT library");
    row("PLCopen motion", "MC_Power", "MC_MoveAbsolute", "CODESYS SoftMotion (PLCopen motion control)");
    row("SoftMotion", "SMC_Homing", "SMC_ReadNCFile", "CODESYS SoftMotion");
    row("Beremiz Python", "PYTHON_EVAL", "PYTHON_POLL", "Beremiz's Python blocks");
}

void TestUtilLib::vendorLibraryBlocks()
{
    QFETCH(QString, first);
    QFETCH(QString, second);
    QFETCH(QString, library);
    // One warning naming the library, at the first block only; Main runs since nothing it runs
    // needs the library.
    const QString unused = QStringLiteral("FUNCTION_BLOCK Client\nVAR a : %1; b : %2; END_VAR\na(); b();\nEND_FUNCTION_BLOCK\n"
                                          "PROGRAM Main\nVAR n : INT; END_VAR\nn := n + 1;\nEND_PROGRAM\n").arg(first, second);
    Diagnostics diagnostics;
    const auto module = compileText(unused, diagnostics);
    QVERIFY2(module, qPrintable(errorsOf(diagnostics)));
    QCOMPARE(diagnosticsText(diagnostics, false),
             QStringLiteral("Client:2:9: warning: %1 is a block of %2, which IEC Studio does not have; the POUs "
                            "that use it cannot run. (hint: the rest of the project is still checked and runs)").arg(first, library));
    Runtime runtime(module);
    QVERIFY(runtime.runCycles(3));
    QCOMPARE(runtime.read(QStringLiteral("Main.n")).value_or(QStringLiteral("?")), QStringLiteral("3"));
    // Run by a task: the project cannot run, and says why.
    Diagnostics used;
    QVERIFY(!compileText(QString(unused).replace(QStringLiteral("n := n + 1;"), QStringLiteral("n := n + 1;\nc();")).replace(QStringLiteral("n : INT;"), QStringLiteral("n : INT; c : Client;")), used));
    QCOMPARE(errorsOf(used), QStringLiteral("Main:0:0: error: Main cannot run: Client uses %1.").arg(library));
}

// Beremiz's SVGHMI types are plain variables of the type each stands for: one warning for the
// project, and the logic runs (HMI_NODE is a BOOL in Beremiz's SVGHMI library too).
void TestUtilLib::svgHmiVariablesRunAsPlainVariables()
{
    Diagnostics diagnostics;
    const auto module = compileText(QStringLiteral("PROGRAM Main\nVAR go : HMI_BOOL := TRUE; n : HMI_INT; r : HMI_REAL; s : HMI_STRING; root : HMI_NODE; END_VAR\n"
                                                   "IF go THEN n := n + 1; r := r + 0.5; END_IF\ns := CONCAT('n=', INT_TO_STRING(n)); root := n > 1;\nEND_PROGRAM\n"
                                                   "FUNCTION_BLOCK Panel\nVAR_INPUT lamp : HMI_BOOL; END_VAR\nEND_FUNCTION_BLOCK\n"),
                                    diagnostics);
    QVERIFY2(module, qPrintable(errorsOf(diagnostics)));
    QCOMPARE(diagnosticsText(diagnostics, false),
             QStringLiteral("Main:2:10: warning: HMI_BOOL is a type of Beremiz's SVGHMI, which IEC Studio does not have: its variables are read as BOOL "
                            "and no HMI is shown. (hint: watch and write them in the watch pane instead)"));
    Runtime runtime(module);
    QStringList cycles;
    for (int cycle = 0; cycle < 3; ++cycle) {
        QVERIFY(runtime.runCycles(1));
        cycles << QStringList({runtime.read(QStringLiteral("Main.n")).value_or(QStringLiteral("?")), runtime.read(QStringLiteral("Main.r")).value_or(QStringLiteral("?")),
                               runtime.read(QStringLiteral("Main.s")).value_or(QStringLiteral("?")), runtime.read(QStringLiteral("Main.root")).value_or(QStringLiteral("?"))})
                      .join(QLatin1Char(' '));
    }
    QCOMPARE(cycles, QStringList({"1 0.5 'n=1' FALSE", "2 1.0 'n=2' TRUE", "3 1.5 'n=3' TRUE"}));

    // A project that declares the type itself uses its own declaration, without the warning.
    Diagnostics own;
    const auto ownModule = compileText(QStringLiteral("TYPE HMI_BOOL : INT; END_TYPE\nPROGRAM Main\nVAR x : HMI_BOOL; END_VAR\nx := x + 2;\nEND_PROGRAM\n"), own);
    QVERIFY2(ownModule, qPrintable(errorsOf(own)));
    QCOMPARE(diagnosticsText(own, false), QString());
    Runtime ownRuntime(ownModule);
    QVERIFY(ownRuntime.runCycles(2));
    QCOMPARE(ownRuntime.read(QStringLiteral("Main.x")).value_or(QStringLiteral("?")), QStringLiteral("4"));
}

void TestUtilLib::unusedLibraryCostsNothing()
{
    // A program that names no Util block does not get them (nor their types' names).
    Diagnostics diagnostics;
    const auto module = compileText(QStringLiteral("PROGRAM Main\nVAR x : INT; END_VAR\nx := 1;\nEND_PROGRAM\n"), diagnostics);
    QVERIFY(module);
    for (const CompiledPou &pou : module->pous)
        QVERIFY2(pou.name != QLatin1String("PID"), "the Util library was compiled without being used");
}

QTEST_GUILESS_MAIN(TestUtilLib)
#include "tst_utillib.moc"
