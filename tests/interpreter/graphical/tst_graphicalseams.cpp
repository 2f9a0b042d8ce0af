// The entry points other parts use: lowerInput (SFC transition conditions wired to LD/FBD
// elements inside a chart) and cfcDiagram (CODESYS CFC kept in a body's addData).
#include "diagram.h"

#include "interpreter/compiler/astdump.h"
#include "interpreter/graphical/graphicallowering.h"

#include <QTest>

using namespace iec;
using namespace iec::testing;
namespace ast = iec::interp::ast;

class TestGraphicalSeams : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void conditionWiredToContactsAndBlocks();
    void conditionThatNeedsStatements();
    void oneNetworkForManyConditions();
    void codesysCfcRunsInItsOrder();
    void codesysCfcBodyCompilesInTheProject();
};

namespace {

// A chart body with a transition (localId 100) whose condition comes from `from`.
model::Body chartWithCondition(Diagram diagram, const std::vector<From> &from)
{
    model::Transition transition;
    transition.localId = 100;
    model::Condition condition;
    condition.kind = Diagram::wire(from);
    transition.condition = condition;
    diagram.elements.emplace_back(transition);
    model::Step step;
    step.localId = 101;
    step.name = QStringLiteral("S1");
    diagram.elements.emplace_back(step);
    return diagram.body(model::BodyLanguage::SFC);
}

const model::ConnectionPointIn &conditionOf(const model::Body &body)
{
    for (const model::Element &element : *body.elements()) {
        if (const auto *t = std::get_if<model::Transition>(&element))
            return std::get<model::ConnectionPointIn>(t->condition->kind);
    }
    qFatal("no transition");
}

} // namespace

void TestGraphicalSeams::conditionWiredToContactsAndBlocks()
{
    Diagram d;
    d.rail(1).contact(2, "a", {{1}}).contact(3, "b", {{2}}, 0, 0, true).contact(4, "c", {{1}}, 100, 40);
    d.in(5, "level").in(6, "50");
    d.block(7, "GT", "", {{"IN1", {{5}}}, {"IN2", {{6}}}}, {"OUT"});
    const model::Body ladder = chartWithCondition(d, {{3}, {4}});
    ast::Pou pou;
    interp::Diagnostics diagnostics;
    interp::graphical::LoweringContext context {pou, QStringLiteral("Chart"), diagnostics};
    const auto contacts = interp::graphical::lowerInput(ladder, conditionOf(ladder), context);
    QCOMPARE(errorsOf(diagnostics), QString());
    QVERIFY(contacts);
    QCOMPARE(ast::dump(*contacts), QStringLiteral("(OR (AND a (NOT b)) c)"));

    const model::Body block = chartWithCondition(d, {{7, "OUT"}});
    const auto compare = interp::graphical::lowerInput(block, conditionOf(block), context);
    QVERIFY(compare);
    QCOMPARE(ast::dump(*compare), QStringLiteral("GT(level, 50)"));
    QVERIFY(pou.sections.empty()); // nothing hidden was needed
}

void TestGraphicalSeams::conditionThatNeedsStatements()
{
    Diagram d;
    d.in(1, "start", 0, 0, false, model::EdgeModifier::Rising);
    const model::Body body = chartWithCondition(d, {{1}});
    ast::Pou pou;
    interp::Diagnostics diagnostics;
    interp::graphical::LoweringContext without {pou, QStringLiteral("Chart"), diagnostics};
    QVERIFY(!interp::graphical::lowerInput(body, conditionOf(body), without));
    QCOMPARE(errorsOf(diagnostics),
        QStringLiteral("Chart@1: An edge detection cannot be used in a condition wired into a chart."));

    interp::Diagnostics clean;
    std::vector<ast::Stmt> setup;
    interp::graphical::LoweringContext with {pou, QStringLiteral("Chart"), clean, &setup};
    const auto value = interp::graphical::lowerInput(body, conditionOf(body), with);
    QCOMPARE(errorsOf(clean), QString());
    QVERIFY(value);
    QCOMPARE(ast::dump(*value), QStringLiteral("__rtrig1.Q"));
    QCOMPARE(ast::dump(setup), QStringLiteral("(call __rtrig1(CLK := start))"));
    QCOMPARE(pou.sections.size(), size_t(1));
}

