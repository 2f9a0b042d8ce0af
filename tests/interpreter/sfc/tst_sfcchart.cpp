// Structural diagnostics of SFC charts (interpreter/sfc/sfcgraph.h), located on the element:
// charts built as model values, element by element, with chosen localIds. Also the step options
// kept in a step's addData (model/sfcoptions.h) and the corpus's SFC POUs.
#include "interpreter/compiler/parser.h"
#include "interpreter/frontend/iecprinter.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"
#include "interpreter/sfc/sfcgraph.h"

#include "model/plcopen/reader.h"
#include "model/plcopen/writer.h"
#include "model/sfcoptions.h"

#include "chartelements.h"

#include <QTest>

using namespace iec;
using namespace iec::interp;
using namespace iec::testing::sfcchart;

Q_DECLARE_METATYPE(iec::model::Pou)
Q_DECLARE_METATYPE(iec::model::StepOptions)

class TestSfcChart : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void diagnostics_data();
    void diagnostics();
    void loopingDivergencesDoNotHang();
    void inlineConditionErrorsPointAtTheTransition_data();
    void inlineConditionErrorsPointAtTheTransition();
    void macroStepRunsItsBody();
    void stepOptionsRoundTrip_data();
    void stepOptionsRoundTrip();
    void stepOptionsKeepOtherAddData();
    void stepOptionsSurviveThePlcopenFile();
    void textualSfcRoundTrips();
    void textualChartCompilesStraightFromText();
    void corpusChartsCompileOrNameTheFeature_data();
    void corpusChartsCompileOrNameTheFeature();
};

namespace {

// "localId: message" per error.
QStringList errors(const model::Pou &pou)
{
    Diagnostics diagnostics;
    sfc::buildChart(*pou.body(), pou.name, diagnostics);
    QStringList lines;
    for (const Diagnostic &d : diagnostics.all())
        lines << QStringLiteral("%1: %2").arg(d.location.localId).arg(d.message);
    return lines;
}

} // namespace

void TestSfcChart::diagnostics_data()
{
    QTest::addColumn<model::Pou>("pou");
    QTest::addColumn<QStringList>("expected");

    QTest::newRow("correct") << chart(loop()) << QStringList {};
    auto noInitial = loop();
    std::get<model::Step>(noInitial[0]).initialStep = false;
    QTest::newRow("no initial step") << chart(noInitial) << QStringList {QStringLiteral("-1: The chart of Main has no initial step.")};
    auto twoInitial = loop();
    std::get<model::Step>(twoInitial[2]).initialStep = true;
    QTest::newRow("two initial steps")
        << chart(twoInitial) << QStringList {QStringLiteral("3: Step S1 is a second initial step; a chart has exactly one (the first is Init).")};
    auto deadEnd = loop();
    deadEnd.resize(3);
    QTest::newRow("step without transition") << chart(deadEnd) << QStringList {QStringLiteral("3: Step S1 has no transition after it.")};
    auto nowhere = loop();
    nowhere.resize(4);
    QTest::newRow("transition without step") << chart(nowhere) << QStringList {QStringLiteral("4: This transition leads to no step.")};
    auto unknownJump = loop();
    std::get<model::JumpStep>(unknownJump[4]).targetName = QStringLiteral("Start");
    QTest::newRow("jump to unknown step") << chart(unknownJump)
                                          << QStringList {QStringLiteral("5: The jump goes to step Start, which the chart does not have."),
                                                 QStringLiteral("4: This transition leads to no step.")};
    auto noCondition = loop();
    std::get<model::Transition>(noCondition[1]).condition.reset();
    QTest::newRow("no condition") << chart(noCondition) << QStringList {QStringLiteral("2: This transition has no condition.")};
    auto twoNames = loop();
    std::get<model::Step>(twoNames[2]).name = QStringLiteral("init");
    QTest::newRow("two steps with one name")
        << chart(twoNames) << QStringList {QStringLiteral("3: Two steps are called init; every step of a chart needs its own name.")};
    // A simultaneous divergence right after a step (it belongs after a transition).
    QTest::newRow("parallel branch after a step")
        << chart({step(1, QStringLiteral("Init"), {}, true), split<model::SimultaneousDivergence>(2, 1), transition(3, 2),
               transition(4, 2), step(5, QStringLiteral("A"), 3), step(6, QStringLiteral("B"), 4), transition(7, 5),
               transition(8, 6), jump(9, 7, QStringLiteral("Init")), jump(10, 8, QStringLiteral("Init"))})
        << QStringList {QStringLiteral("3: A transition must come after a step, a selection divergence or a simultaneous convergence, not after a simultaneous divergence."),
               QStringLiteral("4: A transition must come after a step, a selection divergence or a simultaneous convergence, not after a simultaneous divergence."),
               QStringLiteral("2: Each branch of a simultaneous divergence must begin with a step, not a transition."),
               QStringLiteral("2: Each branch of a simultaneous divergence must begin with a step, not a transition."),
               QStringLiteral("2: A simultaneous divergence must come after a transition, not after a step."),
               QStringLiteral("1: Step Init has no transition after it."), QStringLiteral("3: This transition has no step before it."),
               QStringLiteral("4: This transition has no step before it.")};
    // A selection divergence closed by a simultaneous convergence.
    QTest::newRow("alternative branches joined as parallel")
        << chart({step(1, QStringLiteral("Init"), {}, true), split<model::SelectionDivergence>(2, 1), transition(3, 2),
               transition(4, 2), step(5, QStringLiteral("A"), 3), step(6, QStringLiteral("B"), 4),
               join<model::SimultaneousConvergence>(7, {5, 6}), transition(8, 7), jump(9, 8, QStringLiteral("Init"))})
        << QStringList {};
    QTest::newRow("selection convergence before a transition")
        << chart({step(1, QStringLiteral("Init"), {}, true), split<model::SelectionDivergence>(2, 1), transition(3, 2),
               transition(4, 2), step(5, QStringLiteral("A"), 3), step(6, QStringLiteral("B"), 4),
               join<model::SelectionConvergence>(7, {5, 6}), transition(8, 7), jump(9, 8, QStringLiteral("Init"))})
        << QStringList {QStringLiteral("8: A transition must come after a step, a selection divergence or a simultaneous convergence, not after a selection convergence."),
               QStringLiteral("7: Each branch of a selection convergence must end with a transition, not a step."),
               QStringLiteral("7: Each branch of a selection convergence must end with a transition, not a step."),
               QStringLiteral("7: A selection convergence must lead to a step, not to a transition."),
               QStringLiteral("5: Step A has no transition after it."), QStringLiteral("6: Step B has no transition after it."),
               QStringLiteral("8: This transition has no step before it.")};
}

