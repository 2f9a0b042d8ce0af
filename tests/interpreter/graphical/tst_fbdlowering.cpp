// FBD bodies lowered to statements and run scan by scan: data flow and execution order,
// feedback, connectors, negated and edge pins, set/reset outputs, extensible and user blocks,
// jumps; and the diagnostics of a wrong graph, located on the element.
#include "diagram.h"

#include <QRandomGenerator>
#include <QTest>

#include <functional>

using namespace iec;
using namespace iec::testing;
using model::EdgeModifier;
using model::StorageModifier;

class TestFbdLowering : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void scans_data();
    void scans();
    void wrongGraphs_data();
    void wrongGraphs();
    void executeBoxRunsItsCode();
    void randomGraphsNeverCrash();
};

namespace {

struct Case {
    const char *name;
    const char *declarations;
    std::function<void(Diagram &)> draw;
    QStringList steps;
    const char *extra = "";
};

const char *const kTwice = "FUNCTION Twice : INT\nVAR_INPUT v : INT; END_VAR\nTwice := v * 2;\nEND_FUNCTION\n";

const std::vector<Case> &cases()
{
    static const std::vector<Case> table {
        {"extensible ADD with three inputs", "VAR a, b, c, y : INT; END_VAR",
            [](Diagram &d) {
                d.in(1, "a").in(2, "b", 0, 30).in(3, "c", 0, 60);
                d.block(4, "ADD", "", {{"IN1", {{1}}}, {"IN2", {{2}}}, {"IN3", {{3}}}}, {"OUT"}).out(5, "y", {{4, "OUT"}});
            },
            {"a=1; b=20; c=300 => y=321"}},
        {"negated input and output", "VAR a, b, y, z : BOOL; END_VAR",
            [](Diagram &d) {
                d.in(1, "a").in(2, "b", 0, 30);
                d.block(3, "AND", "", {{"IN1", {{1}}}, {"IN2", {{2}}, true}}, {"OUT"}).out(4, "y", {{3, "OUT"}});
                d.out(5, "z", {{3, "OUT"}}, 500, 50, StorageModifier::None, true);
            },
            {"a=TRUE => y=TRUE; z=FALSE", "b=TRUE => y=FALSE; z=TRUE"}},
        {"feedback through an in-out variable", "VAR cnt, y : INT; END_VAR",
            [](Diagram &d) {
                // ADD(1, cnt) -> cnt -> y, and cnt back into the ADD (Beremiz CounterFBD style).
                d.in(1, "1").block(2, "ADD", "", {{"IN1", {{1}}}, {"IN2", {{3}}}}, {"OUT"});
                d.inOut(3, "cnt", {{2, "OUT"}}).out(4, "y", {{3}});
            },
            {"=> cnt=1; y=1", "=> cnt=2; y=2", "cnt=10 => cnt=11; y=11"}},
        {"an output read twice gives one value", "VAR n, m : INT; END_VAR",
            [](Diagram &d) {
                d.in(1, "n").in(2, "1", 0, 30);
                d.block(3, "ADD", "", {{"IN1", {{1}}}, {"IN2", {{2}}}}, {"OUT"});
                d.out(4, "n", {{3, "OUT"}}, 500, 0).out(5, "m", {{3, "OUT"}}, 500, 50);
            },
            {"=> n=1; m=1", "=> n=2; m=2"}},
        {"connector and continuation", "VAR a, b, y : BOOL; END_VAR",
            [](Diagram &d) {
                d.in(1, "a").connector(2, "link", {{1}});
                d.continuation(3, "link", 0, 100).in(4, "b", 0, 130);
                d.block(5, "OR", "", {{"IN1", {{3}}}, {"IN2", {{4}}}}, {"OUT"}, 200, 100).out(6, "y", {{5, "OUT"}}, 500, 100);
            },
            {"=> y=FALSE", "a=TRUE => y=TRUE", "a=FALSE; b=TRUE => y=TRUE"}},
        {"position order: the upper network reads the old value", "VAR a, x, y : BOOL; END_VAR",
            [](Diagram &d) {
                d.in(1, "a", 0, 100).out(2, "y", {{1}}, 500, 100);
                d.in(3, "y", 0, 0).out(4, "x", {{3}}, 500, 0);
            },
            {"a=TRUE => y=TRUE; x=FALSE", "=> x=TRUE"}},
        {"executionOrderId wins over position", "VAR a, x, y : BOOL; END_VAR",
            [](Diagram &d) {
                d.in(1, "a", 0, 100).out(2, "y", {{1}}, 500, 100);
                d.in(3, "y", 0, 0).out(4, "x", {{3}}, 500, 0);
                d.order(2, 1).order(4, 2);
            },
            {"a=TRUE => y=TRUE; x=TRUE"}},
        {"set and reset outputs", "VAR s, r, q : BOOL; END_VAR",
            [](Diagram &d) {
                d.in(1, "s").out(2, "q", {{1}}, 500, 0, StorageModifier::Set);
                d.in(3, "r", 0, 100).out(4, "q", {{3}}, 500, 100, StorageModifier::Reset);
            },
            {"s=TRUE => q=TRUE", "s=FALSE => q=TRUE", "r=TRUE => q=FALSE", "r=FALSE => q=FALSE"}},
        {"edge-detecting input variable", "VAR a, y : BOOL; END_VAR",
            [](Diagram &d) { d.in(1, "a", 0, 0, false, EdgeModifier::Rising).out(2, "y", {{1}}); },
            {"a=TRUE => y=TRUE", "=> y=FALSE", "a=FALSE => y=FALSE", "a=TRUE => y=TRUE"}},
        {"edge-detecting block input", "VAR a : BOOL; n : INT; END_VAR",
            [](Diagram &d) {
                d.in(1, "a").in(2, "n", 0, 30).in(3, "1", 0, 60);
                d.block(4, "SEL", "", {{"G", {{1}}, false, EdgeModifier::Rising}, {"IN0", {{2}}}, {"IN1", {{5, "OUT"}}}},
                    {"OUT"}, 300);
                d.block(5, "ADD", "", {{"IN1", {{2}}}, {"IN2", {{3}}}}, {"OUT"}, 150, 40);
                d.out(6, "n", {{4, "OUT"}});
            },
            {"a=TRUE => n=1", "=> n=1", "a=FALSE => n=1", "a=TRUE => n=2"}},
        {"user function with formal inputs", "VAR a, y : INT; END_VAR",
            [](Diagram &d) { d.in(1, "a").block(2, "Twice", "", {{"v", {{1}}}}, {"OUT"}).out(3, "y", {{2, "OUT"}}); },
            {"a=21 => y=42"}, kTwice},
        {"function block instance and its outputs", "VAR s, r, q : BOOL; latch : SR; END_VAR",
            [](Diagram &d) {
                d.in(1, "s").in(2, "r", 0, 30);
                d.block(3, "SR", "latch", {{"S1", {{1}}}, {"R", {{2}}}}, {"Q1"}).out(4, "q", {{3, "Q1"}});
            },
            {"s=TRUE => q=TRUE", "s=FALSE => q=TRUE", "r=TRUE => q=FALSE"}},
        {"a loop through a function block reads its output of the previous scan", "VAR s : BOOL; y : INT; c : CTU; END_VAR",
            [](Diagram &d) {
                // The counter resets itself from its own Q (a wire from its output back to R).
                d.in(1, "s").in(2, "2", 0, 60);
                d.block(3, "CTU", "c", {{"CU", {{1}}}, {"R", {{3, "Q"}}}, {"PV", {{2}}}}, {"Q", "CV"}).out(4, "y", {{3, "CV"}});
            },
            {"s=TRUE => y=1", "s=FALSE => y=1", "s=TRUE => y=2", "s=FALSE => y=0", "s=TRUE => y=1"}},
        {"conditional jump over a network", "VAR c, a, x : BOOL; END_VAR",
            [](Diagram &d) {
                d.in(1, "c").jump(2, "Skip", {{1}});
                d.in(3, "a", 0, 100).out(4, "x", {{3}}, 500, 100);
                d.label(5, "Skip", 200);
            },
            {"c=TRUE; a=TRUE => x=FALSE", "c=FALSE => x=TRUE"}},
        {"files without positions run in file order", "VAR a, x, y : BOOL; END_VAR",
            [](Diagram &d) {
                d.in(1, "a", 0, 0).out(2, "y", {{1}}, 0, 0);
                d.in(3, "y", 0, 0).out(4, "x", {{3}}, 0, 0);
            },
            {"a=TRUE => y=TRUE; x=TRUE"}},
    };
    return table;
}

} // namespace

