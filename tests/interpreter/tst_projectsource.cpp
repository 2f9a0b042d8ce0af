// The model front end (interpreter/frontend/projectsource.h): a project read from PLCopen XML
// compiles and runs like the same program written as IEC text; data types, configurations and
// tasks carry over; diagnostics point into the POU's body; graphical POUs are named, not run.
#include "interpreter/compiler/compiler.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"

#include "model/plcopen/reader.h"

#include <QTest>

using namespace iec;
using namespace iec::interp;

class TestProjectSource : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void sameTraceAsText_data();
    void sameTraceAsText();
    void dataTypes_data();
    void dataTypes();
    void configurationRunsTasksAtTheirIntervals();
    void programNameStandsForItsOnlyInstance();
    void projectWithoutConfigurationRunsItsProgram();
    void namedGlobalListsQualifyTheirVariables();
    void bodyDiagnosticsAreLocatedInTheBody_data();
    void bodyDiagnosticsAreLocatedInTheBody();
    void actionDiagnosticsNameTheAction();
    void graphicalPousAreNamed_data();
    void graphicalPousAreNamed();
};

namespace {

const char *const kHeader = R"(<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="t" productName="t" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="t"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
)";

// A whole PLCopen project around the given <dataTypes>, <pous> content and <instances> content.
model::Project project(const QString &dataTypes, const QString &pous, const QString &configurations = {})
{
    const QString xml = QLatin1String(kHeader) + QStringLiteral("<types><dataTypes>") + dataTypes
        + QStringLiteral("</dataTypes><pous>") + pous + QStringLiteral("</pous></types><instances><configurations>")
        + configurations + QStringLiteral("</configurations></instances></project>");
    auto result = model::plcopen::readProject(xml.toUtf8());
    if (!result.ok) {
        for (const auto &d : result.diagnostics)
            qWarning("%d:%d: %s", d.line, d.column, qPrintable(d.message));
    }
    return result.project;
}

// <pou> with the given interface XML and an ST (or IL) body.
QString pou(const QString &name, const QString &kind, const QString &interface, const QString &body,
    const QString &language = QStringLiteral("ST"))
{
    return QStringLiteral(
        R"(<pou name="%1" pouType="%2"><interface>%3</interface><body><%5><xhtml:p><![CDATA[%4]]></xhtml:p></%5></body></pou>)")
        .arg(name, kind, interface, body, language);
}

QString var(const QString &name, const QString &type, const QString &init = {})
{
    const QString initial = init.isEmpty() ? QString() : QStringLiteral("<initialValue>%1</initialValue>").arg(init);
    return QStringLiteral(R"(<variable name="%1"><type>%2</type>%3</variable>)").arg(name, type, initial);
}

QString simple(const QString &value)
{
    return QStringLiteral(R"(<simpleValue value="%1"/>)").arg(value);
}

QString errors(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics.all())
        lines << d.toString();
    return lines.join(QLatin1Char('\n'));
}

// The values of `names` after each of `cycles` cycles, one line per cycle.
QStringList trace(const std::shared_ptr<const Module> &module, const QStringList &names, int cycles)
{
    QStringList lines;
    Runtime runtime(module);
    for (int cycle = 1; cycle <= cycles; ++cycle) {
        if (!runtime.runCycle())
            return {runtime.fault()->toString()};
        QStringList values;
        for (const QString &name : names)
            values << runtime.read(name).value_or(QStringLiteral("?"));
        lines << values.join(QLatin1Char(' '));
    }
    return lines;
}

} // namespace

