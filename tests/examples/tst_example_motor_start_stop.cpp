// resources/examples/motor_start_stop.xml (LD): seal-in with normally closed Stop and Overload
// contacts; stop wins over start. Run through iecstudio-cli, checked scan by scan.
#include "clitrace.h"

#include <QTest>

using namespace iec::testing;

class TestExampleMotorStartStop : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void motorFollowsTheButtons();
};

void TestExampleMotorStartStop::motorFollowsTheButtons()
{
    const QStringList sets {QStringLiteral("Main.Start=TRUE@2"), QStringLiteral("Main.Start=FALSE@3"),
        QStringLiteral("Main.Stop=TRUE@5"), QStringLiteral("Main.Stop=FALSE@6"), QStringLiteral("Main.Start=TRUE@7"),
        QStringLiteral("Main.Stop=TRUE@7"), QStringLiteral("Main.Stop=FALSE@8"), QStringLiteral("Main.Start=FALSE@9"),
        QStringLiteral("Main.Overload=TRUE@10"), QStringLiteral("Main.Overload=FALSE@11"),
        QStringLiteral("Main.Start=TRUE@12"), QStringLiteral("Main.Start=FALSE@13")};
    const CliTrace trace = runExample(QStringLiteral("motor_start_stop.xml"), 14, sets, {QStringLiteral("Main.Motor")});
    QCOMPARE(trace.error, QString());
    // Cycle:   1      2     3     4     5      6      7 (start and stop: stop wins)
    //          8 (stop released, start held)  9  10 (overload)  11  12 (start again) 13 14
    const bool expected[] = {false, true, true, true, false, false, false, true, true, false, false, true, true, true};
    for (int cycle = 1; cycle <= 14; ++cycle)
        QCOMPARE(std::make_pair(cycle, trace.cycles[std::size_t(cycle - 1)].value(QStringLiteral("Main.Motor"))),
            std::make_pair(cycle, boolText(expected[cycle - 1])));
}

QTEST_GUILESS_MAIN(TestExampleMotorStartStop)
#include "tst_example_motor_start_stop.moc"