void TestFbdLowering::scans_data()
{
    QTest::addColumn<int>("index");
    for (std::size_t i = 0; i < cases().size(); ++i)
        QTest::newRow(cases()[i].name) << int(i);
}

void TestFbdLowering::scans()
{
    QFETCH(int, index);
    const Case &c = cases()[std::size_t(index)];
    Diagram diagram;
    c.draw(diagram);
    QCOMPARE(runDiagram(QLatin1String(c.declarations), model::BodyLanguage::FBD, diagram, c.steps, QLatin1String(c.extra)),
        QString());
}

void TestFbdLowering::wrongGraphs_data()
{
    QTest::addColumn<int>("language");
    QTest::addColumn<int>("index");
    QTest::addColumn<QString>("expected");
    const auto ld = int(model::BodyLanguage::LD);
    const auto fbd = int(model::BodyLanguage::FBD);
    QTest::newRow("unconnected contact") << ld << 0 << "Main@2: The contact 'a' has no wire on its left.";
    QTest::newRow("unconnected output") << fbd << 1 << "Main@2: Nothing is wired to the output 'x'.";
    QTest::newRow("unconnected function input") << fbd << 2 << "Main@3: The input IN2 of AND is not connected.";
    QTest::newRow("two drivers") << fbd << 3 << "Main@3: 2 wires end at one input; an input takes exactly one.";
    QTest::newRow("loop without a feedback variable")
        << fbd << 4
        << "Main@2: The wires make a loop through 2 elements with no variable to keep the value from one scan to the next.";
    QTest::newRow("unknown variable") << ld << 5 << "Main@2: Unknown variable 'nosuch'.";
    QTest::newRow("not an expression") << fbd << 6 << "Main@1: 'a +' is not a variable or an expression.";
    QTest::newRow("jump to no label") << fbd << 7 << "Main@2: There is no label 'Nowhere' to jump to.";
    QTest::newRow("continuation without connector")
        << fbd << 8 << "Main@1: There is no connector named 'lost' for this continuation.";
}

