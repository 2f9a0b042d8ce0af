// iecstudio-cli check / run / convert, run as a separate process exactly as users run it
// (formats: docs/cli.md).
#include "clirun.h"

#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

class TestCli : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void firstStepsBlinks_data();
    void firstStepsBlinks();
    void runScriptCommand();
    void cycleTimeForms_data();
    void cycleTimeForms();
    void setAppliesAtItsCycleAndCsvTrace();
    void vcdTrace();
    void vcdEscapesArrayElements();
    void namesByInstanceOrProgram_data();
    void namesByInstanceOrProgram();
    void programOptionRunsOneProgramAlone();
    void unknownNamesAreRefused();
    void runtimeFaultIsReported();
    void compileErrorsStopRun();
    void check_data();
    void check();
    void checkNamesGraphicalPousOfTheCorpus();
    void codesysExportInWindows1252Runs();
    void codesysGraphicalBodyIsNamed();
    void infoCountsIecText();
    void processImageThroughSetAndWatch_data();
    void processImageThroughSetAndWatch();
    void loggerWritesToStderr();
    void convertRoundTrips();
    void convertedStValidatesAgainstTheSchema();
    void usageErrors_data();
    void usageErrors();
    void renderDrawsCharts_data();
    void renderDrawsCharts();
    void renderDrawsActionsAndTransitions();
    void renderDrawsLadder();
    void renderDrawsFunctionBlockDiagrams();
    void renderDrawsCodesysCfc();
    void renderRefuses_data();
    void renderRefuses();
};

namespace {

using clirun::cli;
using clirun::Result;
using clirun::writeFile;

QString example()
{
    return QStringLiteral(IEC_SOURCE_DIR "/resources/examples/first_steps.xml");
}

QString readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll())
                                          : QStringLiteral("<missing %1>").arg(path);
}

const char *const kCounter = "PROGRAM Main\n"
                             "VAR x : INT; on : BOOL; r : REAL := 0.5; t : TIME; s : STRING := 'a,b'; END_VAR\n"
                             "x := x + 1;\nr := r * 2.0;\nt := t + T#1500ms;\n"
                             "END_PROGRAM\n";

// Program Prog runs as instance Fast of configuration C.
const char *const kConfiguration
    = "PROGRAM Prog\nVAR_EXTERNAL g : INT; END_VAR\nVAR n : INT; a : ARRAY[1..2] OF INT; q AT %QX0.1 : BOOL; END_VAR\n"
      "n := n + 1; g := g + 2; a[2] := n; q := n > 2;\nEND_PROGRAM\n"
      "PROGRAM Other\nVAR_EXTERNAL g : INT; END_VAR\ng := g - 1;\nEND_PROGRAM\n"
      "CONFIGURATION C\nVAR_GLOBAL g : INT; END_VAR\nRESOURCE R ON PLC\n"
      "TASK T(INTERVAL := T#5ms, PRIORITY := 1);\nPROGRAM Fast WITH T : Prog;\n"
      "END_RESOURCE\nEND_CONFIGURATION\n";

} // namespace

void TestCli::firstStepsBlinks_data()
{
    // TON with PT = T#500ms at 10 ms: Q in its 51st call (cycle 51, ET = 500 ms), which toggles
    // Blink on and counts; cycle 52 calls it with IN = NOT Q = FALSE (reset), cycle 53 starts
    // again, so Q comes back in cycle 103 (Blink off) and 155 (Blink on, Count 2).
    QTest::addColumn<int>("cycles");
    QTest::addColumn<QString>("output");
    QTest::newRow("50") << 50 << QStringLiteral("Main.Count = 0\nMain.Blink = FALSE\n");
    QTest::newRow("51") << 51 << QStringLiteral("Main.Count = 1\nMain.Blink = TRUE\n");
    QTest::newRow("102") << 102 << QStringLiteral("Main.Count = 1\nMain.Blink = TRUE\n");
    QTest::newRow("103") << 103 << QStringLiteral("Main.Count = 1\nMain.Blink = FALSE\n");
    QTest::newRow("155") << 155 << QStringLiteral("Main.Count = 2\nMain.Blink = TRUE\n");
}

void TestCli::firstStepsBlinks()
{
    QFETCH(int, cycles);
    QFETCH(QString, output);
    const Result result = cli({QStringLiteral("run"), example(), QStringLiteral("--cycles"), QString::number(cycles),
        QStringLiteral("--watch"), QStringLiteral("Main.Count"), QStringLiteral("--watch"),
        QStringLiteral("Main.Blink")});
    QCOMPARE(result.err, QString());
    QCOMPARE(result.out, output);
    QCOMPARE(result.exitCode, 0);
}

void TestCli::runScriptCommand()
{
    // What scripts/run.sh runs without a display.
    const Result result = cli({QStringLiteral("run"), example(), QStringLiteral("--cycles"), QStringLiteral("100"),
        QStringLiteral("--cycle-time"), QStringLiteral("10ms"), QStringLiteral("--watch"), QStringLiteral("Main.Count"),
        QStringLiteral("--watch"), QStringLiteral("Main.Blink")});
    QCOMPARE(result.out, QStringLiteral("Main.Count = 1\nMain.Blink = TRUE\n"));
    QCOMPARE(result.exitCode, 0);
}

void TestCli::cycleTimeForms_data()
{
    QTest::addColumn<QString>("cycleTime");
    QTest::addColumn<QString>("output");
    // ET after 5 cycles is 4 cycle times: the first call starts the timer at ET = 0.
    QTest::newRow("10ms") << QStringLiteral("10ms") << QStringLiteral("Main.T.ET = T#40ms\n");
    QTest::newRow("T#10ms") << QStringLiteral("T#10ms") << QStringLiteral("Main.T.ET = T#40ms\n");
    QTest::newRow("TIME#10ms") << QStringLiteral("TIME#10ms") << QStringLiteral("Main.T.ET = T#40ms\n");
    QTest::newRow("PT0.01S") << QStringLiteral("PT0.01S") << QStringLiteral("Main.T.ET = T#40ms\n");
    QTest::newRow("0.25s") << QStringLiteral("0.25s") << QStringLiteral("Main.T.ET = T#1s\n");
    QTest::newRow("no option: 10 ms") << QString() << QStringLiteral("Main.T.ET = T#40ms\n");
}