void TestSfcChart::diagnostics()
{
    QFETCH(model::Pou, pou);
    QFETCH(QStringList, expected);
    QStringList actual = errors(pou);
    actual.sort();
    expected.sort();
    QCOMPARE(actual.join(QLatin1Char('\n')), expected.join(QLatin1Char('\n')));
}

void TestSfcChart::inlineConditionErrorsPointAtTheTransition_data()
{
    QTest::addColumn<QString>("condition");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("message");
    QTest::newRow("operand missing at the end") << QStringLiteral("go AND") << 7
                                                << QStringLiteral("The condition go AND is incomplete: something is missing at its end.");
    QTest::newRow("stray token") << QStringLiteral("go ) OR go") << 4 << QString();
    QTest::newRow("second line") << QStringLiteral("go OR\n  go AND )") << 16 << QString();
}

void TestSfcChart::inlineConditionErrorsPointAtTheTransition()
{
    // Issue 13: "Main, line 2, column 1 ... found ';'" named neither the transition nor a place
    // in what was typed. Inline condition of transition 2; the error is on 2, at a column of the text.
    QFETCH(QString, condition);
    QFETCH(int, column);
    QFETCH(QString, message);
    model::Pou pou = chart(loop());
    model::Body text = model::Body::withLanguage(model::BodyLanguage::ST);
    text.setText(condition);
    model::InlineCondition inl;
    inl.body = text;
    std::get<model::Transition>(pou.bodies.front().elements()->at(1)).condition = model::Condition {false, inl};
    model::Variable go;
    go.name = QStringLiteral("go");
    go.type.kind = model::ElementaryType {QStringLiteral("BOOL")};
    model::Interface interface;
    interface.varLists.push_back({});
    interface.varLists.front().variables.push_back(go);
    pou.pouInterface = interface;
    model::Project project;
    project.types.pous.push_back(pou);
    Diagnostics diagnostics;
    QVERIFY(!frontend::compileProject(project, diagnostics));
    QVERIFY(!diagnostics.all().empty());
    const Diagnostic &first = diagnostics.all().front();
    QCOMPARE(first.pou, QStringLiteral("Main"));
    QCOMPARE(first.location.localId, qint64(2));
    QCOMPARE(first.location.line, 0);
    QCOMPARE(first.location.column, column);
    if (!message.isEmpty())
        QCOMPARE(first.message, message);
}