// A chart with many wired transitions builds its network once: every condition lowers as with
// lowerInput, and a broken network is reported once, not once per condition.
void TestGraphicalSeams::oneNetworkForManyConditions()
{
    Diagram d;
    d.rail(1).contact(2, "a", {{1}}).contact(3, "b", {{2}}, 0, 0, true).contact(4, "c", {{1}}, 100, 40);
    const model::Body ladder = chartWithCondition(d, {{3}, {4}});
    ast::Pou pou;
    interp::Diagnostics diagnostics;
    interp::graphical::LoweringContext context {pou, QStringLiteral("Chart"), diagnostics};
    const interp::graphical::InputLowering inputs(ladder, context.owner, diagnostics);
    for (int i = 0; i < 2; ++i) {
        const auto value = inputs.lower(conditionOf(ladder), context);
        QVERIFY(value);
        QCOMPARE(ast::dump(*value), QStringLiteral("(OR (AND a (NOT b)) c)"));
    }
    QCOMPARE(errorsOf(diagnostics), QString());

    Diagram broken;
    broken.continuation(1, "nowhere");
    const model::Body body = chartWithCondition(broken, {{1}});
    const interp::graphical::InputLowering brokenInputs(body, context.owner, diagnostics);
    QVERIFY(!brokenInputs.lower(conditionOf(body), context));
    QVERIFY(!brokenInputs.lower(conditionOf(body), context));
    QCOMPARE(errorsOf(diagnostics), QStringLiteral("Chart@1: There is no connector named 'nowhere' for this continuation."));
    QVERIFY(pou.sections.empty());
}

// CODESYS writes a CFC as an empty ST body with the diagram in addData; its executionOrderId
// decides the order (here against the positions, which would run x := y first).
static model::Body codesysCfcBody()
{
    model::Body body = model::Body::withLanguage(model::BodyLanguage::ST);
    model::AddDataEntry cfc;
    cfc.name = QStringLiteral("http://www.3s-software.com/plcopenxml/cfc");
    cfc.content = QStringLiteral(
        "<CFC>"
        "<inVariable localId=\"1\"><position x=\"10\" y=\"60\"/><connectionPointOut/><expression>a</expression></inVariable>"
        "<outVariable localId=\"2\" executionOrderId=\"0\"><position x=\"200\" y=\"60\"/>"
        "<connectionPointIn><connection refLocalId=\"1\"/></connectionPointIn><expression>y</expression></outVariable>"
        "<inVariable localId=\"3\"><position x=\"10\" y=\"10\"/><connectionPointOut/><expression>y</expression></inVariable>"
        "<outVariable localId=\"4\" executionOrderId=\"1\"><position x=\"200\" y=\"10\"/>"
        "<connectionPointIn><connection refLocalId=\"3\"/></connectionPointIn><expression>x</expression></outVariable>"
        "</CFC>");
    body.addData.push_back(cfc);
    return body;
}

void TestGraphicalSeams::codesysCfcRunsInItsOrder()
{
    const model::Body body = codesysCfcBody();
    const auto diagram = interp::graphical::cfcDiagram(body);
    QVERIFY(diagram);
    QCOMPARE(diagram->elements()->size(), size_t(4));
    QVERIFY(!interp::graphical::cfcDiagram(model::Body::withLanguage(model::BodyLanguage::ST)));
    // CODESYS numbers from 0 (Beremiz writes 0 for "none"): y := a (0) runs before x := y (1).
    auto project = diagramProject(QStringLiteral("VAR a, x, y : BOOL; END_VAR"), model::BodyLanguage::FBD, Diagram {});
    project.types.pous.front().bodies = {*diagram};
    QCOMPARE(runProject(project, {"a=TRUE => y=TRUE; x=TRUE", "a=FALSE => y=FALSE; x=FALSE"}), QString());
}

// The project frontend finds the CFC itself: as the POU body and as an action's body.
void TestGraphicalSeams::codesysCfcBodyCompilesInTheProject()
{
    auto project = diagramProject(QStringLiteral("VAR a, x, y : BOOL; END_VAR"), model::BodyLanguage::FBD, Diagram {});
    project.types.pous.front().bodies = {codesysCfcBody()};
    QCOMPARE(runProject(project, {"a=TRUE => y=TRUE; x=TRUE", "a=FALSE => y=FALSE; x=FALSE"}), QString());

    model::Body call = model::Body::withLanguage(model::BodyLanguage::ST);
    call.setText(QStringLiteral("Act();"));
    project.types.pous.front().bodies = {call};
    model::PouAction action;
    action.name = QStringLiteral("Act");
    action.body = codesysCfcBody();
    project.types.pous.front().actions.push_back(action);
    QCOMPARE(runProject(project, {"a=TRUE => y=TRUE; x=TRUE", "a=FALSE => y=FALSE; x=FALSE"}), QString());
}

QTEST_GUILESS_MAIN(TestGraphicalSeams)
#include "tst_graphicalseams.moc"
