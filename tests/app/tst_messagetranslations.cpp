// Every message the compiler and the runtime show is translated (issue 13): faulty programs in
// each language of the project (ST, IL, LD, FBD, SFC, textual SFC, configurations) and programs
// that fault while running are compiled and run once without a translator and once with each
// shipped .qm (the ones the application embeds under :/i18n); every message and hint must differ
// from its English text. A message built with QStringLiteral instead of
// QCoreApplication::translate, or one whose translation is missing from the .ts, fails here.
#include "interpreter/frontend/iecprinter.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"

#include "editors/cfc/cfcedits.h"
#include "editors/common/diagramclipboard.h"
#include "model/plcopen/fragment.h"
#include "model/sfcoptions.h"

#include "../interpreter/graphical/diagram.h"
#include "../interpreter/sfc/chartelements.h"

#include <QCoreApplication>
#include <QMimeData>
#include <QTest>
#include <QTranslator>

#include <functional>

using namespace iec;
using namespace iec::interp;
using namespace iec::testing;
using Messages = std::function<QStringList()>;

Q_DECLARE_METATYPE(Messages)

class TestMessageTranslations : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void messagesAreTranslated_data();
    void messagesAreTranslated();
};

namespace {

void addDiagnostics(QStringList &messages, const Diagnostics &diagnostics)
{
    for (const Diagnostic &d : diagnostics.all()) {
        messages << d.message;
        if (!d.hint.isEmpty())
            messages << d.hint;
    }
}

// The compiler's messages for `project`; when it compiles, the runtime's fault after `cycles`.
QStringList compileAndRun(const model::Project &project, int cycles = 0)
{
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(project, diagnostics);
    QStringList messages;
    addDiagnostics(messages, diagnostics);
    if (module && cycles > 0) {
        Runtime runtime(module);
        runtime.runCycles(cycles);
        if (runtime.fault())
            messages << runtime.fault()->message;
    }
    return messages;
}

// IEC text read into the model (its reader's warnings count), then compiled and run.
Messages text(const QString &source, int cycles = 0)
{
    return [source, cycles] {
        const auto read = frontend::readIecText(source, QStringLiteral("t"));
        QStringList messages;
        addDiagnostics(messages, read.diagnostics);
        return messages + compileAndRun(read.project, cycles);
    };
}

Messages diagram(const QString &declarations, model::BodyLanguage language, const Diagram &d)
{
    return [=] { return compileAndRun(diagramProject(declarations, language, d)); };
}

Messages sfcProgram(std::vector<model::Element> elements, const QString &declarations = QStringLiteral("VAR x : BOOL; END_VAR"))
{
    Diagram d;
    d.elements = std::move(elements);
    return diagram(declarations, model::BodyLanguage::SFC, d);
}

// What writing `literal` into each variable of Main answers (online write and force).
Messages writes(const QString &declarations, const std::vector<std::pair<QString, QString>> &literals)
{
    return [=] {
        Diagnostics diagnostics;
        const auto module = compileText(QString(QStringLiteral("PROGRAM Main\n") + declarations + QStringLiteral("\nEND_PROGRAM\n")), diagnostics);
        QStringList messages;
        if (!module)
            return QStringList {QStringLiteral("does not compile: ") + diagnostics.all().front().toString()};
        Runtime runtime(module);
        for (const auto &[name, literal] : literals) {
            if (const auto problem = runtime.write(name, literal))
                messages << *problem;
        }
        return messages;
    };
}

QString program(const QString &declarations, const QString &body)
{
    return QStringLiteral("PROGRAM Main\n%1\n%2\nEND_PROGRAM\n").arg(declarations, body);
}

} // namespace

