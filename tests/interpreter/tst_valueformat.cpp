#include "interpreter/compiler/literals.h"
#include "interpreter/frontend/duration.h"
#include "interpreter/runtime/valueformat.h"

#include <QTest>

#include <limits>

using namespace iec::interp;

class TestValueFormat : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void durations_data();
    void durations();
    void parsedDurations_data();
    void parsedDurations();
    void reals_data();
    void reals();
    void strings_data();
    void strings();
    void booleansAndIntegers();
};

void TestValueFormat::durations_data()
{
    QTest::addColumn<qint64>("nanoseconds");
    QTest::addColumn<QString>("text");
    constexpr qint64 ms = 1'000'000;
    QTest::newRow("zero") << qint64{0} << QStringLiteral("T#0s");
    QTest::newRow("1s500ms") << 1500 * ms << QStringLiteral("T#1s500ms");
    QTest::newRow("100ms") << 100 * ms << QStringLiteral("T#100ms");
    QTest::newRow("1h2m3s4ms") << (3723 * 1000 + 4) * ms << QStringLiteral("T#1h2m3s4ms");
    QTest::newRow("one day") << 86'400'000 * ms << QStringLiteral("T#1d");
    QTest::newRow("us and ns") << qint64{2'005} << QStringLiteral("T#2us5ns");
    QTest::newRow("negative") << -250 * ms << QStringLiteral("T#-250ms");
    // Found by fuzz_values: read through a double, the last nanoseconds of a long time changed.
    QTest::newRow("long time to the nanosecond") << qint64{5'555'555'551'109'999'616}
                                                 << QStringLiteral("T#64300d9h52m31s109ms999us616ns");
    QTest::newRow("most negative") << std::numeric_limits<qint64>::min()
                                   << QStringLiteral("T#-106751d23h47m16s854ms775us808ns");
}

void TestValueFormat::durations()
{
    QFETCH(qint64, nanoseconds);
    QFETCH(QString, text);
    QCOMPARE(formatDuration(nanoseconds), text);
    QCOMPARE(decodeDuration(QStringView(text).mid(2)), std::optional<std::int64_t>(nanoseconds)); // reads back
}

void TestValueFormat::parsedDurations_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<std::optional<qint64>>("nanoseconds");
    constexpr qint64 ms = 1'000'000;
    QTest::newRow("ISO seconds") << QStringLiteral("PT0.01S") << std::optional<qint64>(10 * ms);
    QTest::newRow("ISO every part") << QStringLiteral("P1DT2H3M4.5S") << std::optional<qint64>((93'784'500) * ms);
    QTest::newRow("ISO negative") << QStringLiteral("-PT1M") << std::optional<qint64>(-60'000 * ms);
    QTest::newRow("ISO most negative") << QStringLiteral("-PT9223372036.854775808S")
                                       << std::optional<qint64>(std::numeric_limits<qint64>::min());
    // Found by fuzz_values: a double overflowed and its negation was undefined.
    QTest::newRow("ISO too long") << QStringLiteral("-PT52222222222222222222S") << std::optional<qint64>();
    QTest::newRow("ISO without parts") << QStringLiteral("PT") << std::optional<qint64>();
    QTest::newRow("IEC") << QStringLiteral("T#1h2m") << std::optional<qint64>(3'720'000 * ms);
    QTest::newRow("bare milliseconds") << QStringLiteral("250") << std::optional<qint64>(250 * ms);
}

void TestValueFormat::parsedDurations()
{
    QFETCH(QString, text);
    QFETCH(std::optional<qint64>, nanoseconds);
    const std::optional<std::int64_t> parsed = frontend::parseDuration(text);
    QCOMPARE(parsed.has_value(), nanoseconds.has_value());
    if (parsed)
        QCOMPARE(qint64(*parsed), *nanoseconds);
}

void TestValueFormat::reals_data()
{
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("text");
    QTest::newRow("1.5") << 1.5 << QStringLiteral("1.5");
    QTest::newRow("integral") << 1.0 << QStringLiteral("1.0");
    QTest::newRow("negative") << -0.25 << QStringLiteral("-0.25");
    QTest::newRow("shortest round trip") << 0.1 << QStringLiteral("0.1");
    QTest::newRow("exponent") << 1e300 << QStringLiteral("1e+300");
    QTest::newRow("million in plain digits") << 1e6 << QStringLiteral("1000000.0");
    QTest::newRow("small in plain digits") << 0.0001 << QStringLiteral("0.0001");
    QTest::newRow("tiny keeps exponent") << 1e-7 << QStringLiteral("1e-07");
    QTest::newRow("infinity") << std::numeric_limits<double>::infinity() << QStringLiteral("+Inf");
}

void TestValueFormat::reals()
{
    QFETCH(double, value);
    QFETCH(QString, text);
    QCOMPARE(formatReal(value), text);
}

void TestValueFormat::strings_data()
{
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("single");
    QTest::addColumn<QString>("wide");
    QTest::newRow("plain") << QStringLiteral("text") << QStringLiteral("'text'") << QStringLiteral("\"text\"");
    QTest::newRow("quotes") << QStringLiteral("it's \"x\"") << QStringLiteral("'it$'s \"x\"'")
                            << QStringLiteral("\"it's $\"x$\"\"");
    QTest::newRow("dollar and newline") << QStringLiteral("5$\n") << QStringLiteral("'5$$$N'")
                                        << QStringLiteral("\"5$$$N\"");
    QTest::newRow("control") << QStringLiteral("\x1b") << QStringLiteral("'$1B'") << QStringLiteral("\"$001B\""); // WSTRING: four digits
    QTest::newRow("empty") << QString() << QStringLiteral("''") << QStringLiteral("\"\"");
}

void TestValueFormat::strings()
{
    QFETCH(QString, value);
    QFETCH(QString, single);
    QFETCH(QString, wide);
    QCOMPARE(formatString(value), single);
    QCOMPARE(formatWString(value), wide);
}

void TestValueFormat::booleansAndIntegers()
{
    QCOMPARE(formatBool(true), QStringLiteral("TRUE"));
    QCOMPARE(formatBool(false), QStringLiteral("FALSE"));
    QCOMPARE(formatInteger(-32768), QStringLiteral("-32768"));
    QCOMPARE(formatUnsigned(std::numeric_limits<std::uint64_t>::max()), QStringLiteral("18446744073709551615"));
}

QTEST_GUILESS_MAIN(TestValueFormat)
#include "tst_valueformat.moc"
