// POUs as CODESYS uses them: programs called from other POUs (PRG1(); PRG1.Out), charts in
// actions (of an ST program, and of a chart), and the shared process image (%QW2 is %QB4..%QB5
// and %QX4.0..%QX5.7, low byte first as CODESYS on x86), seen alike by the program and by names.
#include "tracerunner.h"

#include "interpreter/compiler/parser.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"

#include <QTest>

using namespace iec;
using namespace iec::interp;
using namespace iec::interp::testing;
using namespace iec::interp::testing::table;

namespace {

// Compiles through the front end, which lowers textual charts, and runs the steps.
QString runChart(const QString &source, const QStringList &steps)
{
    Diagnostics diagnostics;
    frontend::ProjectUnit unit {parseUnit(source, diagnostics), false};
    if (diagnostics.hasErrors())
        return QStringLiteral("does not parse: ") + errorsOf(diagnostics);
    const auto module = frontend::compileUnit(unit, diagnostics);
    if (!module)
        return QStringLiteral("does not compile: ") + errorsOf(diagnostics);
    Runtime runtime(module);
    return runSteps(runtime, steps);
}

// The same program as a PLCopen file: the text read into the model (each textual chart becomes a
// graphical SFC body), written as TC6 XML, read back and compiled from the model.
QString runChartThroughPlcopen(const QString &source, const QStringList &steps)
{
    const frontend::TextReadResult text = frontend::readIecText(source, QStringLiteral("Charts"));
    if (text.diagnostics.hasErrors())
        return QStringLiteral("does not read: ") + errorsOf(text.diagnostics);
    int charts = 0;
    for (const model::Pou &pou : text.project.types.pous) {
        for (const model::PouAction &action : pou.actions)
            charts += action.body.language() == model::BodyLanguage::SFC ? 1 : 0;
    }
    if (charts != 1)
        return QStringLiteral("%1 actions are charts").arg(charts);
    const auto read = model::plcopen::readProject(model::plcopen::writeProject(text.project));
    if (!read.isProject)
        return QStringLiteral("the written file does not read back");
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(read.project, diagnostics);
    if (!module)
        return QStringLiteral("does not compile: ") + errorsOf(diagnostics);
    Runtime runtime(module);
    return runSteps(runtime, steps);
}

const char *const kCounter = "PROGRAM Counter\nVAR_INPUT step : INT := 1; END_VAR\nVAR_OUTPUT Out : INT; END_VAR\n"
                             "VAR hidden : INT; END_VAR\nOut := Out + step; hidden := hidden + 1;\nEND_PROGRAM\n";

} // namespace

class TestPous : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void programCalls_data();
    void programCalls() { check(); }
    void programCallErrors();
    void chartsInActions_data();
    void chartsInActions();
    void processImage_data();
    void processImage() { check(); }
    void processImageByName();
};

void TestPous::programCalls_data()
{
    columns();
    // The program instance persists: its output and the input given once stay (CODESYS).
    row("st call and output", QByteArray(kCounter) + "PROGRAM Main\nVAR x : INT; END_VAR\nCounter();\nCounter(step := 10);\nx := Counter.Out;\nEND_PROGRAM\n",
        {"=> x=11; Counter.Out=11", "=> x=31"});
    row("il call", QByteArray(kCounter) + "PROGRAM Main\nVAR x : INT; END_VAR\n CAL Counter\n LD Counter.Out\n ST x\nEND_PROGRAM\n",
        {"=> x=1", "=> x=2"});
    row("input set from outside", QByteArray(kCounter) + "PROGRAM Main\nVAR x : INT; END_VAR\nCounter.step := 5;\nCounter();\nx := Counter.Out;\nEND_PROGRAM\n",
        {"=> x=5", "=> x=10"});
    // A local variable of a program can be read from outside too.
    row("program variable read", QByteArray(kCounter) + "PROGRAM Main\nVAR x : INT; END_VAR\nCounter();\nx := Counter.hidden;\nEND_PROGRAM\n",
        {"=> x=1", "=> x=2"});
}

void TestPous::programCallErrors()
{
    Diagnostics diagnostics;
    compileText(QStringLiteral("%1PROGRAM Main\nVAR x : INT; END_VAR\nx := Counter.hidden;\nCounter.Out := 1;\nx := Counter();\nEND_PROGRAM\n").arg(QLatin1String(kCounter)), diagnostics);
    QCOMPARE(errorsOf(diagnostics), QStringLiteral("Main:10:1: error: Counter.Out is an output of the function block and can only be read. | "
                                                   "Main:11:6: error: A program call is a statement of its own. (hint: call Counter(...); then read its outputs, e.g. Counter.Out)"));
}

