// The standard function blocks scan by scan, at a 10 ms cycle.
#include "tracerunner.h"

#include <QTest>

using namespace iec::interp;
using namespace iec::interp::testing;

class TestStandardFunctionBlocks : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void traces_data();
    void traces();
    void tonSetsQInTheScanWhereEtReachesPt();
    void timerKeepsTimeAcrossLongRuns();
};

void TestStandardFunctionBlocks::traces_data()
{
    // Every row runs twice: with the timers in C++ (the default) and in their ST source. Both
    // must give the same trace.
    QTest::addColumn<QString>("source");
    QTest::addColumn<QStringList>("steps");
    QTest::addColumn<bool>("native");
    const auto row = [](const char *name, const char *source, const QStringList &steps) {
        QTest::newRow(name) << QString::fromUtf8(source) << steps << true;
        QTest::newRow(QByteArray(name).append(" (ST)").constData()) << QString::fromUtf8(source) << steps << false;
    };
    row("TON", "VAR t : TON; in : BOOL; q : BOOL; et : TIME; END_VAR\nt(IN := in, PT := T#30ms, Q => q, ET => et);",
        {"in=TRUE => q=FALSE; et=T#0s", "=> q=FALSE; et=T#10ms", "=> q=FALSE; et=T#20ms", "=> q=TRUE; et=T#30ms", "=> q=TRUE; et=T#30ms",
         "in=FALSE => q=FALSE; et=T#0s", "in=TRUE => q=FALSE; et=T#0s", "in=FALSE => q=FALSE", "in=TRUE => et=T#0s", "=> et=T#10ms"});
    row("TON with PT zero", "VAR t : TON; END_VAR\nt(IN := TRUE, PT := T#0s);", {"=> t.Q=TRUE; t.ET=T#0s"});
    row("TOF", "VAR t : TOF; in : BOOL; END_VAR\nt(IN := in, PT := T#30ms);",
        {"=> t.Q=FALSE", "in=TRUE => t.Q=TRUE; t.ET=T#0s", "in=FALSE => t.Q=TRUE; t.ET=T#0s", "=> t.Q=TRUE; t.ET=T#10ms", "=> t.Q=TRUE; t.ET=T#20ms",
         "=> t.Q=FALSE; t.ET=T#30ms", "=> t.Q=FALSE; t.ET=T#30ms", "in=TRUE => t.Q=TRUE; t.ET=T#0s", "in=FALSE => t.Q=TRUE", "in=TRUE => t.Q=TRUE; t.ET=T#0s"});
    row("TP", "VAR t : TP; in : BOOL; END_VAR\nt(IN := in, PT := T#30ms);",
        {"in=TRUE => t.Q=TRUE; t.ET=T#0s", "in=FALSE => t.Q=TRUE; t.ET=T#10ms", "in=TRUE => t.Q=TRUE; t.ET=T#20ms", "=> t.Q=FALSE; t.ET=T#30ms",
         "=> t.Q=FALSE; t.ET=T#30ms", "in=FALSE => t.Q=FALSE; t.ET=T#0s", "in=TRUE => t.Q=TRUE; t.ET=T#0s"});
    row("CTU", "VAR c : CTU; cu : BOOL; r : BOOL; END_VAR\nc(CU := cu, R := r, PV := 2);",
        {"cu=TRUE => c.CV=1; c.Q=FALSE", "=> c.CV=1", "cu=FALSE => c.CV=1", "cu=TRUE => c.CV=2; c.Q=TRUE", "cu=FALSE => c.CV=2",
         "cu=TRUE => c.CV=3; c.Q=TRUE", "r=TRUE => c.CV=0; c.Q=FALSE", "r=FALSE; cu=FALSE => c.CV=0"});
    row("CTU stops at the maximum", "VAR c : CTU; cu : BOOL; END_VAR\ncu := NOT cu; c(CU := cu, PV := 1);",
        {"c.CV=32766 => c.CV=32767", "=> c.CV=32767", "=> c.CV=32767; c.Q=TRUE"});
    row("CTD", "VAR c : CTD; cd : BOOL; ld : BOOL; END_VAR\nc(CD := cd, LD := ld, PV := 2);",
        {"=> c.CV=0; c.Q=TRUE", "ld=TRUE => c.CV=2; c.Q=FALSE", "ld=FALSE; cd=TRUE => c.CV=1", "cd=FALSE => c.CV=1", "cd=TRUE => c.CV=0; c.Q=TRUE",
         "cd=FALSE => c.CV=0", "cd=TRUE => c.CV=-1; c.Q=TRUE"});
    row("CTUD", "VAR c : CTUD; cu : BOOL; cd : BOOL; r : BOOL; ld : BOOL; END_VAR\nc(CU := cu, CD := cd, R := r, LD := ld, PV := 3);",
        {"ld=TRUE => c.CV=3; c.QU=TRUE; c.QD=FALSE", "ld=FALSE; cd=TRUE => c.CV=2; c.QU=FALSE", "cd=FALSE; cu=TRUE => c.CV=3; c.QU=TRUE",
         "cu=FALSE => c.CV=3", "cu=TRUE; cd=TRUE => c.CV=3", "cu=FALSE; cd=FALSE; r=TRUE => c.CV=0; c.QD=TRUE; c.QU=FALSE"});
    row("CTU_DINT and CTD_UDINT", "VAR a : CTU_DINT; b : CTD_UDINT; p : BOOL; END_VAR\np := NOT p; a(CU := p, PV := 100000); b(CD := p, LD := FALSE, PV := 5);",
        {"=> a.CV=1; b.CV=0", "=> a.CV=1", "=> a.CV=2; b.CV=0; b.Q=TRUE"});
    row("R_TRIG", "VAR t : R_TRIG; clk : BOOL; END_VAR\nt(CLK := clk);",
        {"=> t.Q=FALSE", "clk=TRUE => t.Q=TRUE", "=> t.Q=FALSE", "clk=FALSE => t.Q=FALSE", "clk=TRUE => t.Q=TRUE"});
    row("F_TRIG", "VAR t : F_TRIG; clk : BOOL; END_VAR\nt(CLK := clk);",
        {"=> t.Q=FALSE", "clk=TRUE => t.Q=FALSE", "clk=FALSE => t.Q=TRUE", "=> t.Q=FALSE"});
    row("SR is set dominant", "VAR f : SR; s : BOOL; r : BOOL; END_VAR\nf(S1 := s, R := r);",
        {"s=TRUE => f.Q1=TRUE", "s=FALSE => f.Q1=TRUE", "r=TRUE => f.Q1=FALSE", "s=TRUE => f.Q1=TRUE"});
    row("RS is reset dominant", "VAR f : RS; s : BOOL; r : BOOL; END_VAR\nf(S := s, R1 := r);",
        {"s=TRUE => f.Q1=TRUE", "s=FALSE => f.Q1=TRUE", "r=TRUE; s=TRUE => f.Q1=FALSE", "r=FALSE => f.Q1=TRUE"});
}

