// LD bodies lowered to statements and run scan by scan: contacts, coils, parallel branches,
// blocks with EN/ENO, the order of rungs, jumps and returns.
#include "diagram.h"

#include <QTest>

#include <functional>

using namespace iec;
using namespace iec::testing;
using model::EdgeModifier;
using model::StorageModifier;

class TestLdLowering : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void scans_data();
    void scans();
    void longRungsStayShallow();
};

namespace {

struct Case {
    const char *name;
    const char *declarations;
    std::function<void(Diagram &)> draw;
    QStringList steps;
};

const std::vector<Case> &cases()
{
    static const std::vector<Case> table {
        {"series NO and NC", "VAR a, b, x : BOOL; END_VAR",
            [](Diagram &d) { d.rail(1).contact(2, "a", {{1}}).contact(3, "b", {{2}}, 0, 0, true).coil(4, "x", {{3}}); },
            {"a=TRUE => x=TRUE", "b=TRUE => x=FALSE", "a=FALSE; b=FALSE => x=FALSE"}},
        {"parallel branches are OR", "VAR a, b, x : BOOL; END_VAR",
            [](Diagram &d) { d.rail(1).contact(2, "a", {{1}}).contact(3, "b", {{1}}, 120, 40).coil(4, "x", {{2}, {3}}); },
            {"=> x=FALSE", "a=TRUE => x=TRUE", "a=FALSE; b=TRUE => x=TRUE", "b=FALSE => x=FALSE"}},
        {"branch in the middle of a rung", "VAR a, b, c, d, x : BOOL; END_VAR",
            [](Diagram &d) {
                d.rail(1).contact(2, "a", {{1}}).contact(3, "b", {{2}}).contact(4, "c", {{2}}, 130, 40);
                d.contact(5, "d", {{3}, {4}}).coil(6, "x", {{5}});
            },
            {"a=TRUE; d=TRUE => x=FALSE", "b=TRUE => x=TRUE", "b=FALSE; c=TRUE => x=TRUE", "a=FALSE => x=FALSE"}},
        {"rising edge contact", "VAR a, x : BOOL; END_VAR",
            [](Diagram &d) { d.rail(1).contact(2, "a", {{1}}, 0, 0, false, EdgeModifier::Rising).coil(3, "x", {{2}}); },
            {"a=TRUE => x=TRUE", "=> x=FALSE", "a=FALSE => x=FALSE", "a=TRUE => x=TRUE"}},
        {"falling edge contact", "VAR a, x : BOOL; END_VAR",
            [](Diagram &d) { d.rail(1).contact(2, "a", {{1}}, 0, 0, false, EdgeModifier::Falling).coil(3, "x", {{2}}); },
            {"a=TRUE => x=FALSE", "a=FALSE => x=TRUE", "=> x=FALSE"}},
        {"negated coil", "VAR a, x : BOOL; END_VAR",
            [](Diagram &d) { d.rail(1).contact(2, "a", {{1}}).coil(3, "x", {{2}}, 500, 0, true); },
            {"=> x=TRUE", "a=TRUE => x=FALSE"}},
        {"set and reset coils", "VAR s, r, x : BOOL; END_VAR",
            [](Diagram &d) {
                d.rail(1).contact(2, "s", {{1}}).coil(3, "x", {{2}}, 500, 0, false, EdgeModifier::None, StorageModifier::Set);
                d.contact(4, "r", {{1}}, 100, 100).coil(5, "x", {{4}}, 500, 100, false, EdgeModifier::None, StorageModifier::Reset);
            },
            {"=> x=FALSE", "s=TRUE => x=TRUE", "s=FALSE => x=TRUE", "r=TRUE => x=FALSE", "s=TRUE => x=FALSE",
                "r=FALSE => x=TRUE"}},
        {"rising and falling edge coils", "VAR a, up, down : BOOL; END_VAR",
            [](Diagram &d) {
                d.rail(1).contact(2, "a", {{1}});
                d.coil(3, "up", {{2}}, 500, 0, false, EdgeModifier::Rising);
                d.coil(4, "down", {{2}}, 500, 40, false, EdgeModifier::Falling);
            },
            {"a=TRUE => up=TRUE; down=FALSE", "=> up=FALSE; down=FALSE", "a=FALSE => up=FALSE; down=TRUE",
                "=> down=FALSE"}},
        {"seal-in: stop wins", "VAR start, stop, motor : BOOL; END_VAR",
            [](Diagram &d) {
                d.rail(1).contact(2, "start", {{1}}).contact(3, "motor", {{1}}, 100, 40);
                d.contact(4, "stop", {{2}, {3}}, 200, 0, true).coil(5, "motor", {{4}});
            },
            {"start=TRUE => motor=TRUE", "start=FALSE => motor=TRUE", "stop=TRUE => motor=FALSE",
                "start=TRUE => motor=FALSE", "stop=FALSE; start=FALSE => motor=FALSE"}},
        {"a rung sees what the rung above wrote in the same scan", "VAR a, m, x : BOOL; END_VAR",
            [](Diagram &d) {
                // Listed bottom rung first: the position decides.
                d.rail(1).contact(4, "m", {{1}}, 100, 100).coil(5, "x", {{4}}, 500, 100);
                d.contact(2, "a", {{1}}, 100, 0).coil(3, "m", {{2}}, 500, 0);
            },
            {"a=TRUE => m=TRUE; x=TRUE", "a=FALSE => m=FALSE; x=FALSE"}},
        {"coils in series pass the power on", "VAR a, x, y : BOOL; END_VAR",
            [](Diagram &d) { d.rail(1).contact(2, "a", {{1}}).coil(3, "x", {{2}}, 400).coil(4, "y", {{3}}, 500); },
            {"a=TRUE => x=TRUE; y=TRUE", "a=FALSE => x=FALSE; y=FALSE"}},
        {"timer block in a rung", "VAR go, lamp : BOOL; t : TON; END_VAR",
            [](Diagram &d) {
                d.rail(1).contact(2, "go", {{1}}).in(3, "T#30ms", 100, 40);
                d.block(4, "TON", "t", {{"IN", {{2}}}, {"PT", {{3}}}}, {"Q", "ET"}, 250).coil(5, "lamp", {{4, "Q"}});
            },
            {"go=TRUE => lamp=FALSE", "=> lamp=FALSE", "=> lamp=FALSE", "=> lamp=TRUE", "go=FALSE => lamp=FALSE"}},
        {"function with EN and ENO", "VAR e, done : BOOL; n : INT; END_VAR",
            [](Diagram &d) {
                d.rail(1).contact(2, "e", {{1}}).in(3, "n", 100, 40).in(4, "1", 100, 60);
                d.block(5, "ADD", "", {{"EN", {{2}}}, {"IN1", {{3}}}, {"IN2", {{4}}}}, {"ENO", "OUT"}, 250);
                d.coil(6, "done", {{5, "ENO"}}).out(7, "n", {{5, "OUT"}}, 500, 40);
            },
            {"=> n=0; done=FALSE", "e=TRUE => n=1; done=TRUE", "=> n=2", "e=FALSE => n=2; done=FALSE"}},
        {"function block with EN keeps its state while off", "VAR e, up : BOOL; c : CTU; n : INT; END_VAR",
            [](Diagram &d) {
                d.rail(1).contact(2, "e", {{1}}).contact(3, "up", {{1}}, 100, 40);
                d.block(4, "CTU", "c", {{"EN", {{2}}}, {"CU", {{3}}}}, {"ENO", "Q", "CV"}, 250);
                d.out(5, "n", {{4, "CV"}});
            },
            // Not called in scan 3, so in scan 4 CTU sees CU rise (it last saw FALSE in scan 2).
            {"e=TRUE; up=TRUE => n=1", "up=FALSE => n=1", "e=FALSE; up=TRUE => n=1", "e=TRUE => n=2",
                "up=FALSE => n=2", "up=TRUE => n=3"}},
        {"jump over a rung", "VAR skip, a, x, y : BOOL; END_VAR",
            [](Diagram &d) {
                d.rail(1).contact(2, "skip", {{1}}).jump(3, "Over", {{2}});
                d.contact(4, "a", {{1}}, 100, 100).coil(5, "x", {{4}}, 500, 100);
                d.label(6, "Over", 200).contact(7, "a", {{1}}, 100, 250).coil(8, "y", {{7}}, 500, 250);
            },
            {"skip=TRUE; a=TRUE => x=FALSE; y=TRUE", "skip=FALSE => x=TRUE; y=TRUE",
                "skip=TRUE; a=FALSE => x=TRUE; y=FALSE"}},
        {"jump back runs a rung again", "VAR n : INT; again : BOOL; END_VAR",
            [](Diagram &d) {
                d.label(1, "Top", 0).rail(2, 50).in(3, "n", 100, 50).in(4, "1", 100, 80);
                d.block(5, "ADD", "", {{"IN1", {{3}}}, {"IN2", {{4}}}}, {"OUT"}, 200, 50).out(6, "n", {{5, "OUT"}}, 400, 50);
                d.in(7, "n", 100, 150).in(8, "3", 100, 180);
                d.block(9, "LT", "", {{"IN1", {{7}}}, {"IN2", {{8}}}}, {"OUT"}, 200, 150).jump(10, "Top", {{9, "OUT"}}, 400, 150);
            },
            {"=> n=3", "n=10 => n=11"}},
        {"conditional return", "VAR r, a, x : BOOL; END_VAR",
            [](Diagram &d) {
                d.rail(1).contact(2, "r", {{1}}).ret(3, {{2}});
                d.contact(4, "a", {{1}}, 100, 100).coil(5, "x", {{4}}, 500, 100);
            },
            {"r=TRUE; a=TRUE => x=FALSE", "r=FALSE => x=TRUE"}},
    };
    return table;
}

} // namespace