void TestSfcChart::loopingDivergencesDoNotHang()
{
    // A broken file: a simultaneous divergence fed by a selection convergence fed by itself.
    model::Element fork = split<model::SimultaneousDivergence>(3, 5);
    model::Element merge = join<model::SelectionConvergence>(5, {2, 3});
    const QStringList found = errors(chart({step(1, QStringLiteral("Init"), {}, true), transition(2, 1), fork, merge}));
    QVERIFY(found.contains(QStringLiteral("2: This transition leads to no step.")));
}

void TestSfcChart::macroStepRunsItsBody()
{
    // Init -go-> Macro{M1 -TRUE-> M2} -TRUE-> jump Init: the macro is active while M1 or M2 is.
    model::MacroStep macro;
    macro.localId = 3;
    macro.name = QStringLiteral("Fill");
    macro.connectionPointIn = from(2);
    model::Body inner = model::Body::withLanguage(model::BodyLanguage::SFC);
    *inner.elements() = {step(1, QStringLiteral("M1"), {}, true), transition(2, 1), step(3, QStringLiteral("M2"), 2)};
    macro.body = inner;
    model::Pou pou = chart({step(1, QStringLiteral("Init"), {}, true), transition(2, 1, QStringLiteral("go")), macro,
        transition(4, 3), jump(5, 4, QStringLiteral("Init"))});
    model::Interface interface;
    model::VarList vars;
    model::Variable go;
    go.name = QStringLiteral("go");
    go.type.kind = model::ElementaryType {QStringLiteral("BOOL")};
    vars.variables.push_back(go);
    interface.varLists.push_back(vars);
    pou.pouInterface = interface;
    QCOMPARE(errors(pou), QStringList {});
    model::Project project;
    project.types.pous.push_back(pou);
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(project, diagnostics);
    QVERIFY2(module, qPrintable(diagnostics.all().empty() ? QString() : diagnostics.all().front().toString()));
    Runtime runtime(module);
    const auto active = [&](const char *name) { return runtime.read(QStringLiteral("Main.") + QLatin1String(name)).value_or(QString()); };
    QVERIFY(runtime.write(QStringLiteral("Main.go"), QStringLiteral("TRUE")) == std::nullopt);
    QVERIFY(runtime.runCycle()); // Init
    QVERIFY(runtime.runCycle());
    QCOMPARE(active("M1.x"), QStringLiteral("TRUE"));
    QCOMPARE(active("Fill.x"), QStringLiteral("TRUE"));
    QVERIFY(runtime.runCycle());
    QCOMPARE(active("M2.x"), QStringLiteral("TRUE"));
    QCOMPARE(active("Fill.x"), QStringLiteral("TRUE"));
    QVERIFY(runtime.runCycle());
    QCOMPARE(active("Init.x"), QStringLiteral("TRUE"));
    QCOMPARE(active("Fill.x"), QStringLiteral("FALSE"));
}

void TestSfcChart::stepOptionsRoundTrip_data()
{
    QTest::addColumn<model::StepOptions>("options");
    QTest::newRow("default") << model::StepOptions {};
    QTest::newRow("simplified") << model::StepOptions {true, {}, {}, QStringLiteral("Run"), {}, {}};
    QTest::newRow("all") << model::StepOptions {false, QStringLiteral("In"), QStringLiteral("Out"), QStringLiteral("Run"),
        QStringLiteral("T#1s"), QStringLiteral("tMax")};
    QTest::newRow("characters that need escaping")
        << model::StepOptions {false, QStringLiteral("A<B"), QStringLiteral("\"q\""), {}, QStringLiteral("T#1s&"), {}};
}

void TestSfcChart::stepOptionsRoundTrip()
{
    QFETCH(model::StepOptions, options);
    model::Step step;
    model::setStepOptions(step, options);
    QCOMPARE(step.addData.empty(), options.isDefault());
    QCOMPARE(model::stepOptions(step), options);
    model::setStepOptions(step, {}); // back to default: the entry goes
    QVERIFY(step.addData.empty());
}