void TestProjectSource::sameTraceAsText_data()
{
    QTest::addColumn<QString>("interface"); // PLCopen XML
    QTest::addColumn<QString>("declarations"); // the same as IEC text
    QTest::addColumn<QString>("body");
    QTest::addColumn<QString>("language");
    QTest::addColumn<QStringList>("watch");
    QTest::addColumn<QStringList>("expected"); // after cycles 1, 2, 3, ...

    QTest::newRow("ST TON blinker") << QStringLiteral("<localVars>")
            + var(QStringLiteral("T"), QStringLiteral(R"(<derived name="TON"/>)"))
            + var(QStringLiteral("Q"), QStringLiteral("<BOOL/>")) + QStringLiteral("</localVars>")
                                    << QStringLiteral("VAR T : TON; Q : BOOL; END_VAR")
                                    << QStringLiteral("T(IN := NOT T.Q, PT := T#20ms);\nQ := T.Q;")
                                    << QStringLiteral("ST")
                                    << QStringList {QStringLiteral("Main.Q"), QStringLiteral("Main.T.ET")}
                                    << QStringList {QStringLiteral("FALSE T#0s"), QStringLiteral("FALSE T#10ms"),
                                           QStringLiteral("TRUE T#20ms"), QStringLiteral("FALSE T#0s"),
                                           QStringLiteral("FALSE T#0s"), QStringLiteral("FALSE T#10ms")};
    QTest::newRow("IL deferred parenthesis")
        << QStringLiteral("<localVars>")
            + var(QStringLiteral("ERG"), QStringLiteral("<INT/>"), simple(QStringLiteral("1")))
            + QStringLiteral("</localVars>")
        << QStringLiteral("VAR ERG : INT := 1; END_VAR") << QStringLiteral("LD ERG\nMUL (6\nADD 7\n)\nST ERG")
        << QStringLiteral("IL") << QStringList {QStringLiteral("Main.ERG")}
        << QStringList {QStringLiteral("13"), QStringLiteral("169"), QStringLiteral("2197")}; // ERG * (6 + 7)
    QTest::newRow("ST input with initial value and CONSTANT")
        << QStringLiteral(R"(<localVars constant="true">)")
            + var(QStringLiteral("Step"), QStringLiteral("<DINT/>"), simple(QStringLiteral("16#10")))
            + QStringLiteral("</localVars><localVars>") + var(QStringLiteral("N"), QStringLiteral("<DINT/>"))
            + QStringLiteral("</localVars>")
        << QStringLiteral("VAR CONSTANT Step : DINT := 16#10; END_VAR VAR N : DINT; END_VAR")
        << QStringLiteral("N := N + Step;") << QStringLiteral("ST") << QStringList {QStringLiteral("Main.N")}
        << QStringList {QStringLiteral("16"), QStringLiteral("32")};
}

void TestProjectSource::sameTraceAsText()
{
    QFETCH(QString, interface);
    QFETCH(QString, declarations);
    QFETCH(QString, body);
    QFETCH(QString, language);
    QFETCH(QStringList, watch);
    QFETCH(QStringList, expected);

    Diagnostics fromModel;
    const auto modelModule = frontend::compileProject(
        project({}, pou(QStringLiteral("Main"), QStringLiteral("program"), interface, body, language)), fromModel);
    QCOMPARE(errors(fromModel), QString());
    QVERIFY(modelModule);
    Diagnostics fromText;
    const auto textModule
        = compileText(QStringLiteral("PROGRAM Main\n%1\n%2\nEND_PROGRAM\n").arg(declarations, body), fromText);
    QCOMPARE(errors(fromText), QString());
    QVERIFY(textModule);

    const QStringList modelTrace = trace(modelModule, watch, int(expected.size()));
    QCOMPARE(modelTrace, expected);
    QCOMPARE(trace(textModule, watch, int(expected.size())), modelTrace);
}