void TestLdLowering::scans_data()
{
    QTest::addColumn<int>("index");
    for (std::size_t i = 0; i < cases().size(); ++i)
        QTest::newRow(cases()[i].name) << int(i);
}

void TestLdLowering::scans()
{
    QFETCH(int, index);
    const Case &c = cases()[std::size_t(index)];
    Diagram diagram;
    c.draw(diagram);
    QCOMPARE(runDiagram(QLatin1String(c.declarations), model::BodyLanguage::LD, diagram, c.steps), QString());
}

// 2,000 contacts in series: the expression is cut into pieces, so the compiler's recursion
// stays shallow, and the result is still their AND.
void TestLdLowering::longRungsStayShallow()
{
    Diagram diagram;
    diagram.rail(1);
    quint64 previous = 1;
    for (quint64 id = 2; id < 2002; ++id) {
        diagram.contact(id, QStringLiteral("a"), {{previous}}, double(id), 0);
        previous = id;
    }
    diagram.coil(3000, QStringLiteral("x"), {{previous}}, 5000, 0);
    QCOMPARE(runDiagram(QStringLiteral("VAR a, x : BOOL; END_VAR"), model::BodyLanguage::LD, diagram,
                 {"=> x=FALSE", "a=TRUE => x=TRUE"}),
        QString());
}

QTEST_GUILESS_MAIN(TestLdLowering)
#include "tst_ldlowering.moc"