void TestStandardFunctionBlocks::traces()
{
    QFETCH(QString, source);
    QFETCH(QStringList, steps);
    QFETCH(bool, native);
    CompileOptions options;
    options.nativeStandardBlocks = native;
    QCOMPARE(runTrace(source, steps, options), QString());
}

void TestStandardFunctionBlocks::tonSetsQInTheScanWhereEtReachesPt()
{
    // The rule: PT = T#100ms at a 10 ms cycle, Q in the 11th call (ET = 100 ms), never
    // in the first.
    QStringList steps;
    for (int cycle = 1; cycle <= 13; ++cycle) {
        const int et = std::min(100, (cycle - 1) * 10);
        steps << QStringLiteral("=> q=%1; et=%2").arg(cycle >= 11 ? QStringLiteral("TRUE") : QStringLiteral("FALSE"),
                                                      et == 0 ? QStringLiteral("T#0s") : QStringLiteral("T#%1ms").arg(et));
    }
    QCOMPARE(runTrace(QStringLiteral("VAR t : TON; q : BOOL; et : TIME; END_VAR\nt(IN := TRUE, PT := T#100ms); q := t.Q; et := t.ET;"), steps), QString());
}

void TestStandardFunctionBlocks::timerKeepsTimeAcrossLongRuns()
{
    // One hour of 10 ms cycles: the virtual clock is exact, so the timer ends on the cycle.
    QStringList steps(360'000, QString());
    steps[359'999] = QStringLiteral("=> t.Q=FALSE; t.ET=T#59m59s990ms");
    steps << QStringLiteral("=> t.Q=TRUE; t.ET=T#1h");
    QCOMPARE(runTrace(QStringLiteral("VAR t : TON; END_VAR\nt(IN := TRUE, PT := T#1h);"), steps), QString());
}

QTEST_GUILESS_MAIN(TestStandardFunctionBlocks)
#include "tst_stdfb.moc"