void TestProjectSource::dataTypes_data()
{
    QTest::addColumn<QString>("dataTypes");
    QTest::addColumn<QString>("variables"); // <localVars> content of Main
    QTest::addColumn<QString>("body");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("expected");

    const QString point = QStringLiteral(R"(<dataType name="Point"><baseType><struct>)")
        + var(QStringLiteral("x"), QStringLiteral("<INT/>"), simple(QStringLiteral("3")))
        + var(QStringLiteral("y"), QStringLiteral("<INT/>")) + QStringLiteral("</struct></baseType></dataType>");
    QTest::newRow("struct with member defaults")
        << point << var(QStringLiteral("p"), QStringLiteral(R"(<derived name="Point"/>)"))
        << QStringLiteral("p.y := p.x * 2;") << QStringLiteral("Main.p") << QStringLiteral("(x := 3, y := 6)");
    QTest::newRow("struct initial value")
        << point
        << var(QStringLiteral("p"), QStringLiteral(R"(<derived name="Point"/>)"),
               QStringLiteral(R"(<structValue><value member="y">%1</value></structValue>)")
                   .arg(simple(QStringLiteral("-4"))))
        << QString() << QStringLiteral("Main.p") << QStringLiteral("(x := 3, y := -4)");
    QTest::newRow("enum") << QStringLiteral(
        R"(<dataType name="Color"><baseType><enum><values><value name="Red"/><value name="Green"/></values></enum></baseType><initialValue>%1</initialValue></dataType>)")
                                 .arg(simple(QStringLiteral("Green")))
                          << var(QStringLiteral("c"), QStringLiteral(R"(<derived name="Color"/>)")) << QString()
                          << QStringLiteral("Main.c") << QStringLiteral("Color#Green");
    QTest::newRow("array type with repetition")
        << QStringLiteral(
               R"(<dataType name="Row"><baseType><array><dimension lower="1" upper="4"/><baseType><INT/></baseType></array></baseType></dataType>)")
        << var(QStringLiteral("r"), QStringLiteral(R"(<derived name="Row"/>)"),
               QStringLiteral(R"(<arrayValue><value repetitionValue="2">%1</value><value>%2</value></arrayValue>)")
                   .arg(simple(QStringLiteral("7")), simple(QStringLiteral("9"))))
        << QStringLiteral("r[4] := r[1] + r[3];") << QStringLiteral("Main.r") << QStringLiteral("[7, 7, 9, 16]");
    QTest::newRow("subrange") << QStringLiteral(
        R"(<dataType name="Percent"><baseType><subrangeSigned><range lower="0" upper="100"/><baseType><INT/></baseType></subrangeSigned></baseType></dataType>)")
                              << var(QStringLiteral("v"), QStringLiteral(R"(<derived name="Percent"/>)"),
                                     simple(QStringLiteral("42")))
                              << QString() << QStringLiteral("Main.v") << QStringLiteral("42");
    QTest::newRow("alias of an elementary type")
        << QStringLiteral(
               R"(<dataType name="Speed"><baseType><REAL/></baseType><initialValue>%1</initialValue></dataType>)")
               .arg(simple(QStringLiteral("1.5")))
        << var(QStringLiteral("s"), QStringLiteral(R"(<derived name="Speed"/>)")) << QStringLiteral("s := s * 2.0;")
        << QStringLiteral("Main.s") << QStringLiteral("3.0");
    QTest::newRow("string with length") << QStringLiteral(
        R"(<dataType name="Name"><baseType><string length="4"/></baseType></dataType>)")
                                        << var(QStringLiteral("n"), QStringLiteral(R"(<derived name="Name"/>)"),
                                               simple(QStringLiteral("'ab'")))
                                        << QStringLiteral("n := CONCAT(n, 'c');") << QStringLiteral("Main.n")
                                        << QStringLiteral("'abc'");
    QTest::newRow("located variable") << QString()
                                      << QStringLiteral(
                                             R"(<variable name="q" address="%QX0.1"><type><BOOL/></type></variable>)")
                                      << QStringLiteral("q := TRUE;") << QStringLiteral("%QX0.1")
                                      << QStringLiteral("TRUE");
    QTest::newRow("two-dimensional array variable")
        << QString()
        << var(QStringLiteral("m"),
               QStringLiteral(
                   R"(<array><dimension lower="0" upper="1"/><dimension lower="0" upper="1"/><baseType><DINT/></baseType></array>)"),
               QStringLiteral(R"(<arrayValue><value repetitionValue="4">%1</value></arrayValue>)")
                   .arg(simple(QStringLiteral("5"))))
        << QStringLiteral("m[1, 0] := 8;") << QStringLiteral("Main.m") << QStringLiteral("[5, 5, 8, 5]");
}