void TestPous::chartsInActions_data()
{
    QTest::addColumn<QString>("source");
    QTest::addColumn<QStringList>("steps");
    // Every transition TRUE: the chart moves one step per cycle (a transition takes effect in the
    // next cycle), A, B, A, ... while the action runs.
    const QString alternating = QStringLiteral("INITIAL_STEP A: END_STEP\nTRANSITION FROM A TO B := TRUE; END_TRANSITION\n"
                                               "STEP B: END_STEP\nTRANSITION FROM B TO A := TRUE; END_TRANSITION\n");
    QTest::newRow("chart in an action of an st program")
        << QStringLiteral("PROGRAM Main\nVAR xa : BOOL; xb : BOOL; END_VAR\nSeq();\nxa := A.x; xb := B.x;\nACTION Seq:\n%1END_ACTION\nEND_PROGRAM\n").arg(alternating)
        << QStringList{"=> xa=TRUE; xb=FALSE", "=> xa=FALSE; xb=TRUE", "=> xa=TRUE; xb=FALSE"};
    // The outer chart stays in Run, whose N action is the inner chart.
    QTest::newRow("chart in an action of a chart")
        << QStringLiteral("PROGRAM Main\nVAR go : BOOL; END_VAR\nINITIAL_STEP Run: Inner(N); END_STEP\n"
                          "TRANSITION FROM Run TO Idle := go; END_TRANSITION\nSTEP Idle: END_STEP\nTRANSITION FROM Idle TO Run := NOT go; END_TRANSITION\n"
                          "ACTION Inner:\n%1END_ACTION\nEND_PROGRAM\n").arg(alternating)
        << QStringList{"=> A.x=TRUE; B.x=FALSE", "=> A.x=FALSE; B.x=TRUE", "=> A.x=TRUE; B.x=FALSE"};
    // Each instance has its own inner chart: g runs only every other cycle, so it moves half as often.
    QTest::newRow("chart in an action of a function block")
        << QStringLiteral("FUNCTION_BLOCK Fb\nVAR_OUTPUT first : BOOL; END_VAR\nSeq();\nfirst := A.x;\nACTION Seq:\n%1END_ACTION\nEND_FUNCTION_BLOCK\n"
                          "PROGRAM Main\nVAR f : Fb; g : Fb; fa : BOOL; ga : BOOL; END_VAR\nf();\nfa := f.first;\nIF fa THEN g(); END_IF;\nga := g.first;\nEND_PROGRAM\n").arg(alternating)
        << QStringList{"=> fa=TRUE; ga=TRUE", "=> fa=FALSE; ga=TRUE", "=> fa=TRUE; ga=FALSE", "=> fa=FALSE; ga=FALSE"};
}

void TestPous::chartsInActions()
{
    QFETCH(QString, source);
    QFETCH(QStringList, steps);
    QCOMPARE(runChart(source, steps), QString());
    QCOMPARE(runChartThroughPlcopen(source, steps), QString());
}

void TestPous::processImage_data()
{
    columns();
    row("bit written, word read", "VAR w AT %QW2 : WORD; b AT %QX4.1 : BOOL; x : WORD; END_VAR\nb := TRUE;\nx := w;", {"=> x=2; w=2"});
    row("word written, bits read", "VAR c : BOOL; d : BOOL; e : BOOL; END_VAR\n%QW2 := 16#0300;\nc := %QX5.0; d := %QX5.1; e := %QX4.0;",
        {"=> c=TRUE; d=TRUE; e=FALSE; %QB5=3; %QB4=0"});
    row("declared and in code", "VAR q AT %QX0.0 : BOOL; END_VAR\nq := TRUE;\n%QX0.1 := q;", {"=> %QB0=3"});
    // x86 stores the low byte first: %QD0 := 16#11223344 makes %QB0 16#44 and %QB3 16#11.
    row("byte order", "%QD0 := 16#11223344;", {"=> %QB0=68; %QB3=17; %QW0=13124; %QW1=4386"});
    row("input bits make the word", "VAR w : WORD; END_VAR\nw := %IW0;", {"%IX0.0=TRUE; %IX1.7=TRUE => w=32769", "%IX0.0=FALSE => w=32768"});
    row("input word seen as bits", "VAR i AT %IW1 : INT; b AT %IX2.2 : BOOL; END_VAR\n", {"%IW1=4 => b=TRUE; i=4", "Main.i=0 => b=FALSE"});
    row("memory area", "VAR m AT %MW0 : WORD; END_VAR\n%MX0.3 := TRUE;\nm := m + 1;", {"=> m=9", "=> m=10"});
    row("initial value in the image", "VAR q AT %QW0 : INT := 5; END_VAR\n", {"=> %QB0=5; %QW0=5"});
}

void TestPous::processImageByName()
{
    Diagnostics diagnostics;
    const auto module = compileText(QStringLiteral("PROGRAM Main\nVAR w AT %QW2 : WORD; b AT %QX4.1 : BOOL; END_VAR\n;\nEND_PROGRAM\n"), diagnostics);
    QVERIFY2(module, qPrintable(errorsOf(diagnostics)));
    Runtime runtime(module);
    // Written by name between cycles: every name of the same memory sees it at once.
    QCOMPARE(runtime.write(QStringLiteral("%QX4.1"), QStringLiteral("TRUE")), std::nullopt);
    QCOMPARE(runtime.read(QStringLiteral("%QW2")), QStringLiteral("2"));
    QCOMPARE(runtime.read(QStringLiteral("Main.w")), QStringLiteral("2"));
    QCOMPARE(runtime.read(QStringLiteral("Main.b")), QStringLiteral("TRUE"));
    QCOMPARE(runtime.write(QStringLiteral("Main.w"), QStringLiteral("16#0100")), std::nullopt);
    QCOMPARE(runtime.read(QStringLiteral("%QX5.0")), QStringLiteral("TRUE"));
    QCOMPARE(runtime.read(QStringLiteral("Main.b")), QStringLiteral("FALSE"));
    // The output image the I/O panel shows is the same after a cycle.
    QVERIFY(runtime.runCycle());
    QCOMPARE(int(runtime.image('Q')[5]), 1);
    QCOMPARE(int(runtime.image('Q')[4]), 0);
}

QTEST_GUILESS_MAIN(TestPous)
#include "tst_pous.moc"