void TestFbdLowering::wrongGraphs()
{
    QFETCH(int, language);
    QFETCH(int, index);
    QFETCH(QString, expected);
    Diagram d;
    switch (index) {
    case 0:
        d.rail(1).contact(2, "a", {}).coil(3, "x", {{2}});
        break;
    case 1:
        d.in(1, "a").out(2, "x", {});
        break;
    case 2:
        d.in(1, "a").block(3, "AND", "", {{"IN1", {{1}}}, {"IN2", {}}}, {"OUT"}).out(4, "x", {{3, "OUT"}});
        break;
    case 3:
        d.in(1, "a").in(2, "b").out(3, "x", {{1}, {2}});
        break;
    case 4:
        d.in(1, "a");
        d.block(2, "AND", "", {{"IN1", {{1}}}, {"IN2", {{3, "OUT"}}}}, {"OUT"});
        d.block(3, "AND", "", {{"IN1", {{1}}}, {"IN2", {{2, "OUT"}}}}, {"OUT"}).out(4, "x", {{3, "OUT"}});
        break;
    case 5:
        d.rail(1).contact(2, "nosuch", {{1}}).coil(3, "x", {{2}});
        break;
    case 6:
        d.in(1, "a +").out(2, "x", {{1}});
        break;
    case 7:
        d.in(1, "a").jump(2, "Nowhere", {{1}});
        break;
    case 8:
        d.continuation(1, "lost").out(2, "x", {{1}});
        break;
    }
    QCOMPARE(diagramErrors(QStringLiteral("VAR a, b, x : BOOL; END_VAR"), model::BodyLanguage(language), d), expected);
}