void TestCli::cycleTimeForms()
{
    QFETCH(QString, cycleTime);
    QFETCH(QString, output);
    QTemporaryDir dir;
    const QString file = writeFile(dir, QStringLiteral("timer.st"),
        QStringLiteral("PROGRAM Main\nVAR T : TON; END_VAR\nT(IN := TRUE, PT := T#10s);\nEND_PROGRAM\n"));
    QStringList arguments {QStringLiteral("run"), file, QStringLiteral("--cycles"), QStringLiteral("5"),
        QStringLiteral("--watch"), QStringLiteral("Main.T.ET")};
    if (!cycleTime.isEmpty())
        arguments << QStringLiteral("--cycle-time") << cycleTime;
    const Result result = cli(arguments);
    QCOMPARE(result.err, QString());
    QCOMPARE(result.out, output);
    QCOMPARE(result.exitCode, 0);
}

void TestCli::setAppliesAtItsCycleAndCsvTrace()
{
    QTemporaryDir dir;
    const QString file = writeFile(dir, QStringLiteral("counter.st"), QLatin1String(kCounter));
    const QString csv = dir.filePath(QStringLiteral("trace.csv"));
    const Result result = cli(
        {QStringLiteral("run"), file, QStringLiteral("--cycles"), QStringLiteral("4"), QStringLiteral("--cycle-time"),
            QStringLiteral("T#2.5ms"), QStringLiteral("--set"), QStringLiteral("Main.x=100@3"), QStringLiteral("--set"),
            QStringLiteral("Main.on=TRUE@2"), QStringLiteral("--set"), QStringLiteral("Main.s='y,\"z\"'"),
            QStringLiteral("--watch"), QStringLiteral("Main.x"), QStringLiteral("--watch"), QStringLiteral("Main.on"),
            QStringLiteral("--watch"), QStringLiteral("Main.r"), QStringLiteral("--watch"), QStringLiteral("Main.t"),
            QStringLiteral("--watch"), QStringLiteral("Main.s"), QStringLiteral("--trace"), csv});
    QCOMPARE(result.err, QString());
    QCOMPARE(
        result.out, QStringLiteral("Main.x = 102\nMain.on = TRUE\nMain.r = 8.0\nMain.t = T#6s\nMain.s = 'y,\"z\"'\n"));
    QCOMPARE(result.exitCode, 0);
    QCOMPARE(readAll(csv),
        QStringLiteral("cycle,time_ms,Main.x,Main.on,Main.r,Main.t,Main.s\n"
                       "1,2.5,1,FALSE,1.0,T#1s500ms,\"'y,\"\"z\"\"'\"\n"
                       "2,5,2,TRUE,2.0,T#3s,\"'y,\"\"z\"\"'\"\n"
                       "3,7.5,101,TRUE,4.0,T#4s500ms,\"'y,\"\"z\"\"'\"\n"
                       "4,10,102,TRUE,8.0,T#6s,\"'y,\"\"z\"\"'\"\n"));
}

void TestCli::vcdTrace()
{
    QTemporaryDir dir;
    const QString file = writeFile(dir, QStringLiteral("counter.st"), QLatin1String(kCounter));
    const QString vcd = dir.filePath(QStringLiteral("trace.vcd"));
    const Result result = cli({QStringLiteral("run"), file, QStringLiteral("--cycles"), QStringLiteral("2"),
        QStringLiteral("--set"), QStringLiteral("Main.on=TRUE@2"), QStringLiteral("--watch"), QStringLiteral("Main.on"),
        QStringLiteral("--watch"), QStringLiteral("Main.x"), QStringLiteral("--watch"), QStringLiteral("Main.r"),
        QStringLiteral("--trace"), vcd});
    QCOMPARE(result.err, QString());
    QCOMPARE(result.exitCode, 0);
    QCOMPARE(readAll(vcd),
        QStringLiteral("$version iecstudio-cli run $end\n$timescale 1 us $end\n$scope module iecstudio $end\n"
                       "$var wire 1 ! Main.on $end\n$var wire 16 \" Main.x $end\n$var real 64 # Main.r $end\n"
                       "$upscope $end\n$enddefinitions $end\n#0\n$dumpvars\n0!\nb0 \"\nr0.5 #\n$end\n"
                       "#10000\nb1 \"\nr1 #\n"
                       "#20000\n1!\nb10 \"\nr2 #\n"));

    const Result refused = cli({QStringLiteral("run"), file, QStringLiteral("--watch"), QStringLiteral("Main.s"),
        QStringLiteral("--trace"), vcd});
    QCOMPARE(refused.exitCode, 2);
    QCOMPARE(refused.err,
        QStringLiteral(
            "iecstudio-cli: Main.s is a STRING, which a VCD trace cannot show; trace it to a .csv file instead.\n"));
}

void TestCli::vcdEscapesArrayElements()
{
    // Main.a[2] written plainly reads as bit 2 of a vector Main.a in GTKWave: escaped identifier.
    QTemporaryDir dir;
    const QString file = writeFile(dir, QStringLiteral("array.st"),
        QStringLiteral("PROGRAM Main\nVAR a : ARRAY[1..2] OF INT; m : ARRAY[0..1, 0..1] OF BOOL; END_VAR\n"
                       "a[2] := a[2] - 1; m[1, 0] := TRUE;\nEND_PROGRAM\n"));
    const QString vcd = dir.filePath(QStringLiteral("trace.vcd"));
    const Result result = cli({QStringLiteral("run"), file, QStringLiteral("--watch"), QStringLiteral("Main.a[2]"),
        QStringLiteral("--watch"), QStringLiteral("Main.m[1, 0]"), QStringLiteral("--trace"), vcd});
    QCOMPARE(result.err, QString());
    QCOMPARE(result.out, QStringLiteral("Main.a[2] = -1\nMain.m[1, 0] = TRUE\n"));
    QCOMPARE(readAll(vcd),
        QStringLiteral("$version iecstudio-cli run $end\n$timescale 1 us $end\n$scope module iecstudio $end\n"
                       "$var wire 16 ! \\Main.a[2] $end\n$var wire 1 \" \\Main.m[1,_0] $end\n"
                       "$upscope $end\n$enddefinitions $end\n#0\n$dumpvars\nb0 !\n0\"\n$end\n"
                       "#10000\nb1111111111111111 !\n1\"\n"));
}