void TestProjectSource::dataTypes()
{
    QFETCH(QString, dataTypes);
    QFETCH(QString, variables);
    QFETCH(QString, body);
    QFETCH(QString, name);
    QFETCH(QString, expected);

    const QString interface = QStringLiteral("<localVars>") + variables + QStringLiteral("</localVars>");
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(
        project(dataTypes, pou(QStringLiteral("Main"), QStringLiteral("program"), interface, body)), diagnostics);
    QCOMPARE(errors(diagnostics), QString());
    QVERIFY(module);
    Runtime runtime(module);
    QVERIFY(runtime.runCycle());
    QCOMPARE(runtime.read(name).value_or(QStringLiteral("no such variable")), expected);
}

void TestProjectSource::configurationRunsTasksAtTheirIntervals()
{
    const QString counter = pou(QStringLiteral("Counter"), QStringLiteral("program"),
        QStringLiteral("<externalVars>") + var(QStringLiteral("Total"), QStringLiteral("<DINT/>"))
            + QStringLiteral("</externalVars><localVars>") + var(QStringLiteral("n"), QStringLiteral("<INT/>"))
            + QStringLiteral("</localVars>"),
        QStringLiteral("n := n + 1;\nTotal := Total + 1;"));
    const QString configuration
        = QStringLiteral(R"(<configuration name="Plant">
          <resource name="Cpu">
            <task name="Fast" interval="T#10ms" priority="1"><pouInstance name="FastCount" typeName="Counter"/></task>
            <task name="Slow" interval="PT0.03S" priority="2"><pouInstance name="SlowCount" typeName="Counter"/></task>
            <globalVars>%1</globalVars>
          </resource>
        </configuration>)")
              .arg(var(QStringLiteral("Total"), QStringLiteral("<DINT/>"), simple(QStringLiteral("100"))));
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(project({}, counter, configuration), diagnostics);
    QCOMPARE(errors(diagnostics), QString());
    QVERIFY(module);
    Runtime runtime(module, 10'000'000);
    QVERIFY(runtime.runCycles(7)); // 0, 10, ..., 60 ms: the slow task runs at 0, 30 and 60 ms
    QCOMPARE(runtime.read(QStringLiteral("FastCount.n")).value(), QStringLiteral("7"));
    QCOMPARE(runtime.read(QStringLiteral("SlowCount.n")).value(), QStringLiteral("3"));
    QCOMPARE(runtime.read(QStringLiteral("Total")).value(), QStringLiteral("110"));
    QVERIFY(!runtime.find(QStringLiteral("Counter.n"))); // two instances: the name is ambiguous
}

void TestProjectSource::programNameStandsForItsOnlyInstance()
{
    const QString main = pou(QStringLiteral("Main"), QStringLiteral("program"),
        QStringLiteral("<localVars>") + var(QStringLiteral("n"), QStringLiteral("<INT/>"))
            + QStringLiteral("</localVars>"),
        QStringLiteral("n := n + 2;"));
    const QString configuration = QStringLiteral(R"(<configuration name="C"><resource name="R">
        <task name="T" interval="T#10ms" priority="0"><pouInstance name="Inst" typeName="Main"/></task>
        </resource></configuration>)");
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(project({}, main, configuration), diagnostics);
    QVERIFY(module);
    Runtime runtime(module);
    QVERIFY(runtime.runCycles(2));
    QCOMPARE(runtime.read(QStringLiteral("Inst.n")).value(), QStringLiteral("4"));
    QCOMPARE(runtime.read(QStringLiteral("Main.n")).value(), QStringLiteral("4"));
}