// CODESYS keeps the ST of an EXECUTE box in addData; it runs when EN is on.
void TestFbdLowering::executeBoxRunsItsCode()
{
    Diagram d;
    d.in(1, "go").block(2, "EXECUTE", "", {{"EN", {{1}}}}, {"ENO"}).out(3, "done", {{2, "ENO"}});
    model::AddDataEntry code;
    code.name = QStringLiteral("http://www.3s-software.com/plcopenxml/stcode");
    code.content = QStringLiteral("<STCode xmlns=\"\">n := n + 1; IF n &gt; 2 THEN n := 0; END_IF</STCode>");
    std::get<model::Block>(d.elements[1]).addData.push_back(code);
    QCOMPARE(runDiagram(QStringLiteral("VAR go, done : BOOL; n : INT; END_VAR"), model::BodyLanguage::FBD, d,
                 {"=> n=0; done=FALSE", "go=TRUE => n=1; done=TRUE", "=> n=2", "=> n=0"}),
        QString());
}

// Wires to anything (missing elements, loops, several drivers, labels): every graph lowers to
// statements or to diagnostics, never to a crash.
void TestFbdLowering::randomGraphsNeverCrash()
{
    QRandomGenerator random(61131);
    const QStringList names {"a", "b", "x", "n", "a +", "T#1s", "%QX0.1", "3"};
    for (int round = 0; round < 200; ++round) {
        Diagram d;
        const int count = 2 + int(random.bounded(10));
        const auto anySource = [&] { return From {quint64(random.bounded(count + 2)), random.bounded(3) ? QString() : "OUT"}; };
        const auto sources = [&] {
            std::vector<From> from;
            for (int i = int(random.bounded(3)); i > 0; --i)
                from.push_back(anySource());
            return from;
        };
        for (quint64 id = 1; id <= quint64(count); ++id) {
            const QString name = names[int(random.bounded(names.size()))];
            const double x = random.bounded(4) * 100.0, y = random.bounded(4) * 50.0;
            switch (random.bounded(11)) {
            case 0: d.rail(id, y); break;
            case 1: d.contact(id, name, sources(), x, y, random.bounded(2), model::EdgeModifier(random.bounded(3))); break;
            case 2: d.coil(id, name, sources(), x, y, false, model::EdgeModifier(random.bounded(3)), model::StorageModifier(random.bounded(3))); break;
            case 3: d.in(id, name, x, y, random.bounded(2), model::EdgeModifier(random.bounded(3))); break;
            case 4: d.out(id, name, sources(), x, y, model::StorageModifier(random.bounded(3))); break;
            case 5: d.inOut(id, name, sources(), x, y); break;
            case 6: d.block(id, random.bounded(2) ? "ADD" : "TON", random.bounded(2) ? "" : "t", {{"IN1", sources()}, {"EN", sources()}}, {"OUT", "ENO"}, x, y); break;
            case 7: d.connector(id, "c", sources(), x, y); break;
            case 8: d.continuation(id, random.bounded(2) ? "c" : "d", x, y); break;
            case 9: d.jump(id, random.bounded(2) ? "L" : "M", sources(), x, y); break;
            default: d.label(id, "L", y); break;
            }
        }
        for (const auto language : {model::BodyLanguage::LD, model::BodyLanguage::FBD})
            diagramErrors(QStringLiteral("VAR a, b, x : BOOL; n : INT; t : TON; END_VAR"), language, d);
    }
}

QTEST_GUILESS_MAIN(TestFbdLowering)
#include "tst_fbdlowering.moc"