void TestCli::namesByInstanceOrProgram_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("output");
    QTest::newRow("instance") << QStringLiteral("Fast.n") << QStringLiteral("Fast.n = 3\n");
    QTest::newRow("program POU, one instance") << QStringLiteral("Prog.n") << QStringLiteral("Prog.n = 3\n");
    QTest::newRow("global") << QStringLiteral("g") << QStringLiteral("g = 6\n");
    QTest::newRow("output address") << QStringLiteral("%QX0.1") << QStringLiteral("%QX0.1 = TRUE\n");
    QTest::newRow("array element") << QStringLiteral("Fast.a[2]") << QStringLiteral("Fast.a[2] = 3\n");
}

void TestCli::namesByInstanceOrProgram()
{
    QFETCH(QString, name);
    QFETCH(QString, output);
    QTemporaryDir dir;
    const QString file = writeFile(dir, QStringLiteral("config.st"), QLatin1String(kConfiguration));
    const Result result = cli({QStringLiteral("run"), file, QStringLiteral("--cycles"), QStringLiteral("3"),
        QStringLiteral("--watch"), name});
    QCOMPARE(result.err, QString());
    QCOMPARE(result.out, output);
    QCOMPARE(result.exitCode, 0);
}

void TestCli::programOptionRunsOneProgramAlone()
{
    QTemporaryDir dir;
    const QString file = writeFile(dir, QStringLiteral("config.st"), QLatin1String(kConfiguration));
    const Result result = cli({QStringLiteral("run"), file, QStringLiteral("--program"), QStringLiteral("Other"),
        QStringLiteral("--cycles"), QStringLiteral("4"), QStringLiteral("--watch"), QStringLiteral("g")});
    QCOMPARE(result.err, QString());
    QCOMPARE(result.out, QStringLiteral("g = -4\n")); // the configuration's global stays; only Other runs
    QCOMPARE(result.exitCode, 0);
    const Result missing = cli({QStringLiteral("run"), file, QStringLiteral("--program"), QStringLiteral("Nope")});
    QCOMPARE(missing.exitCode, 1);
    QCOMPARE(missing.err, file + QStringLiteral(": error: There is no PROGRAM called Nope.\n"));
}

void TestCli::unknownNamesAreRefused()
{
    const Result result = cli({QStringLiteral("run"), example(), QStringLiteral("--watch"),
        QStringLiteral("Main.Nothing"), QStringLiteral("--set"), QStringLiteral("Other.x=1")});
    QCOMPARE(result.exitCode, 2);
    QCOMPARE(result.out, QString());
    const QString prefix = QStringLiteral("iecstudio-cli: ") + example();
    QCOMPARE(result.err,
        prefix
            + QStringLiteral(
                ": there is no variable called Main.Nothing (write it as Program.Variable, Global or %QX0.1).\n")
            + prefix
            + QStringLiteral(
                ": there is no variable called Other.x (write it as Program.Variable, Global or %QX0.1).\n"));
}

void TestCli::runtimeFaultIsReported()
{
    QTemporaryDir dir;
    const QString file = writeFile(dir, QStringLiteral("fault.st"),
        QStringLiteral("PROGRAM Main\nVAR d : INT := 2; q : INT; END_VAR\nd := d - 1;\nq := 10 / d;\nEND_PROGRAM\n"));
    const Result result = cli({QStringLiteral("run"), file, QStringLiteral("--cycles"), QStringLiteral("5"),
        QStringLiteral("--watch"), QStringLiteral("Main.q")});
    QCOMPARE(result.exitCode, 1);
    QCOMPARE(result.out, QStringLiteral("Main.q = 10\n")); // the state the program stopped in
    QCOMPARE(result.err, file + QStringLiteral(":Main:4: runtime error in cycle 2: Integer division by zero.\n"));
}

void TestCli::compileErrorsStopRun()
{
    QTemporaryDir dir;
    const QString file = writeFile(
        dir, QStringLiteral("wrong.st"), QStringLiteral("PROGRAM Main\nVAR x : INT; END_VAR\nx := y;\nEND_PROGRAM\n"));
    const Result result = cli({QStringLiteral("run"), file, QStringLiteral("--watch"), QStringLiteral("Main.x")});
    QCOMPARE(result.exitCode, 1);
    QCOMPARE(result.out, QString());
    QCOMPARE(result.err,
        file + QStringLiteral(":Main:3:6: error: Unknown variable 'y'. (hint: declare it in a VAR section)\n"));
}

