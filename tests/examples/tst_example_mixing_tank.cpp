// resources/examples/mixing_tank.xml (SFC, seed 001): SB1 starts; Y1 fills liquid A until L2;
// Y2 fills B until L1; the mixer M runs MixTime; Y3 drains until L3 clears; then the next batch;
// SB2 stops the tank at the end of the batch in progress. The level switches are driven per
// cycle as the liquid would move them; the outputs are checked scan by scan (10 ms scans).
#include "clitrace.h"

#include <QTest>

using namespace iec::testing;

class TestExampleMixingTank : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void twoBatchesThenStop();
};

namespace {

bool within(int cycle, std::initializer_list<std::pair<int, int>> ranges)
{
    for (const auto &[first, last] : ranges) {
        if (cycle >= first && cycle <= last)
            return true;
    }
    return false;
}

} // namespace

void TestExampleMixingTank::twoBatchesThenStop()
{
    const int cycles = 100;
    // A transition that becomes TRUE in cycle n activates the next step in cycle n + 1, whose
    // Boolean actions switch the outputs in that cycle.
    const CliTrace trace = runExample(QStringLiteral("mixing_tank.xml"), cycles,
        {QStringLiteral("Main.MixTime=T#100ms@1"), QStringLiteral("Main.SB1=TRUE@2"), QStringLiteral("Main.SB1=FALSE@3"),
            // batch 1: A up to L2, B up to L1, mix 100 ms (cycles 21..31), drain
            QStringLiteral("Main.L3=TRUE@6"), QStringLiteral("Main.L2=TRUE@10"), QStringLiteral("Main.L1=TRUE@20"),
            QStringLiteral("Main.L1=FALSE@35"), QStringLiteral("Main.L2=FALSE@38"), QStringLiteral("Main.L3=FALSE@40"),
            // batch 2, with SB2 pressed while filling
            QStringLiteral("Main.L3=TRUE@44"), QStringLiteral("Main.SB2=TRUE@45"), QStringLiteral("Main.SB2=FALSE@46"),
            QStringLiteral("Main.L2=TRUE@50"), QStringLiteral("Main.L1=TRUE@55"), QStringLiteral("Main.L1=FALSE@70"),
            QStringLiteral("Main.L2=FALSE@72"), QStringLiteral("Main.L3=FALSE@75"),
            // after the stop the levels change no more; SB1 again starts a new batch
            QStringLiteral("Main.SB1=TRUE@90"), QStringLiteral("Main.SB1=FALSE@91")},
        {QStringLiteral("Main.Y1"), QStringLiteral("Main.Y2"), QStringLiteral("Main.M"), QStringLiteral("Main.Y3"),
            QStringLiteral("Main.Init.x")});
    QCOMPARE(trace.error, QString());
    for (int cycle = 1; cycle <= cycles; ++cycle) {
        const auto &row = trace.cycles[std::size_t(cycle - 1)];
        const bool y1 = within(cycle, {{3, 10}, {41, 50}, {91, 100}});
        const bool y2 = within(cycle, {{11, 20}, {51, 55}});
        const bool m = within(cycle, {{21, 31}, {56, 66}});
        const bool y3 = within(cycle, {{32, 40}, {67, 75}});
        const bool init = within(cycle, {{1, 2}, {76, 90}});
        QCOMPARE(std::make_pair(cycle, row.value(QStringLiteral("Main.Y1"))), std::make_pair(cycle, boolText(y1)));
        QCOMPARE(std::make_pair(cycle, row.value(QStringLiteral("Main.Y2"))), std::make_pair(cycle, boolText(y2)));
        QCOMPARE(std::make_pair(cycle, row.value(QStringLiteral("Main.M"))), std::make_pair(cycle, boolText(m)));
        QCOMPARE(std::make_pair(cycle, row.value(QStringLiteral("Main.Y3"))), std::make_pair(cycle, boolText(y3)));
        QCOMPARE(std::make_pair(cycle, row.value(QStringLiteral("Main.Init.x"))), std::make_pair(cycle, boolText(init)));
    }
}

QTEST_GUILESS_MAIN(TestExampleMixingTank)
#include "tst_example_mixing_tank.moc"
