// resources/examples/staggered_fans.xml (FBD): fan 1 with Start, fan 2 5 s later, fan 3 5 s after
// fan 2; one Stop switches all three off in the same scan. Checked scan by scan (10 ms scans).
#include "clitrace.h"

#include <QTest>

using namespace iec::testing;

class TestExampleStaggeredFans : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void fansStartFiveSecondsApart();
};

void TestExampleStaggeredFans::fansStartFiveSecondsApart()
{
    const int cycles = 1100;
    const CliTrace trace = runExample(QStringLiteral("staggered_fans.xml"), cycles,
        {QStringLiteral("Main.Start=TRUE@1"), QStringLiteral("Main.Start=FALSE@2"), QStringLiteral("Main.Stop=TRUE@1050"),
            QStringLiteral("Main.Stop=FALSE@1051"), QStringLiteral("Main.Start=TRUE@1060"), QStringLiteral("Main.Start=FALSE@1061")},
        {QStringLiteral("Main.Fan1"), QStringLiteral("Main.Fan2"), QStringLiteral("Main.Fan3")});
    QCOMPARE(trace.error, QString());
    for (int cycle = 1; cycle <= cycles; ++cycle) {
        const auto &row = trace.cycles[std::size_t(cycle - 1)];
        const bool first = cycle < 1050 || cycle >= 1060;
        const bool second = cycle >= 501 && cycle < 1050;  // cycle 501 runs at 5 s
        const bool third = cycle >= 1001 && cycle < 1050;  // cycle 1001 runs at 10 s
        QCOMPARE(std::make_pair(cycle, row.value(QStringLiteral("Main.Fan1"))), std::make_pair(cycle, boolText(first)));
        QCOMPARE(std::make_pair(cycle, row.value(QStringLiteral("Main.Fan2"))), std::make_pair(cycle, boolText(second)));
        QCOMPARE(std::make_pair(cycle, row.value(QStringLiteral("Main.Fan3"))), std::make_pair(cycle, boolText(third)));
    }
}

QTEST_GUILESS_MAIN(TestExampleStaggeredFans)
#include "tst_example_staggered_fans.moc"