void TestCli::check_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("content");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("output"); // FILE stands for the file's path

    QTest::newRow("clean .st") << QStringLiteral("ok.st") << QString::fromLatin1(kCounter) << 0 << QString();
    QTest::newRow("undeclared")
        << QStringLiteral("bad.st") << QStringLiteral("PROGRAM Main\nVAR x : INT; END_VAR\nx := y;\nEND_PROGRAM\n") << 1
        << QStringLiteral("FILE:Main:3:6: error: Unknown variable 'y'. (hint: declare it in a VAR section)\n");
    QTest::newRow("XML body: line in the body")
        << QStringLiteral("bad.xml") << QStringLiteral(R"(<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous><pou name="P" pouType="program"><interface><localVars><variable name="x"><type><INT/></type></variable></localVars></interface>
  <body><ST><xhtml:p><![CDATA[x := 1;
x := y;]]></xhtml:p></ST></body></pou></pous></types><instances><configurations/></instances></project>)")
        << 1 << QStringLiteral("FILE:P:2:6: error: Unknown variable 'y'. (hint: declare it in a VAR section)\n");
    // A graphical element has no line: the diagnostic names its localId, 64-bit like CODESYS's.
    QTest::newRow("XML FBD: element's localId")
        << QStringLiteral("fbd.xml") << QStringLiteral(R"(<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous><pou name="P" pouType="program"><interface><localVars><variable name="x"><type><INT/></type></variable></localVars></interface>
  <body><FBD><outVariable localId="10000000012"><position x="200" y="10"/><connectionPointIn/><expression>x</expression></outVariable></FBD></body></pou></pous></types><instances><configurations/></instances></project>)")
        << 1 << QStringLiteral("FILE:P: error: Nothing is wired to the output 'x'. (hint: draw a wire to it) [localId 10000000012]\n");
    // An inline SFC transition condition: the transition's localId and the column in its text.
    QTest::newRow("XML SFC: inline condition's localId and column")
        << QStringLiteral("sfc.xml") << QStringLiteral(R"(<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous><pou name="P" pouType="program"><interface><localVars><variable name="go"><type><BOOL/></type></variable></localVars></interface>
  <body><SFC><step localId="1" name="Init" initialStep="true"><position x="0" y="0"/><connectionPointOut formalParameter="x"/></step>
  <transition localId="2"><position x="0" y="40"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut formalParameter="x"/><condition><inline name="T1"><ST><xhtml:p><![CDATA[go AND]]></xhtml:p></ST></inline></condition></transition>
  <jumpStep localId="3" targetName="Init"><position x="0" y="80"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn></jumpStep></SFC></body></pou></pous></types><instances><configurations/></instances></project>)")
        << 1 << QStringLiteral("FILE:P: error: The condition go AND is incomplete: something is missing at its end. [localId 2, column 7]\n");
    // CODESYS 3.5 leaves typeName empty and names the instance after its program; its own
    // visualisation program (VisuElems.Visu_Prg) is not in the file and is left out.
    QTest::newRow("XML CODESYS program instances without typeName")
        << QStringLiteral("codesys.xml") << QStringLiteral(R"(<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous><pou name="main" pouType="program"><interface><localVars><variable name="x"><type><INT/></type></variable></localVars></interface>
  <body><ST><xhtml:p><![CDATA[x := x + 1;]]></xhtml:p></ST></body></pou></pous></types>
  <instances><configurations><configuration name="SoftPLC"><resource name="Application">
  <task name="Task" interval="PT0.02S" priority="1"><pouInstance name="main" typeName=""/></task>
  <task name="VISU_TASK" interval="PT0.1S" priority="31"><pouInstance name="VisuElems.Visu_Prg" typeName=""/></task>
  </resource></configuration></configurations></instances></project>)")
        << 0 << QString();
    QTest::newRow("not XML") << QStringLiteral("broken.xml") << QStringLiteral("<project") << 1 << QString();
    // CODESYS accepts implicit narrowing and sign changes with a warning: the file checks (exit 0).
    QTest::newRow("implicit narrowing: warnings only")
        << QStringLiteral("narrow.st")
        << QStringLiteral("PROGRAM Main\nVAR i : INT; d : DINT := 70000; u : UINT; r : REAL := 2.5; b : BYTE; END_VAR\n"
                          "i := d;\nu := i;\ni := r;\nb := i;\nEND_PROGRAM\n")
        << 0
        << QStringLiteral("FILE:Main:3:1: warning: Implicit conversion from DINT to INT: possible loss of information. (hint: convert it explicitly, e.g. DINT_TO_INT(...))\n"
                          "FILE:Main:4:1: warning: Implicit conversion from signed type INT to unsigned type UINT: possible change of sign. (hint: convert it explicitly, e.g. INT_TO_UINT(...))\n"
                          "FILE:Main:5:1: warning: Implicit conversion from REAL to INT: possible loss of information. (hint: convert it explicitly, e.g. REAL_TO_INT(...))\n"
                          "FILE:Main:6:1: warning: Implicit conversion from INT to BYTE: possible loss of information. (hint: convert it explicitly, e.g. INT_TO_BYTE(...))\n");
}

// %QW2 is %QB4..%QB5 and %QX4.0..%QX5.7 (low byte first, as CODESYS on x86): written by --set
// under one name, read by --watch and by the program under another.
void TestCli::processImageThroughSetAndWatch_data()
{
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<QString>("output");
    QTest::newRow("bit set, word read") << QStringList {"--set", "%QX4.1=TRUE", "--watch", "%QW2", "--watch", "Main.x", "--watch", "Main.w"}
                                        << QStringLiteral("%QW2 = 2\nMain.x = 2\nMain.w = 2\n");
    QTest::newRow("word set, bits read") << QStringList {"--set", "%QW2=16#0300", "--watch", "%QX5.0", "--watch", "%QX5.1", "--watch", "%QX4.0"}
                                         << QStringLiteral("%QX5.0 = TRUE\n%QX5.1 = TRUE\n%QX4.0 = FALSE\n");
    QTest::newRow("input bits, word read") << QStringList {"--set", "%IX0.0=TRUE", "--set", "%IX1.7=TRUE", "--watch", "%IW0", "--watch", "Main.i"}
                                           << QStringLiteral("%IW0 = 32769\nMain.i = 32769\n");
    QTest::newRow("variable set, bit read") << QStringList {"--set", "Main.w=16#8000", "--watch", "%QX5.7", "--watch", "%QB5"}
                                            << QStringLiteral("%QX5.7 = TRUE\n%QB5 = 128\n");
}

void TestCli::processImageThroughSetAndWatch()
{
    QFETCH(QStringList, options);
    QFETCH(QString, output);
    QTemporaryDir dir;
    const QString file = writeFile(dir, QStringLiteral("image.st"),
        QStringLiteral("PROGRAM Main\nVAR w AT %QW2 : WORD; x : WORD; i : WORD; END_VAR\nx := w;\ni := %IW0;\nEND_PROGRAM\n"));
    const Result result = cli(QStringList {QStringLiteral("run"), file} + options);
    QCOMPARE(result.err, QString());
    QCOMPARE(result.exitCode, 0);
    QCOMPARE(result.out, output);
}

// Beremiz's LOGGER: each message on stderr as it happens, with the cycle.
void TestCli::loggerWritesToStderr()
{
    QTemporaryDir dir;
    const QString file = writeFile(dir, QStringLiteral("log.st"),
        QStringLiteral("PROGRAM Main\nVAR l : LOGGER; n : INT; END_VAR\nn := n + 1;\n"
                       "l(TRIG := n >= 2, MSG := 'level reached', LEVEL := WARNING);\nEND_PROGRAM\n"));
    const Result result = cli({QStringLiteral("run"), file, QStringLiteral("--cycles"), QStringLiteral("4")});
    QCOMPARE(result.exitCode, 0);
    QCOMPARE(result.err, file + QStringLiteral(": WARNING: level reached (cycle 2)\n"));
}

void TestCli::check()
{
    QFETCH(QString, name);
    QFETCH(QString, content);
    QFETCH(int, exitCode);
    QFETCH(QString, output);
    QTemporaryDir dir;
    const QString file = writeFile(dir, name, content);
    const Result result = cli({QStringLiteral("check"), file});
    QCOMPARE(result.exitCode, exitCode);
    if (!output.isEmpty() || exitCode == 0)
        QCOMPARE(result.out, QString(output).replace(QLatin1String("FILE"), file));
    else
        QVERIFY2(result.out.startsWith(file + QLatin1Char(':')), qPrintable(result.out));

    const Result missing = cli({QStringLiteral("check"), dir.filePath(QStringLiteral("missing.st"))});
    QCOMPARE(missing.exitCode, 3);
}

