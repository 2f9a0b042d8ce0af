// The Beremiz examples of ../shared/plcopen/corpus, read by the model's PLCopen reader and
// compiled through the model front end (projectsource.h): every project that needs no missing
// vendor library compiles and runs, and the language test's own checks pass, its FBD POUs
// included (they report through Beremiz's LOGGER).
#include "interpreter/compiler/compiler.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"

#include "model/plcopen/reader.h"

#include <QTest>

using namespace iec;
using namespace iec::interp;

class TestCorpus : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void languageTestPassesItsOwnChecks();
    void languageTestRunsItsFbdPous();
    void standardFunctionBlocksCompile();
    void everyProjectCompiles_data();
    void everyProjectCompiles();
    void firstStepsCountersAgree();
    void svgHmiTrafficLightRuns();
};

namespace {

model::Project readCorpus(const char *file)
{
    const auto result
        = model::plcopen::readProjectFile(QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/") + QLatin1String(file));
    return result.project;
}

QString errors(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics.all())
        lines << d.toString();
    return lines.join(QLatin1Char('\n'));
}

// Drops the POUs the compiler cannot run yet (graphical bodies); returns their names.
QStringList dropGraphicalPous(model::Project &project)
{
    QStringList dropped;
    std::erase_if(project.types.pous, [&](const model::Pou &pou) {
        const bool graphical = pou.body() && pou.body()->isGraphical();
        if (graphical)
            dropped << pou.name;
        return graphical;
    });
    return dropped;
}

} // namespace

void TestCorpus::languageTestPassesItsOwnChecks()
{
    model::Project project = readCorpus("beremiz_iec61131_lang_test.xml");
    QCOMPARE(dropGraphicalPous(project), (QStringList {QStringLiteral("main_test"), QStringLiteral("TEMPO_TEST")}));
    project.instances.configurations.clear(); // its task runs main_test, which is FBD
    const auto main = frontend::readIecText(
        u"PROGRAM Main\nVAR t : CONVERSION_TEST; result : STRING; END_VAR\nt();\nresult := t.RESULT;\nEND_PROGRAM\n",
        {});
    QCOMPARE(errors(main.diagnostics), QString());
    project.types.pous.push_back(main.project.types.pous.front());
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(project, diagnostics);
    QCOMPARE(errors(diagnostics), QString());
    QVERIFY(module);
    Runtime runtime(module);
    QVERIFY(runtime.runCycle());
    // The test sets RESULT to the name of each conversion before checking it and returns at the
    // first failure; 'OK' means all 240 passed.
    QCOMPARE(runtime.read(QStringLiteral("Main.result")).value(), QStringLiteral("'OK'"));
}

void TestCorpus::languageTestRunsItsFbdPous()
{
    // The FBD test programs use Beremiz's LOGGER and RTC (docs/stdlib.md): they compile and run,
    // and report through LOGGER.
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(readCorpus("beremiz_iec61131_lang_test.xml"), diagnostics);
    QCOMPARE(errors(diagnostics), QString());
    QVERIFY(module);
    Runtime runtime(module, 20'000'000); // the task's interval, T#20ms
    // TEMPO_TEST measures 10 s with RTC against a TON: its verdict comes when the TON is done.
    QVERIFY(runtime.runCycles(600));
    QStringList log;
    for (const Runtime::LogEntry &e : runtime.takeLog())
        log << e.toString();
    QCOMPARE(log, QStringList({QStringLiteral("DEBUG: CONVERSION: OK (cycle 1)"), QStringLiteral("DEBUG: TEMPO: OK (cycle 501)"),
                                  QStringLiteral("DEBUG: ALL TESTS OK (cycle 501)")}));
}

void TestCorpus::standardFunctionBlocksCompile()
{
    const model::Project project = readCorpus("beremiz_Standard_Function_Blocks.xml");
    QCOMPARE(project.types.pous.size(), size_t(23));
    Diagnostics diagnostics;
    CompileOptions options;
    const auto unit = frontend::buildUnit(project, diagnostics);
    QCOMPARE(unit.unit.pous.size(), size_t(23));
    const auto module = frontend::compileUnit(unit, diagnostics, options);
    QCOMPARE(errors(diagnostics), QString());
    QVERIFY(module); // the file's own SR, TON, ... replace the built-in library ones
}