void TestSfcChart::stepOptionsKeepOtherAddData()
{
    model::Step step;
    step.addData.push_back({QStringLiteral("http://vendor/x"), QStringLiteral("preserve"), QStringLiteral("<x/>")});
    model::setStepOptions(step, {false, QStringLiteral("In"), {}, {}, {}, {}});
    model::setStepOptions(step, {false, QStringLiteral("In2"), {}, {}, {}, {}});
    QCOMPARE(step.addData.size(), size_t(2));
    QCOMPARE(step.addData.front().content, QStringLiteral("<x/>"));
    QCOMPARE(model::stepOptions(step).entryAction, QStringLiteral("In2"));
    step.addData.back().content = QStringLiteral("<broken");
    QCOMPARE(model::stepOptions(step), model::StepOptions {}); // malformed: defaults, no crash
}

void TestSfcChart::textualSfcRoundTrips()
{
    // .st -> model (graphical SFC with divergences) -> .st gives the chart back.
    const QString source = QStringLiteral(
        "PROGRAM Main\nVAR\n    go : BOOL;\n    n : INT;\nEND_VAR\n"
        "INITIAL_STEP Init:\nEND_STEP\n"
        "STEP A1:\n    Count(L, T#2s);\n    Lamp(N);\nEND_STEP\n"
        "STEP B1:\nEND_STEP\n"
        "STEP C1:\nEND_STEP\n"
        "TRANSITION FROM Init TO (A1, B1) := go; END_TRANSITION\n"
        "TRANSITION (PRIORITY := 1) FROM Init TO C1 := NOT go; END_TRANSITION\n"
        "TRANSITION FROM (A1, B1) TO Init:\n    LD n\n    GT 3\nEND_TRANSITION\n"
        "TRANSITION FROM C1 TO Init := TRUE; END_TRANSITION\n"
        "ACTION Count:\n    n := n + 1;\nEND_ACTION\n"
        "END_PROGRAM\n");
    const auto first = frontend::readIecText(source, QStringLiteral("t"));
    QCOMPARE(first.diagnostics.all().size(), size_t(0));
    QCOMPARE(first.project.types.pous.size(), size_t(1));
    const model::Pou &pou = first.project.types.pous.front();
    QCOMPARE(pou.language(), model::BodyLanguage::SFC);
    QCOMPARE(pou.actions.size(), size_t(1));
    std::vector<frontend::PrintWarning> warnings;
    const QString printed = frontend::printPou(pou, &warnings);
    QCOMPARE(warnings.size(), size_t(0));
    // Transitions come out in priority order: the explicit priority first.
    QCOMPARE(printed,
        QStringLiteral("PROGRAM Main\nVAR\n    go : BOOL;\n    n : INT;\nEND_VAR\n"
                       "INITIAL_STEP Init:\nEND_STEP\n"
                       "STEP A1:\n    Count(L, T#2s);\n    Lamp(N);\nEND_STEP\n"
                       "STEP B1:\nEND_STEP\n"
                       "STEP C1:\nEND_STEP\n"
                       "TRANSITION (PRIORITY := 1) FROM Init TO C1 := NOT go; END_TRANSITION\n"
                       "TRANSITION FROM Init TO (A1, B1) := go; END_TRANSITION\n"
                       "TRANSITION FROM (A1, B1) TO Init:\n    LD n\n    GT 3\nEND_TRANSITION\n"
                       "TRANSITION FROM C1 TO Init := TRUE; END_TRANSITION\n"
                       "ACTION Count:\n    n := n + 1;\nEND_ACTION\n"
                       "END_PROGRAM\n"));
    const auto second = frontend::readIecText(printed, QStringLiteral("t"));
    // Read again: the same lines (transitions that share no step may come in another order, as
    // the generated layout places them; their order does not matter).
    QStringList again = frontend::printPou(second.project.types.pous.front()).split(QLatin1Char('\n'));
    QStringList once = printed.split(QLatin1Char('\n'));
    again.sort();
    once.sort();
    QCOMPARE(again, once);
}