// A CoDeSys 2.3 export (.exp, Windows-1252, its own comments): read, its umlauts and € kept.
void TestCli::codesysExportInWindows1252Runs()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("PLC_PRG.EXP"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("\r\n(* @NESTEDCOMMENTS := 'Yes' *)\r\n(* @PATH := '' *)\r\n(* @OBJECTFLAGS := '0, 8' *)\r\n"
               "PROGRAM PLC_PRG\r\nVAR\r\n\tMeldung : STRING := 'St\xF6rung \x80';\r\n\tn : INT;\r\nEND_VAR\r\n"
               "(* @END_DECLARATION := '0' *)\r\nn := LEN(Meldung);\r\nEND_PROGRAM\r\n");
    file.close();
    const Result checked = cli({QStringLiteral("check"), path});
    QCOMPARE(checked.exitCode, 0);
    QCOMPARE(checked.out,
        path + QStringLiteral(":7:1: warning: The file is not UTF-8: it was read as Windows-1252, the code page CoDeSys 2.3 "
                              "writes, so that its umlauts and other special characters are kept.\n"));
    const Result run = cli({QStringLiteral("run"), path, QStringLiteral("--cycles"), QStringLiteral("1"), QStringLiteral("--watch"),
        QStringLiteral("PLC_PRG.Meldung"), QStringLiteral("--watch"), QStringLiteral("PLC_PRG.n")});
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(run.out, QStringLiteral("PLC_PRG.Meldung = 'Störung €'\nPLC_PRG.n = 9\n"));
}

// CoDeSys 2.3 exports LD, FBD, CFC and SFC bodies in a graphical form of its own: one error at such a
// body, naming its POU, and the POUs beside it are still checked.
void TestCli::codesysGraphicalBodyIsNamed()
{
    QTemporaryDir dir;
    const QString path = writeFile(dir, QStringLiteral("EXPORT.EXP"),
        QStringLiteral("(* @NESTEDCOMMENTS := 'Yes' *)\r\n(* @PATH := '' *)\r\nPROGRAM LdProg\r\nVAR\r\n\ta : BOOL;\r\n\tx : BOOL;\r\nEND_VAR\r\n"
        "(* @END_DECLARATION := '0' *)\r\n_LD_BODY\r\n_NETWORKS : 1\r\n_NETWORK\r\n\r\n_COMMENT\r\n''\r\n_END_COMMENT\r\n"
        "_LD_ASSIGN\r\n_LD_CONTACT\r\na\r\n_EXPRESSION\r\n_POSITIV\r\n_EXPRESSION\r\n_POSITIV\r\n\r\nENABLELIST : 0\r\n"
        "ENABLELIST_END\r\n_OUTPUTS : 1\r\n_OUTPUT\r\n_POSITIV\r\n_NO_SET\r\nx\r\nEND_PROGRAM\r\n\r\n"
        "(* @NESTEDCOMMENTS := 'Yes' *)\r\nPROGRAM PLC_PRG\r\nVAR\r\n\tn : INT;\r\nEND_VAR\r\n"
        "(* @END_DECLARATION := '0' *)\r\nn := n + 1;\r\nm := 2;\r\nEND_PROGRAM\r\n"));
    const Result checked = cli({QStringLiteral("check"), path});
    QCOMPARE(checked.exitCode, 1);
    QCOMPARE(checked.out,
        path + QStringLiteral(":LdProg:9:1: error: CoDeSys 2.3 exported this LD body in its own graphical form, which IEC "
                              "Studio does not read; it is kept below as a comment. Export the POU from CoDeSys as PLCopen "
                              "XML to open it as a diagram.\n")
            + path + QStringLiteral(":PLC_PRG:40:1: error: Unknown variable 'm'. (hint: declare it in a VAR section)\n"));
}

void TestCli::infoCountsIecText()
{
    QTemporaryDir dir;
    const QString path = writeFile(dir, QStringLiteral("two.st"),
        QStringLiteral("PROGRAM Main\nVAR x : INT; END_VAR\nx := x + 1;\nEND_PROGRAM\n"
                       "FUNCTION_BLOCK Fb\nVAR_INPUT a : BOOL; b : INT; END_VAR\nEND_FUNCTION_BLOCK\n"));
    const Result info = cli({QStringLiteral("info"), path});
    QCOMPARE(info.err, QString());
    QCOMPARE(info.exitCode, 0);
    QCOMPARE(info.out,
        QStringLiteral("project: two\nPOUs: 2\n  function: 0\n  functionBlock: 1\n  program: 1\nPOUs by language:\n"
                       "  FBD: 0\n  IL: 0\n  LD: 0\n  SFC: 0\n  ST: 2\n  none: 0\ndata types: 0\nvariables: 3\n"
                       "actions: 0\ntransitions: 0\ngraphical elements: 0\n"));
    // Text that does not read: its errors, and exit 1.
    const QString broken = writeFile(dir, QStringLiteral("broken.st"), QStringLiteral("PROGRAM Main\nx := ;\nEND_PROGRAM\n"));
    const Result failed = cli({QStringLiteral("info"), broken});
    QCOMPARE(failed.exitCode, 1);
    QCOMPARE(failed.err, broken + QStringLiteral(":Main:2:6: error: Expected a value, a variable or a function call but found ';'.\n"));
}

void TestCli::checkNamesGraphicalPousOfTheCorpus()
{
    // Its FBD POUs use Beremiz's LOGGER and RTC, which IEC Studio has: the whole file checks clean.
    const QString file = QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/beremiz_iec61131_lang_test.xml");
    const Result result = cli({QStringLiteral("check"), file});
    QCOMPARE(result.out, QString());
    QCOMPARE(result.exitCode, 0);
    // A block of a vendor library IEC Studio lacks: one warning naming the library at its first
    // use, and the program that would need it cannot run.
    const QString tcp = QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/openplc_TCP_socket.xml");
    const Result missing = cli({QStringLiteral("check"), tcp});
    QCOMPARE(missing.exitCode, 1);
    QCOMPARE(missing.out,
        tcp + QStringLiteral(":tcp_socket:3:20: warning: TCP_CONNECT is a block of the OpenPLC TCP socket library, which IEC Studio does not have; "
                             "the POUs that use it cannot run. (hint: the rest of the project is still checked and runs)\n")
            + tcp + QStringLiteral(":tcp_socket: error: instance0 cannot run: tcp_socket uses the OpenPLC TCP socket library.\n"));
}