void TestProjectSource::projectWithoutConfigurationRunsItsProgram()
{
    const QString blinker = pou(QStringLiteral("Blinker"), QStringLiteral("program"),
        QStringLiteral("<localVars>") + var(QStringLiteral("on"), QStringLiteral("<BOOL/>"))
            + QStringLiteral("</localVars>"),
        QStringLiteral("on := NOT on;"));
    const QString helper = pou(QStringLiteral("Twice"), QStringLiteral("function"),
        QStringLiteral("<returnType><INT/></returnType><inputVars>")
            + var(QStringLiteral("x"), QStringLiteral("<INT/>")) + QStringLiteral("</inputVars>"),
        QStringLiteral("Twice := x * 2;"));
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(project({}, helper + blinker), diagnostics);
    QCOMPARE(errors(diagnostics), QString());
    QVERIFY(module);
    QCOMPARE(module->tasks.size(), size_t(1));
    Runtime runtime(module);
    QVERIFY(runtime.runCycles(3));
    QCOMPARE(runtime.read(QStringLiteral("Blinker.on")).value(), QStringLiteral("TRUE"));
}

// CODESYS exports each global variable list (GVL) as a named globalVars block and its programs
// write IO.Valve as well as Valve.
void TestProjectSource::namedGlobalListsQualifyTheirVariables()
{
    const QString main = pou(QStringLiteral("Main"), QStringLiteral("program"),
        QStringLiteral("<localVars>") + var(QStringLiteral("Valve"), QStringLiteral("<INT/>"))
            + QStringLiteral("</localVars>"),
        QStringLiteral("IO.Valve := IO.Valve OR Level > 5;\nValve := Valve + 1;\nHMI.Count := hmi.COUNT + 1;"));
    const QString configuration = QStringLiteral(R"(<configuration name="C"><resource name="R">
        <task name="T" interval="T#10ms" priority="0"><pouInstance name="Main" typeName="Main"/></task>
        <globalVars name="IO">%1%2</globalVars><globalVars name="HMI">%3</globalVars>
        </resource></configuration>)")
                                      .arg(var(QStringLiteral("Valve"), QStringLiteral("<BOOL/>")),
                                           var(QStringLiteral("Level"), QStringLiteral("<INT/>"), simple(QStringLiteral("7"))),
                                           var(QStringLiteral("Count"), QStringLiteral("<DINT/>")));
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(project({}, main, configuration), diagnostics);
    QCOMPARE(errors(diagnostics), QString());
    QVERIFY(module);
    Runtime runtime(module);
    QVERIFY(runtime.runCycles(3));
    // IO.Valve is the global; the program's own Valve is another variable.
    QCOMPARE(runtime.read(QStringLiteral("IO.Valve")).value(), QStringLiteral("TRUE"));
    QCOMPARE(runtime.read(QStringLiteral("Valve")).value(), QStringLiteral("TRUE"));
    QCOMPARE(runtime.read(QStringLiteral("Main.Valve")).value(), QStringLiteral("3"));
    QCOMPARE(runtime.read(QStringLiteral("hmi.count")).value(), QStringLiteral("3"));
    QVERIFY(!runtime.find(QStringLiteral("HMI.Valve"))); // not in that list
    QVERIFY(!runtime.find(QStringLiteral("IO")));

    const QString wrong = pou(QStringLiteral("Main"), QStringLiteral("program"), QString(), QStringLiteral("HMI.Valve := TRUE;"));
    Diagnostics wrongDiagnostics;
    QVERIFY(!frontend::compileProject(project({}, wrong, configuration), wrongDiagnostics));
    QCOMPARE(errors(wrongDiagnostics), QStringLiteral("Main:1:1: error: The global list HMI has no variable Valve."));
}

void TestProjectSource::bodyDiagnosticsAreLocatedInTheBody_data()
{
    QTest::addColumn<QString>("body");
    QTest::addColumn<QString>("language");
    QTest::addColumn<QString>("expected"); // every diagnostic: exactly one

    QTest::newRow("undeclared name on line 3")
        << QStringLiteral("n := 1;\n\n  n := m + 1;") << QStringLiteral("ST")
        << QStringLiteral("Main:3:8: error: Unknown variable 'm'. (hint: declare it in a VAR section)");
    QTest::newRow("= instead of :=")
        << QStringLiteral("n := 1;\nn = 2;") << QStringLiteral("ST")
        << QStringLiteral(
               "Main:2:1: error: '=' compares two values; to assign a value write ':='. (hint: write n := ...;)");
    QTest::newRow("IL operand type") << QStringLiteral("LD n\nADD TRUE\nST n") << QStringLiteral("IL")
                                     << QStringLiteral("Main:2:1: error: '+' cannot combine INT and BOOL. (hint: "
                                                       "convert it explicitly, e.g. BOOL_TO_INT(...))");
}