void TestMessageTranslations::messagesAreTranslated_data()
{
    QTest::addColumn<Messages>("messages");
    QTest::addColumn<int>("count"); // how many messages the English run gives: the row still tests what it says

    const QString boolVars = QStringLiteral("VAR a, b, x : BOOL; n : INT; END_VAR");
    // ST: parser and type checker.
    QTest::newRow("st syntax") << text(program(boolVars, QStringLiteral("IF a THEN x := ; END_IF;"))) << 2;
    QTest::newRow("st types") << text(program(QStringLiteral("VAR x : BOOL; n : INT; r : REAL; END_VAR"),
                                     QStringLiteral("x := n; n := r; y := 1; n := UNKNOWN_FN(1);"))) << 7;
    QTest::newRow("st program not a type")
        << text(QStringLiteral("PROGRAM Other\nEND_PROGRAM\n") + program(QStringLiteral("VAR o : Other; END_VAR"), QString())) << 1;
    QTest::newRow("il") << text(QStringLiteral("PROGRAM Main\nVAR x : BOOL; END_VAR\nLD x\nFROB x\nEND_PROGRAM\n")) << 1;
    QTest::newRow("configuration")
        << text(program(QStringLiteral("VAR_EXTERNAL g : INT; END_VAR"), QString())
                + QStringLiteral("VAR_GLOBAL h : INT; END_VAR\nCONFIGURATION C\nVAR_CONFIG cx : INT; END_VAR\n"
                                 "RESOURCE R ON PLC\nTASK T(INTERVAL := T#10ms, PRIORITY := 70000);\n"
                                 "PROGRAM P WITH T : Main(n := 1);\nPROGRAM Q WITH T : Nothing;\nEND_RESOURCE\nEND_CONFIGURATION\n"))
        << 7;
    // Runtime faults.
    QTest::newRow("division by zero") << text(program(QStringLiteral("VAR n, zero : INT; END_VAR"), QStringLiteral("n := 10 / zero;")), 1) << 1;
    QTest::newRow("array index")
        << text(program(QStringLiteral("VAR a : ARRAY[0..2] OF INT; i : INT := 5; END_VAR"), QStringLiteral("a[i] := 1;")), 1) << 1;
    QTest::newRow("null pointer")
        << text(program(QStringLiteral("VAR p : POINTER TO INT; n : INT; END_VAR"), QStringLiteral("n := p^;")), 1) << 1;
    QTest::newRow("online writes")
        << writes(QStringLiteral("VAR n : INT; s : STRING(3); r : REAL; b : BYTE; END_VAR"),
               {{QStringLiteral("Main.n"), QStringLiteral("abc")}, {QStringLiteral("Main.n"), QStringLiteral("40000")},
                   {QStringLiteral("Main.s"), QStringLiteral("'toolong'")}, {QStringLiteral("Main.r"), QStringLiteral("1E39")},
                   {QStringLiteral("Main.b"), QStringLiteral("16#1FF")}, {QStringLiteral("Main.nope"), QStringLiteral("1")}})
        << 6;

    // SFC structure: the warnings of issue 13 and the chart's errors.
    using namespace sfcchart;
    QTest::newRow("sfc one alternative branch")
        << sfcProgram({step(1, QStringLiteral("Init"), {}, true), split<model::SelectionDivergence>(2, 1), transition(3, 2),
               step(4, QStringLiteral("S1"), 3), transition(5, 4), join<model::SelectionConvergence>(6, {5}),
               step(7, QStringLiteral("S2"), 6), transition(8, 7), jump(9, 8, QStringLiteral("Init"))})
        << 2;
    QTest::newRow("sfc one parallel branch")
        << sfcProgram({step(1, QStringLiteral("Init"), {}, true), transition(2, 1), split<model::SimultaneousDivergence>(3, 2),
               step(4, QStringLiteral("S1"), 3), join<model::SimultaneousConvergence>(5, {4}), transition(6, 5),
               jump(7, 6, QStringLiteral("Init"))})
        << 2;
    QTest::newRow("sfc parallel branch after a step")
        << sfcProgram({step(1, QStringLiteral("Init"), {}, true), split<model::SimultaneousDivergence>(2, 1), transition(3, 2),
               transition(4, 2), step(5, QStringLiteral("A"), 3), step(6, QStringLiteral("B"), 4), transition(7, 5),
               transition(8, 6), jump(9, 7, QStringLiteral("Init")), jump(10, 8, QStringLiteral("Init"))})
        << 11;
    QTest::newRow("sfc selection convergence before a transition")
        << sfcProgram({step(1, QStringLiteral("Init"), {}, true), split<model::SelectionDivergence>(2, 1), transition(3, 2),
               transition(4, 2), step(5, QStringLiteral("A"), 3), step(6, QStringLiteral("B"), 4),
               join<model::SelectionConvergence>(7, {5, 6}), transition(8, 7), jump(9, 8, QStringLiteral("Init"))})
        << 10;
    auto noInitial = loop();
    std::get<model::Step>(noInitial[0]).initialStep = false;
    QTest::newRow("sfc no initial step") << sfcProgram(noInitial) << 2;
    auto broken = loop();
    std::get<model::Step>(broken[2]).initialStep = true;
    std::get<model::JumpStep>(broken[4]).targetName = QStringLiteral("Start");
    std::get<model::Transition>(broken[1]).condition.reset();
    QTest::newRow("sfc second initial step, unknown jump, no condition") << sfcProgram(broken) << 6;
    auto actions = loop();
    actions.push_back(actionBlock(6, 3, {{QStringLiteral("L"), QStringLiteral("x"), {}},
                                            {QStringLiteral("Q"), QStringLiteral("x"), {}}}));
    QTest::newRow("sfc actions") << sfcProgram(actions) << 2;
    auto timed = loop();
    model::setStepOptions(std::get<model::Step>(timed[2]),
        {.entryAction = QStringLiteral("Fill_exit"), .minTime = QStringLiteral("soon +"), .maxTime = QStringLiteral("later +")});
    timed.push_back(actionBlock(6, 3, {{QStringLiteral("D"), QStringLiteral("x"), QStringLiteral("nonsense +")}}));
    QTest::newRow("sfc step options and times") << sfcProgram(timed) << 8;

    QTest::newRow("textual sfc")
        << text(QStringLiteral("PROGRAM Main\nVAR x : BOOL; END_VAR\nINITIAL_STEP Init: END_STEP\nSTEP Init: END_STEP\n"
                               "TRANSITION FROM Init TO Nowhere := x; END_TRANSITION\nEND_PROGRAM\n"))
        << 7;

    // LD and FBD.
    using model::BodyLanguage;
    QTest::newRow("ld unwired contact and coil")
        << diagram(boolVars, BodyLanguage::LD, Diagram().rail(1).contact(2, QStringLiteral("a"), {}).coil(3, QStringLiteral("x"), {})) << 2;
    QTest::newRow("fbd open input and output")
        << diagram(boolVars, BodyLanguage::FBD,
               Diagram().in(1, QStringLiteral("a")).block(2, QStringLiteral("AND"), {}, {{QStringLiteral("IN1"), {{1}}}, {QStringLiteral("IN2"), {}}}, {QStringLiteral("OUT")})
                   .out(3, QStringLiteral("x"), {{2, QStringLiteral("OUT")}}).out(4, QStringLiteral("b"), {}))
        << 4;
    QTest::newRow("fbd continuation without connector")
        << diagram(boolVars, BodyLanguage::FBD, Diagram().continuation(1, QStringLiteral("c")).out(2, QStringLiteral("x"), {{1}}))
        << 2;
    QTest::newRow("fbd jump to a missing label")
        << diagram(boolVars, BodyLanguage::FBD, Diagram().in(1, QStringLiteral("a")).jump(2, QStringLiteral("Nowhere"), {{1}}))
        << 2;
    QTest::newRow("fbd two labels with one name")
        << diagram(boolVars, BodyLanguage::FBD,
               Diagram().label(1, QStringLiteral("L"), 100).label(2, QStringLiteral("L"), 200).in(3, QStringLiteral("a"), 0, 300)
                   .out(4, QStringLiteral("x"), {{3}}, 500, 300))
        << 2;
    QTest::newRow("fbd bad variables")
        << diagram(boolVars, BodyLanguage::FBD,
               Diagram().in(1, QString()).out(2, QStringLiteral("x"), {{1}}).in(3, QStringLiteral("a +")).out(4, QStringLiteral("b"), {{3}}))
        << 4;
    QTest::newRow("fbd loop")
        << diagram(boolVars, BodyLanguage::FBD,
               Diagram().in(1, QStringLiteral("a"))
                   .block(2, QStringLiteral("AND"), {}, {{QStringLiteral("IN1"), {{1}}}, {QStringLiteral("IN2"), {{3, QStringLiteral("OUT")}}}}, {QStringLiteral("OUT")})
                   .block(3, QStringLiteral("OR"), {}, {{QStringLiteral("IN1"), {{2, QStringLiteral("OUT")}}}, {QStringLiteral("IN2"), {{1}}}}, {QStringLiteral("OUT")})
                   .out(4, QStringLiteral("x"), {{3, QStringLiteral("OUT")}}))
        << 2;
    QTest::newRow("fbd duplicate localId")
        << diagram(boolVars, BodyLanguage::FBD, Diagram().in(1, QStringLiteral("a")).out(1, QStringLiteral("x"), {})) << 2;
    QTest::newRow("fbd wire from nowhere")
        << diagram(boolVars, BodyLanguage::FBD, Diagram().out(1, QStringLiteral("x"), {{99}}).out(2, QStringLiteral("b"), {{1}})) << 1;
    Diagram withStep;
    withStep.elements.push_back(step(1, QStringLiteral("S")));
    QTest::newRow("fbd step in a network") << diagram(boolVars, BodyLanguage::FBD, withStep) << 1;

    // Printing a graphical body as IEC text (iecstudio-cli convert).
    QTest::newRow("print ld as text") << Messages([boolVars] {
        std::vector<frontend::PrintWarning> warnings;
        frontend::printProject(diagramProject(boolVars, BodyLanguage::LD, Diagram().rail(1)), &warnings);
        QStringList messages;
        for (const frontend::PrintWarning &w : warnings)
            messages << w.message;
        return messages;
    }) << 1;

    // What the diagram editors refuse, and what a paste of foreign data says.
    QTest::newRow("cfc edits refused") << Messages([] {
        std::vector<model::Element> none;
        return QStringList {editors::cfc::deleteElements(none, {}).error, editors::cfc::setOrderNumber(none, 1, 1).error,
            editors::cfc::moveInOrder(none, {1}, editors::cfc::OrderMove::Earlier).error,
            editors::cfc::connectPins(none, 1, std::nullopt, 2, 0).error};
    }) << 4;
    QTest::newRow("paste of foreign data") << Messages([] {
        QMimeData text;
        text.setText(QStringLiteral("x := 1;"));
        return QStringList {model::plcopen::readElementsFragment("<other/>").error,
            editors::elementsFromMimeData(&text, editors::EditorLanguage::CFC, 1).error};
    }) << 2;
}

void TestMessageTranslations::messagesAreTranslated()
{
    QFETCH(Messages, messages);
    QFETCH(int, count);
    const QStringList english = messages();
    QVERIFY2(english.size() == count, qPrintable(english.join(QLatin1Char('\n'))));
    for (const QString &locale : {QStringLiteral("de"), QStringLiteral("zh_CN")}) {
        QTranslator translator;
        QVERIFY2(translator.load(QStringLiteral(":/i18n/iecstudio_%1.qm").arg(locale)), qPrintable(locale));
        QCoreApplication::installTranslator(&translator);
        const QStringList translated = messages();
        QCoreApplication::removeTranslator(&translator);
        QCOMPARE(translated.size(), english.size());
        QStringList untranslated;
        for (qsizetype i = 0; i < english.size(); ++i) {
            if (translated[i] == english[i])
                untranslated << english[i];
        }
        QVERIFY2(untranslated.isEmpty(), qPrintable(locale + QStringLiteral(" lacks:\n") + untranslated.join(QLatin1Char('\n'))));
    }
}

QTEST_GUILESS_MAIN(TestMessageTranslations)
#include "tst_messagetranslations.moc"