void TestCli::convertRoundTrips()
{
    QTemporaryDir dir;
    const QString st1 = dir.filePath(QStringLiteral("a.st"));
    const QString xml = dir.filePath(QStringLiteral("b.xml"));
    const QString st2 = dir.filePath(QStringLiteral("c.st"));
    const QString st3 = dir.filePath(QStringLiteral("d.st"));
    QCOMPARE(cli({QStringLiteral("convert"), example(), st1}).exitCode, 0);
    QCOMPARE(cli({QStringLiteral("convert"), st1, xml}).exitCode, 0);
    QCOMPARE(cli({QStringLiteral("convert"), xml, st2}).exitCode, 0);
    QCOMPARE(cli({QStringLiteral("convert"), st2, st3}).exitCode, 0);
    QVERIFY(readAll(st1).startsWith(QLatin1String("PROGRAM Main\n")));
    QCOMPARE(readAll(st2), readAll(st1));
    QCOMPARE(readAll(st3), readAll(st1));
    // The converted program still runs the same.
    const QStringList watch {
        QStringLiteral("--cycles"), QStringLiteral("51"), QStringLiteral("--watch"), QStringLiteral("Main.Count")};
    QCOMPARE(cli(QStringList {QStringLiteral("run"), st1} + watch).out, QStringLiteral("Main.Count = 1\n"));
    QCOMPARE(cli(QStringList {QStringLiteral("run"), xml} + watch).out, QStringLiteral("Main.Count = 1\n"));
    // .xml -> .xml keeps working; the copy converts to the same text.
    const QString copy = dir.filePath(QStringLiteral("copy.xml"));
    const QString st4 = dir.filePath(QStringLiteral("e.st"));
    QCOMPARE(cli({QStringLiteral("convert"), xml, copy}).exitCode, 0);
    QCOMPARE(cli({QStringLiteral("convert"), copy, st4}).exitCode, 0);
    QCOMPARE(readAll(st4), readAll(st1));
}

void TestCli::convertedStValidatesAgainstTheSchema()
{
    const QString xmllint = QStandardPaths::findExecutable(QStringLiteral("xmllint"));
    if (xmllint.isEmpty())
        QSKIP("xmllint is not installed (libxml2-utils)");
    QTemporaryDir dir;
    const QString st = writeFile(dir, QStringLiteral("all.st"),
        QStringLiteral("TYPE P : STRUCT x : INT := 1; END_STRUCT; C : (Red, Green); R : INT (0..9); END_TYPE\n")
            + QLatin1String(kCounter) + QLatin1String(kConfiguration));
    const QString xml = dir.filePath(QStringLiteral("all.xml"));
    const Result converted = cli({QStringLiteral("convert"), st, xml});
    QCOMPARE(converted.err, QString());
    QCOMPARE(converted.exitCode, 0);
    QProcess lint;
    lint.start(xmllint,
        {QStringLiteral("--noout"), QStringLiteral("--schema"),
            QStringLiteral(IEC_SHARED_DIR "/plcopen/tc6_xml_v201.xsd"), xml});
    QVERIFY(lint.waitForFinished(60'000));
    QVERIFY2(lint.exitCode() == 0, lint.readAllStandardError().constData());
}

void TestCli::usageErrors_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("firstLine");
    QTest::newRow("run without file") << QStringList {QStringLiteral("run")}
                                      << QStringLiteral("iecstudio-cli: run needs a FILE (.xml, .st or .exp).");
    QTest::newRow("bad cycles") << QStringList {QStringLiteral("run"), QStringLiteral("x.st"),
        QStringLiteral("--cycles"), QStringLiteral("many")}
                                << QStringLiteral(
                                       "iecstudio-cli: --cycles needs a whole number of cycles, not 'many'.");
    QTest::newRow("bad cycle time")
        << QStringList {QStringLiteral("run"), QStringLiteral("x.st"), QStringLiteral("--cycle-time"),
               QStringLiteral("fast")}
        << QStringLiteral(
               "iecstudio-cli: --cycle-time needs a duration above zero such as 10ms, T#10ms or PT0.01S, not 'fast'.");
    QTest::newRow("bad trace") << QStringList {QStringLiteral("run"), QStringLiteral("x.st"), QStringLiteral("--trace"),
        QStringLiteral("t.txt")}
                               << QStringLiteral("iecstudio-cli: --trace writes a .csv or a .vcd file, not 't.txt'.");
    QTest::newRow("bad set") << QStringList {QStringLiteral("run"), QStringLiteral("x.st"), QStringLiteral("--set"),
        QStringLiteral("x")} << QStringLiteral("iecstudio-cli: --set needs NAME=VALUE or NAME=VALUE@CYCLE, not 'x'.");
    QTest::newRow("convert to .txt")
        << QStringList {QStringLiteral("convert"), QStringLiteral("a.xml"), QStringLiteral("b.txt")}
        << QStringLiteral("iecstudio-cli: convert reads PLCopen XML (.xml) and IEC text (.st, .exp) and writes .xml or .st.");
}

void TestCli::usageErrors()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, firstLine);
    const Result result = cli(arguments);
    QCOMPARE(result.exitCode, 2);
    QCOMPARE(result.err.section(QLatin1Char('\n'), 0, 0), firstLine);
}

// ---- render (docs/cli.md): an SFC body drawn without a display.

namespace {

QString sfcCorpusFile()
{
    return QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/beremiz_first_steps.xml");
}

} // namespace

void TestCli::renderDrawsCharts_data()
{
    QTest::addColumn<QString>("suffix");
    QTest::addColumn<QByteArray>("magic"); // how the file starts
    QTest::newRow("svg") << QStringLiteral("svg") << QByteArray("<?xml");
    QTest::newRow("png") << QStringLiteral("png") << QByteArray("\x89PNG");
    QTest::newRow("pdf") << QStringLiteral("pdf") << QByteArray("%PDF");
}