void TestProjectSource::bodyDiagnosticsAreLocatedInTheBody()
{
    QFETCH(QString, body);
    QFETCH(QString, language);
    QFETCH(QString, expected);

    const QString interface = QStringLiteral("<localVars>") + var(QStringLiteral("n"), QStringLiteral("<INT/>"))
        + QStringLiteral("</localVars>");
    Diagnostics diagnostics;
    QVERIFY(!frontend::compileProject(
        project({}, pou(QStringLiteral("Main"), QStringLiteral("program"), interface, body, language)), diagnostics));
    QCOMPARE(errors(diagnostics), expected);
}

void TestProjectSource::actionDiagnosticsNameTheAction()
{
    const QString main
        = QStringLiteral(R"(<pou name="Main" pouType="program"><interface><localVars>%1</localVars></interface>
        <actions><action name="Reset"><body><ST><xhtml:p><![CDATA[n := 0;
n := k;]]></xhtml:p></ST></body></action></actions>
        <body><ST><xhtml:p><![CDATA[n := n + 1;]]></xhtml:p></ST></body></pou>)")
              .arg(var(QStringLiteral("n"), QStringLiteral("<INT/>")));
    Diagnostics diagnostics;
    const auto unit = frontend::buildUnit(project({}, main), diagnostics);
    QCOMPARE(errors(diagnostics), QString());
    QCOMPARE(unit.unit.pous.front().actions.size(), size_t(1));
    QCOMPARE(unit.unit.pous.front().actions.front().name, QStringLiteral("Reset"));
    const auto &statements = unit.unit.pous.front().actions.front().body.statements;
    QCOMPARE(statements.size(), size_t(2));
    QCOMPARE(statements.back().location.line, 2);

    Diagnostics broken;
    const QString typo = QString(main).replace(QStringLiteral("n := k;"), QStringLiteral("n := := k;"));
    frontend::buildUnit(project({}, typo), broken);
    QCOMPARE(errors(broken),
        QStringLiteral("Main.Reset:2:6: error: Expected a value, a variable or a function call but found ':='."));
}

void TestProjectSource::graphicalPousAreNamed_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("LD") << QStringLiteral("LD");
    QTest::newRow("FBD") << QStringLiteral("FBD");
    QTest::newRow("SFC") << QStringLiteral("SFC");
}

void TestProjectSource::graphicalPousAreNamed()
{
    QFETCH(QString, language);
    const QString graphical
        = QStringLiteral(R"(<pou name="Drawn" pouType="functionBlock"><interface/><body><%1/></body></pou>)")
              .arg(language);
    const QString main = pou(QStringLiteral("Main"), QStringLiteral("program"),
        QStringLiteral("<localVars>") + var(QStringLiteral("d"), QStringLiteral(R"(<derived name="Drawn"/>)"))
            + QStringLiteral("</localVars>"),
        QStringLiteral("d();"));
    Diagnostics diagnostics;
    if (language != QLatin1String("SFC")) { // an empty LD or FBD body runs and does nothing
        QVERIFY(frontend::compileProject(project({}, graphical + main), diagnostics));
        QCOMPARE(errors(diagnostics), QString());
        return;
    }
    // An empty chart has no initial step (the SFC engine's own diagnostic).
    QVERIFY(!frontend::compileProject(project({}, graphical + main), diagnostics));
    QCOMPARE(errors(diagnostics),
        QStringLiteral("Drawn:0:0: error: The chart of Drawn has no initial step. "
                       "(hint: make one step the initial step (double frame))"));
}

QTEST_GUILESS_MAIN(TestProjectSource)
#include "tst_projectsource.moc"
