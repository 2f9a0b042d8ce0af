// One behaviour written three times, in LD, FBD and ST, must give the same trace scan by scan:
// a motor with start/stop seal-in, a lamp that lights 50 ms after the motor runs, and a counter
// of starts (rising edge of the motor).
#include "diagram.h"

#include "interpreter/compiler/compiler.h"

#include <QTest>

using namespace iec;
using namespace iec::testing;

class TestGraphicalLanguages : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void ldFbdAndStGiveTheSameTrace();
};

namespace {

const char *const kDeclarations = "VAR start, stop, run, lamp : BOOL; t : TON; starts : INT; END_VAR";

Diagram ladder()
{
    Diagram d;
    d.rail(1).contact(2, "start", {{1}}).contact(3, "run", {{1}}, 100, 40);
    d.contact(4, "stop", {{2}, {3}}, 200, 0, true).coil(5, "run", {{4}});
    d.contact(6, "run", {{1}}, 100, 100).in(7, "T#50ms", 100, 140);
    d.block(8, "TON", "t", {{"IN", {{6}}}, {"PT", {{7}}}}, {"Q", "ET"}, 250, 100).coil(9, "lamp", {{8, "Q"}}, 500, 100);
    d.contact(10, "run", {{1}}, 100, 200, false, model::EdgeModifier::Rising).in(11, "starts", 100, 240).in(12, "1", 100, 270);
    d.block(13, "ADD", "", {{"EN", {{10}}}, {"IN1", {{11}}}, {"IN2", {{12}}}}, {"ENO", "OUT"}, 250, 200);
    d.out(14, "starts", {{13, "OUT"}}, 500, 240);
    return d;
}

Diagram functionBlocks()
{
    Diagram d;
    d.in(1, "start").in(2, "run", 0, 30).in(3, "stop", 0, 60);
    d.block(4, "OR", "", {{"IN1", {{1}}}, {"IN2", {{2}}}}, {"OUT"}, 100);
    d.block(5, "AND", "", {{"IN1", {{4, "OUT"}}}, {"IN2", {{3}}, true}}, {"OUT"}, 200).out(6, "run", {{5, "OUT"}});
    d.in(7, "run", 0, 100).in(8, "T#50ms", 0, 130);
    d.block(9, "TON", "t", {{"IN", {{7}}}, {"PT", {{8}}}}, {"Q", "ET"}, 200, 100).out(10, "lamp", {{9, "Q"}}, 500, 100);
    d.in(11, "run", 0, 200, false, model::EdgeModifier::Rising).in(12, "starts", 0, 230).in(13, "1", 0, 260);
    d.block(14, "ADD", "", {{"IN1", {{12}}}, {"IN2", {{13}}}}, {"OUT"}, 100, 230);
    d.block(15, "SEL", "", {{"G", {{11}}}, {"IN0", {{12}}}, {"IN1", {{14, "OUT"}}}}, {"OUT"}, 200, 200);
    d.out(16, "starts", {{15, "OUT"}}, 500, 200);
    return d;
}

const char *const kStructuredText = "PROGRAM Main\n"
                                    "VAR start, stop, run, lamp : BOOL; t : TON; starts : INT; edge : R_TRIG; END_VAR\n"
                                    "run := (start OR run) AND NOT stop;\n"
                                    "t(IN := run, PT := T#50ms);\n"
                                    "lamp := t.Q;\n"
                                    "edge(CLK := run);\n"
                                    "IF edge.Q THEN starts := starts + 1; END_IF\n"
                                    "END_PROGRAM\n";

// Inputs per scan: start pulses, a stop in the middle, a second start.
QStringList inputs()
{
    QStringList scans;
    for (int scan = 1; scan <= 30; ++scan) {
        const bool start = scan == 2 || scan == 3 || scan == 18;
        const bool stop = scan >= 12 && scan <= 14;
        scans << QStringLiteral("start=%1; stop=%2").arg(start ? "TRUE" : "FALSE", stop ? "TRUE" : "FALSE");
    }
    return scans;
}

QString trace(const std::shared_ptr<const interp::Module> &module)
{
    if (!module)
        return QStringLiteral("does not compile");
    interp::Runtime runtime(module);
    QStringList rows;
    for (const QString &scan : inputs()) {
        for (const QString &item : scan.split(QStringLiteral("; "))) {
            const QStringList pair = item.split(QLatin1Char('='));
            if (pair.size() != 2)
                return QStringLiteral("malformed input '%1'").arg(item);
            if (const auto refused = runtime.write(QStringLiteral("Main.") + pair[0], pair[1]))
                return QStringLiteral("writing %1: %2").arg(item, *refused);
        }
        if (!runtime.runCycle())
            return QStringLiteral("stopped: ") + (runtime.fault() ? runtime.fault()->toString() : QString());
        QStringList row;
        for (const char *name : {"run", "lamp", "starts"})
            row << runtime.read(QStringLiteral("Main.") + QLatin1String(name)).value_or(QStringLiteral("?"));
        rows << row.join(QLatin1Char(','));
    }
    return rows.join(QLatin1Char('\n'));
}

} // namespace

void TestGraphicalLanguages::ldFbdAndStGiveTheSameTrace()
{
    interp::Diagnostics diagnostics;
    const QString st = trace(interp::compileText(QString::fromLatin1(kStructuredText), diagnostics));
    const QString ld = trace(interp::frontend::compileProject(
        diagramProject(QLatin1String(kDeclarations), model::BodyLanguage::LD, ladder()), diagnostics));
    const QString fbd = trace(interp::frontend::compileProject(
        diagramProject(QLatin1String(kDeclarations), model::BodyLanguage::FBD, functionBlocks()), diagnostics));
    QCOMPARE(errorsOf(diagnostics), QString());
    QCOMPARE(ld, st);
    QCOMPARE(fbd, st);
    // The trace is not trivial: the motor runs, the lamp follows, both starts are counted.
    QVERIFY(st.contains(QLatin1String("TRUE,TRUE,1")));
    QVERIFY(st.endsWith(QLatin1String("TRUE,TRUE,2")));
}

QTEST_GUILESS_MAIN(TestGraphicalLanguages)
#include "tst_graphicallanguages.moc"