void TestCli::renderDrawsCharts()
{
    QFETCH(QString, suffix);
    QFETCH(QByteArray, magic);
    if (!QFile::exists(sfcCorpusFile()))
        QSKIP("the PLCopen corpus of shared/ is not there");
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("chart.") + suffix);
    const Result result = cli({QStringLiteral("render"), sfcCorpusFile(), QStringLiteral("--pou"),
        QStringLiteral("CounterSFC"), out});
    QCOMPARE(result.err, QString());
    QCOMPARE(result.out, QString());
    QCOMPARE(result.exitCode, 0);
    QFile file(out);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray bytes = file.readAll();
    QVERIFY(bytes.startsWith(magic));
    QVERIFY(bytes.size() > 1000);
    if (suffix == QLatin1String("svg")) {
        QVERIFY(bytes.contains("ResetCounter")); // the step names are text in the picture
        QVERIFY(bytes.contains("NOT Reset"));
    }
}

void TestCli::renderDrawsLadder()
{
    // Beremiz's CounterLD: networks of contacts, a box and coils, with their variables as text.
    const QString file = QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/beremiz_first_steps.xml");
    if (!QFile::exists(file))
        QSKIP("the PLCopen corpus of shared/ is not there");
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("ladder.svg"));
    const Result result = cli({QStringLiteral("render"), file, QStringLiteral("--pou"), QStringLiteral("CounterLD"), out});
    QCOMPARE(result.err, QString());
    QCOMPARE(result.exitCode, 0);
    QFile svg(out);
    QVERIFY(svg.open(QIODevice::ReadOnly));
    const QByteArray bytes = svg.readAll();
    QVERIFY(bytes.contains(">Reset<"));
    QVERIFY(bytes.contains("ResetCounterValue"));
}

void TestCli::renderDrawsFunctionBlockDiagrams()
{
    // Beremiz's plc_prg: five counters feeding AverageVal through in-out variables, drawn as a
    // tree network, with every name as text.
    const QString file = QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/beremiz_first_steps.xml");
    if (!QFile::exists(file))
        QSKIP("the PLCopen corpus of shared/ is not there");
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("fbd.svg"));
    const Result result = cli({QStringLiteral("render"), file, QStringLiteral("--pou"), QStringLiteral("plc_prg"), out});
    QCOMPARE(result.err, QString());
    QCOMPARE(result.exitCode, 0);
    QFile svg(out);
    QVERIFY(svg.open(QIODevice::ReadOnly));
    const QByteArray bytes = svg.readAll();
    for (const char *name : {"AverageVal", "CounterST0", "CounterLD", ">Cnt5<", "AVCnt", ">Reset<"})
        QVERIFY2(bytes.contains(name), name);
}

void TestCli::renderDrawsCodesysCfc()
{
    // A CFC as CODESYS exports it: an empty ST body, the chart in addData, every wire through an
    // anonymous connector, positions on CODESYS's grid.
    const QByteArray project =
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
        "<project xmlns=\"http://www.plcopen.org/xml/tc6_0200\">"
        "<fileHeader companyName=\"\" productName=\"CODESYS\" productVersion=\"3.5\" creationDateTime=\"2026-11-26T10:00:00\"/>"
        "<contentHeader name=\"cfc\"><coordinateInfo><fbd><scaling x=\"1\" y=\"1\"/></fbd><ld><scaling x=\"1\" y=\"1\"/></ld>"
        "<sfc><scaling x=\"1\" y=\"1\"/></sfc></coordinateInfo></contentHeader>"
        "<types><dataTypes/><pous><pou name=\"PLC_PRG\" pouType=\"program\"><interface><localVars>"
        "<variable name=\"Start\"><type><BOOL/></type></variable><variable name=\"Lamp\"><type><BOOL/></type></variable>"
        "<variable name=\"Delay\"><type><derived name=\"TON\"/></type></variable></localVars></interface>"
        "<body><ST><xhtml xmlns=\"http://www.w3.org/1999/xhtml\"/></ST>"
        "<addData><data name=\"http://www.3s-software.com/plcopenxml/cfc\" handleUnknown=\"implementation\"><CFC>"
        "<inVariable localId=\"1\"><position x=\"4\" y=\"6\"/><connectionPointOut><expression/></connectionPointOut><expression>Start</expression></inVariable>"
        "<connector localId=\"2\" name=\"\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"1\" formalParameter=\"Start\"/></connectionPointIn></connector>"
        "<inVariable localId=\"3\"><position x=\"4\" y=\"7\"/><connectionPointOut><expression/></connectionPointOut><expression>T#2s</expression></inVariable>"
        "<connector localId=\"4\" name=\"\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"3\" formalParameter=\"T#2s\"/></connectionPointIn></connector>"
        "<block localId=\"5\" executionOrderId=\"0\" typeName=\"TON\" instanceName=\"Delay\"><position x=\"12\" y=\"5\"/>"
        "<inputVariables><variable formalParameter=\"IN\"><connectionPointIn><relPosition x=\"0\" y=\"0\"/><connection refLocalId=\"2\"/></connectionPointIn></variable>"
        "<variable formalParameter=\"PT\"><connectionPointIn><relPosition x=\"0\" y=\"1\"/><connection refLocalId=\"4\"/></connectionPointIn></variable></inputVariables>"
        "<inOutVariables/><outputVariables><variable formalParameter=\"Q\"><connectionPointOut><relPosition x=\"0\" y=\"0\"/><expression/></connectionPointOut></variable>"
        "<variable formalParameter=\"ET\"><connectionPointOut><relPosition x=\"0\" y=\"1\"/><expression/></connectionPointOut></variable></outputVariables></block>"
        "<connector localId=\"6\" name=\"\"><position x=\"0\" y=\"0\"/><connectionPointIn><connection refLocalId=\"5\" formalParameter=\"Q\"/></connectionPointIn></connector>"
        "<outVariable localId=\"7\" executionOrderId=\"1\"><position x=\"22\" y=\"6\"/><connectionPointIn><relPosition x=\"0\" y=\"0\"/>"
        "<connection refLocalId=\"6\"/></connectionPointIn><expression>Lamp</expression></outVariable>"
        "</CFC></data></addData></body></pou></pous></types>"
        "<instances><configurations/></instances></project>\n";
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("cfc.xml"));
    QFile source(file);
    QVERIFY(source.open(QIODevice::WriteOnly));
    source.write(project);
    source.close();
    const QString out = dir.filePath(QStringLiteral("cfc.svg"));
    const Result result = cli({QStringLiteral("render"), file, QStringLiteral("--pou"), QStringLiteral("PLC_PRG"), out});
    QCOMPARE(result.err, QString());
    QCOMPARE(result.exitCode, 0);
    QFile svg(out);
    QVERIFY(svg.open(QIODevice::ReadOnly));
    const QByteArray bytes = svg.readAll();
    // Every name, the pins, and the execution order counted from 1.
    for (const char *name : {">Start<", ">T#2s<", ">TON<", ">Delay<", ">Lamp<", ">IN<", ">PT<", ">Q<", ">ET<", ">1<", ">2<"})
        QVERIFY2(bytes.contains(name), name);
    // Drawing it changed nothing in the file.
    QFile after(file);
    QVERIFY(after.open(QIODevice::ReadOnly));
    QCOMPARE(after.readAll(), project);
}