void TestSfcChart::stepOptionsSurviveThePlcopenFile()
{
    // The mixing tank with entry/exit/active actions and times written into the file and read back.
    auto read = model::plcopen::readProjectFile(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/mixing_tank.xml"));
    QVERIFY(read.ok);
    const model::StepOptions options {false, QStringLiteral("ClearStop"), QStringLiteral("Watch"), QStringLiteral("Watch"),
        QStringLiteral("T#1s"), QStringLiteral("MixTime")};
    for (model::Element &e : *read.project.types.pous.front().bodies.front().elements()) {
        if (auto *s = std::get_if<model::Step>(&e); s && s->name == QLatin1String("Mixing"))
            model::setStepOptions(*s, options);
    }
    const auto again = model::plcopen::readProject(model::plcopen::writeProject(read.project));
    QVERIFY(again.ok);
    bool found = false;
    for (const model::Element &e : *again.project.types.pous.front().bodies.front().elements()) {
        if (const auto *s = std::get_if<model::Step>(&e)) {
            found = found || s->name == QLatin1String("Mixing");
            QCOMPARE(model::stepOptions(*s), s->name == QLatin1String("Mixing") ? options : model::StepOptions {});
        }
    }
    QVERIFY(found);
}

void TestSfcChart::textualChartCompilesStraightFromText()
{
    // iecstudio-cli run chart.st parses the text into a unit without the model: compileUnit
    // lowers its charts, with the parsed ACTION bodies.
    const QString source = QStringLiteral(
        "PROGRAM Main\nVAR go : BOOL; n : INT; END_VAR\n"
        "INITIAL_STEP Init: END_STEP\n"
        "TRANSITION FROM Init TO Run := go; END_TRANSITION\n"
        "STEP Run: Count(N); END_STEP\n"
        "TRANSITION FROM Run TO Init := NOT go; END_TRANSITION\n"
        "ACTION Count: n := n + 1; END_ACTION\n"
        "END_PROGRAM\n");
    Diagnostics diagnostics;
    frontend::ProjectUnit unit {parseUnit(source, diagnostics), false};
    QVERIFY(!diagnostics.hasErrors());
    const auto module = frontend::compileUnit(unit, diagnostics);
    QVERIFY2(module, qPrintable(diagnostics.all().empty() ? QString() : diagnostics.all().front().toString()));
    QCOMPARE(diagnostics.all().size(), size_t(0));
    Runtime runtime(module);
    QVERIFY(runtime.write(QStringLiteral("Main.go"), QStringLiteral("TRUE")) == std::nullopt);
    QVERIFY(runtime.runCycles(4));
    QCOMPARE(runtime.read(QStringLiteral("Main.Run.x")).value_or(QString()), QStringLiteral("TRUE"));
    QCOMPARE(runtime.read(QStringLiteral("Main.n")).value_or(QString()), QStringLiteral("3"));
}

void TestSfcChart::corpusChartsCompileOrNameTheFeature_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("check");    // "compiles" or only "structure"
    QTest::addColumn<QString>("expected"); // the errors of its SFC POUs
    // The CODESYS test file uses an INT variable as an action: a warning, the INT is 1 while the
    // action is active.
    QTest::newRow("CODESYS test chart") << "codesys35sp18_sfc_test.xml" << "compiles" << "";
    QTest::newRow("Beremiz first steps") << "beremiz_first_steps.xml" << "compiles" << "";
    // Its LD action and FBD transition go through the graphical lowering, checked elsewhere.
    QTest::newRow("Beremiz traffic light") << "beremiz_svghmi_traffic_light.xml" << "structure" << "";
    QTest::newRow("TwinCAT PPU") << "twincat356_ppu.xml" << "compiles" << "";
}

void TestSfcChart::corpusChartsCompileOrNameTheFeature()
{
    QFETCH(QString, file);
    QFETCH(QString, check);
    QFETCH(QString, expected);
    const auto read = model::plcopen::readProjectFile(QStringLiteral(IEC_SHARED_DIR "/plcopen/corpus/") + file);
    QVERIFY2(read.ok, qPrintable(file));
    Diagnostics structure;
    int charts = 0;
    for (const model::Pou &p : read.project.types.pous) {
        if (p.language() == model::BodyLanguage::SFC) {
            sfc::buildChart(*p.body(), p.name, structure);
            ++charts;
        }
    }
    QVERIFY2(charts > 0, "the file has no chart to check");
    QCOMPARE(structure.hasErrors(), false);
    if (check == QLatin1String("structure"))
        return;
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(read.project, diagnostics);
    if (expected.isEmpty())
        QVERIFY2(module, "expected to compile");
    QStringList sfcErrors;
    for (const model::Pou &p : read.project.types.pous) {
        if (p.language() != model::BodyLanguage::SFC)
            continue;
        for (const Diagnostic &d : diagnostics.all()) {
            if (d.severity == Diagnostic::Severity::Error && d.pou.startsWith(p.name))
                sfcErrors << d.message;
        }
    }
    QCOMPARE(sfcErrors.join(QLatin1Char('\n')), expected);
}

QTEST_GUILESS_MAIN(TestSfcChart)
#include "tst_sfcchart.moc"
