// resources/examples/star_delta.xml (LD): star for 8 s, 100 ms with both contactors open, then
// delta; star and delta are never on together; Stop drops everything. Checked scan by scan
// (10 ms scans: cycle n runs at (n - 1) * 10 ms).
#include "clitrace.h"

#include <QTest>

using namespace iec::testing;

class TestExampleStarDelta : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void starThenDeadTimeThenDelta();
};

void TestExampleStarDelta::starThenDeadTimeThenDelta()
{
    const int cycles = 1000;
    const CliTrace trace = runExample(QStringLiteral("star_delta.xml"), cycles,
        {QStringLiteral("Main.Start=TRUE@1"), QStringLiteral("Main.Start=FALSE@2"), QStringLiteral("Main.Stop=TRUE@950"),
            QStringLiteral("Main.Stop=FALSE@951")},
        {QStringLiteral("Main.Line"), QStringLiteral("Main.Star"), QStringLiteral("Main.Delta")});
    QCOMPARE(trace.error, QString());
    for (int cycle = 1; cycle <= cycles; ++cycle) {
        const auto &row = trace.cycles[std::size_t(cycle - 1)];
        const bool line = cycle < 950;
        const bool star = cycle <= 800;              // until 8 s have passed (cycle 801 runs at 8.00 s)
        const bool delta = cycle >= 811 && cycle < 950; // 100 ms later (cycle 811 runs at 8.10 s)
        QCOMPARE(std::make_pair(cycle, row.value(QStringLiteral("Main.Line"))), std::make_pair(cycle, boolText(line)));
        QCOMPARE(std::make_pair(cycle, row.value(QStringLiteral("Main.Star"))), std::make_pair(cycle, boolText(star)));
        QCOMPARE(std::make_pair(cycle, row.value(QStringLiteral("Main.Delta"))), std::make_pair(cycle, boolText(delta)));
    }
}

QTEST_GUILESS_MAIN(TestExampleStarDelta)
#include "tst_example_star_delta.moc"