void TestCli::renderDrawsActionsAndTransitions()
{
    // TwinCAT's PPU keeps SFC charts in actions of its function blocks.
    const QString file = QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/twincat356_ppu.xml");
    if (!QFile::exists(file))
        QSKIP("the PLCopen corpus of shared/ is not there");
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("action.svg"));
    Result result = cli({QStringLiteral("render"), file, QStringLiteral("--pou"), QStringLiteral("Stamp"),
        QStringLiteral("--action"), QStringLiteral("ACT_Stamp"), out});
    QCOMPARE(result.err, QString());
    QCOMPARE(result.exitCode, 0);
    QFile svg(out);
    QVERIFY(svg.open(QIODevice::ReadOnly));
    const QByteArray bytes = svg.readAll();
    QVERIFY(bytes.contains("Slider_Retract"));
    QVERIFY(bytes.contains("Medium_Pressure"));
    // The option's other spelling, and a part that is not there.
    result = cli({QStringLiteral("render"), file, QStringLiteral("--pou=Stamp"), QStringLiteral("--action=ACT_Init"), out});
    QCOMPARE(result.exitCode, 0);
    result = cli({QStringLiteral("render"), file, QStringLiteral("--pou"), QStringLiteral("Stamp"), QStringLiteral("--transition"),
        QStringLiteral("Nope"), out});
    QCOMPARE(result.exitCode, 2);
    QCOMPARE(result.err.trimmed(), QStringLiteral("iecstudio-cli: render: POU 'Stamp' has no transition named 'Nope'."));
    // An action in ST cannot be drawn.
    result = cli({QStringLiteral("render"), file, QStringLiteral("--pou"), QStringLiteral("Stamp"), QStringLiteral("--action"),
        QStringLiteral("ACT_GreenLampOn"), out});
    QCOMPARE(result.exitCode, 1);
    QCOMPARE(result.err.trimmed(), QStringLiteral("iecstudio-cli: render: Action 'Stamp.ACT_GreenLampOn' is written in ST, "
                                                  "which cannot be drawn yet (LD, FBD, CFC, SFC can)."));
}

void TestCli::renderRefuses_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    const QString file = sfcCorpusFile();
    QTest::newRow("not drawable yet") << QStringList {QStringLiteral("render"), file, QStringLiteral("--pou"),
        QStringLiteral("CounterST"), QStringLiteral("x.svg")} << 1
                                      << QStringLiteral("iecstudio-cli: render: POU 'CounterST' is written in ST, which "
                                                        "cannot be drawn yet (LD, FBD, CFC, SFC can).");
    QTest::newRow("no such POU") << QStringList {QStringLiteral("render"), file, QStringLiteral("--pou"),
        QStringLiteral("Nope"), QStringLiteral("x.svg")} << 2
                                 << QStringLiteral("iecstudio-cli: render: %1 has no POU named 'Nope'.").arg(file);
    QTest::newRow("picture type") << QStringList {QStringLiteral("render"), file, QStringLiteral("--pou"),
        QStringLiteral("CounterSFC"), QStringLiteral("x.bmp")} << 2
                                  << QStringLiteral("iecstudio-cli: render: x.bmp: the picture must end in .svg, .png or .pdf.");
    QTest::newRow("no --pou") << QStringList {QStringLiteral("render"), file, QStringLiteral("x.svg")} << 2
                              << QStringLiteral("Usage: iecstudio-cli render FILE --pou NAME [--action NAME | --transition NAME] OUT.svg|OUT.png|OUT.pdf");
    QTest::newRow("--pou without a name") << QStringList {QStringLiteral("render"), file, QStringLiteral("x.svg"), QStringLiteral("--pou")} << 2
                                          << QStringLiteral("iecstudio-cli: render: --pou needs the name of a POU.");
    QTest::newRow("two parts") << QStringList {QStringLiteral("render"), file, QStringLiteral("--pou"), QStringLiteral("CounterSFC"),
        QStringLiteral("--action"), QStringLiteral("A"), QStringLiteral("--transition"), QStringLiteral("T"), QStringLiteral("x.svg")} << 2
                               << QStringLiteral("iecstudio-cli: render: give one --action or --transition.");
    QTest::newRow("--action without a name") << QStringList {QStringLiteral("render"), file, QStringLiteral("x.svg"), QStringLiteral("--pou"),
        QStringLiteral("CounterSFC"), QStringLiteral("--action")} << 2
                                             << QStringLiteral("iecstudio-cli: render: --action needs the name of an action.");
    QTest::newRow("unknown option") << QStringList {QStringLiteral("render"), file, QStringLiteral("--zoom"), QStringLiteral("x.svg")} << 2
                                    << QStringLiteral("iecstudio-cli: render: unknown option '--zoom'.");
    QTest::newRow("unwritable") << QStringList {QStringLiteral("render"), file, QStringLiteral("--pou"),
        QStringLiteral("CounterSFC"), QStringLiteral("/nonexistent-dir/x.svg")} << 3
                                << QStringLiteral("iecstudio-cli: render: Cannot write /nonexistent-dir/x.svg.");
}

void TestCli::renderRefuses()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    if (!QFile::exists(sfcCorpusFile()))
        QSKIP("the PLCopen corpus of shared/ is not there");
    const Result result = cli(arguments);
    QCOMPARE(result.exitCode, exitCode);
    QCOMPARE(result.err.section(QLatin1Char('\n'), 0, 0), message);
    QCOMPARE(result.out, QString());
}

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
