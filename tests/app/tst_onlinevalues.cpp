// Which variables each line of an ST or IL body shows online, and how a value box reads.
#include "editors/text/onlinevalues.h"

#include <QTest>

using namespace iec::editors;

class TestOnlineValues : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void pathsPerLine_data();
    void pathsPerLine();
    void onlineNames();
    void chipText();
};

void TestOnlineValues::pathsPerLine_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QList<QStringList>>("expected");
    using L = QList<QStringList>;
    QTest::newRow("assignment") << QStringLiteral("Count := Count + Delta;") << L{{"Count", "Delta"}};
    QTest::newRow("members and bits") << QStringLiteral("Tank.Level := W.3;")
                                      << L{{"Tank.Level", "W.3"}};
    QTest::newRow("literal index kept, computed index dropped")
        << QStringLiteral("A[2] := B[i] + M[1, 2];") << L{{"A[2]", "i", "M[1, 2]"}};
    QTest::newRow("calls and formal parameters")
        << QStringLiteral("Timer(IN := Start, PT := T#1s); x := ABS(y);")
        << L{{"Start", "x", "y"}};
    QTest::newRow("FB output after the call") << QStringLiteral("Done := Timer.Q;") << L{{"Done", "Timer.Q"}};
    QTest::newRow("keywords, literals, comments")
        << QStringLiteral("IF Run AND NOT Stop THEN (* Level *) n := 16#FF; END_IF")
        << L{{"Run", "Stop", "n"}};
    QTest::newRow("comment across lines") << QStringLiteral("a := 1; (* b\nc *) d := 2;") << L{{"a"}, {"d"}};
    QTest::newRow("direct addresses") << QStringLiteral("%QX0.1 := %IX0.0;") << L{{"%QX0.1", "%IX0.0"}};
    QTest::newRow("IL with label") << QStringLiteral("Start: LD Count\n  ADD 1\n  ST Count\n  JMPC Start")
                                   << L{{"Count"}, {}, {"Count"}, {"Start"}};
    QTest::newRow("each path once per line") << QStringLiteral("x := x * x;") << L{{"x"}};
    QTest::newRow("empty") << QString() << L{{}};
}

void TestOnlineValues::pathsPerLine()
{
    QFETCH(QString, text);
    QFETCH(QList<QStringList>, expected);
    const std::vector<QStringList> paths = variablePathsByLine(text);
    QCOMPARE(QList<QStringList>(paths.begin(), paths.end()), expected);
}

void TestOnlineValues::onlineNames()
{
    QCOMPARE(onlineName(QStringLiteral("Main"), QStringLiteral("Tank.Level")), QStringLiteral("Main.Tank.Level"));
    QCOMPARE(onlineName(QStringLiteral("Main.Filler"), QStringLiteral("n")), QStringLiteral("Main.Filler.n"));
    QCOMPARE(onlineName(QStringLiteral("Main"), QStringLiteral("%IX0.0")), QStringLiteral("%IX0.0"));
    QCOMPARE(onlineName(QString(), QStringLiteral("n")), QStringLiteral("n"));
}

void TestOnlineValues::chipText()
{
    QCOMPARE(iec::editors::chipText({QStringLiteral("Count"), QStringLiteral("42"), false}), QStringLiteral("Count = 42"));
    const QString longValue(40, QLatin1Char('x'));
    const QString shown = iec::editors::chipText({QStringLiteral("S"), longValue, true});
    QCOMPARE(shown.size(), 4 + 24);
    QVERIFY(shown.endsWith(QChar(0x2026)));
    // The label and the first 23 characters of the value stay; the rest becomes the ellipsis.
    QCOMPARE(shown, QStringLiteral("S = ") + QString(23, QLatin1Char('x')) + QChar(0x2026));
    // A value that fits is shown whole.
    const QString fits(24, QLatin1Char('y'));
    QCOMPARE(iec::editors::chipText({QStringLiteral("S"), fits, false}), QStringLiteral("S = ") + fits);
}

QTEST_GUILESS_MAIN(TestOnlineValues)
#include "tst_onlinevalues.moc"