// Every project of the corpus that needs no vendor library IEC Studio lacks compiles without an
// error, and the CODESYS and TwinCAT ones run (100 cycles without a fault); the others name the
// library they need.
void TestCorpus::everyProjectCompiles_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<bool>("runs");
    QTest::addColumn<QString>("needs"); // the error naming what is missing; empty: compiles
    const auto row = [](const char *file, bool runs, const char *needs = "") {
        QTest::newRow(file) << QString::fromLatin1(file) << runs << QString::fromUtf8(needs);
    };
    row("beremiz_Standard_Function_Blocks.xml", false);
    row("beremiz_first_steps.xml", true);
    row("beremiz_iec61131_lang_test.xml", true);
    row("beremiz_svghmi_traffic_light.xml", true); // its SVGHMI variables are plain ones (docs/stdlib.md)
    row("codesys35sp14_FBDExample.xml", true);
    row("codesys35sp16_hello_mixing_tank.xml", true);
    row("codesys35sp18_sfc_test.xml", true);
    row("openplc_TCP_socket.xml", false, "the OpenPLC TCP socket library");
    row("openplc_Traffic_Light_FBD.xml", true);
    // One POU exported from a TwinCAT library: its types (Pose3D ...) are in files it does not include.
    row("twincat3513_MAIN.xml", false, "Unknown type 'Pose3D'");
    row("twincat356_ppu.xml", true);
}

void TestCorpus::everyProjectCompiles()
{
    QFETCH(QString, file);
    QFETCH(bool, runs);
    QFETCH(QString, needs);
    const auto read = model::plcopen::readProjectFile(QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/") + file);
    QVERIFY(read.isProject);
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(read.project, diagnostics);
    QStringList errorLines;
    for (const Diagnostic &d : diagnostics.all()) {
        if (d.severity == Diagnostic::Severity::Error)
            errorLines << d.toString();
    }
    if (!needs.isEmpty()) {
        QVERIFY2(!errorLines.isEmpty() || errors(diagnostics).contains(needs), qPrintable(errors(diagnostics)));
        QVERIFY2(errors(diagnostics).contains(needs), qPrintable(errors(diagnostics)));
        return;
    }
    QCOMPARE(errorLines.join(QLatin1Char('\n')), QString());
    QVERIFY(module);
    if (!runs)
        return;
    Runtime runtime(module);
    QVERIFY2(runtime.runCycles(100), qPrintable(runtime.fault() ? runtime.fault()->toString() : QString()));
}

// Beremiz's first steps counts in five languages; its IL counter ends in "JMP QuitFb" with the
// sum as the current result, which the jump carries to "QuitFb: ST Cnt" (it once stayed at 17).
void TestCorpus::firstStepsCountersAgree()
{
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(readCorpus("beremiz_first_steps.xml"), diagnostics);
    QVERIFY2(module, qPrintable(errors(diagnostics)));
    Runtime runtime(module, 100'000'000); // the task's interval, T#100ms
    QVERIFY(runtime.runCycles(5));
    for (const char *counter : {"CounterST0", "CounterFBD0", "CounterIL0", "CounterLD0"})
        QCOMPARE(runtime.read(QStringLiteral("plc_task_instance.%1.Cnt").arg(QLatin1String(counter))).value_or(QStringLiteral("?")), QStringLiteral("5"));
    QVERIFY(!runtime.write(QStringLiteral("plc_task_instance.Reset"), QStringLiteral("TRUE")));
    QVERIFY(runtime.runCycle());
    QCOMPARE(runtime.read(QStringLiteral("plc_task_instance.CounterIL0.Cnt")).value_or(QStringLiteral("?")), QStringLiteral("17"));
    QCOMPARE(runtime.read(QStringLiteral("plc_task_instance.Cnt4")).value_or(QStringLiteral("?")), QStringLiteral("17"));
}

// Beremiz's SVGHMI traffic light: its HMI_BOOL buttons and lights are plain BOOLs here, so the
// chart runs: switched on, the car lights go orange 2 s, red while the pedestrians cross (2 s +
// 10 s + 2 s, each step change a cycle), green 20 s, orange again. Lengths in 100 ms cycles.
void TestCorpus::svgHmiTrafficLightRuns()
{
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(readCorpus("beremiz_svghmi_traffic_light.xml"), diagnostics);
    QVERIFY2(module, qPrintable(errors(diagnostics)));
    Runtime runtime(module, 100'000'000);
    QVERIFY(!runtime.write(QStringLiteral("main_instance.SwitchButton"), QStringLiteral("TRUE")));
    QStringList phases; // "light cycles", one entry per change
    QString current;
    int length = 0;
    for (int cycle = 0; cycle < 400; ++cycle) {
        QVERIFY(runtime.runCycle());
        QString lit;
        for (const char *light : {"RedLight", "OrangeLight", "GreenLight"}) {
            if (runtime.read(QStringLiteral("main_instance.%1").arg(QLatin1String(light))) == QStringLiteral("TRUE"))
                lit += QLatin1String(light).chopped(5);
        }
        if (lit != current && length > 0) {
            phases << QStringLiteral("%1 %2").arg(current).arg(length);
            length = 0;
        }
        current = lit;
        ++length;
    }
    QCOMPARE(phases, QStringList({"Orange 22", "Red 143", "Green 201", "Orange 21"}));
}

QTEST_GUILESS_MAIN(TestCorpus)
#include "tst_corpus.moc"
