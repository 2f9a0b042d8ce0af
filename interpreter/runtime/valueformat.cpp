#include "interpreter/runtime/valueformat.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>

namespace iec::interp {

QString formatBool(bool value)
{
    return value ? QStringLiteral("TRUE") : QStringLiteral("FALSE");
}

QString formatInteger(std::int64_t value)
{
    return QString::number(value);
}

QString formatUnsigned(std::uint64_t value)
{
    return QString::number(value);
}

namespace {

// "1.5e+07" as plain digits, "15000000": the digits of the shortest form with the point moved, so a
// float keeps its shortest digits (1e+15 is not written as the float's exact 999999986991104).
QString withoutExponent(const QString &scientific)
{
    const qsizetype e = scientific.indexOf(QLatin1Char('e'));
    const bool negative = scientific.startsWith(QLatin1Char('-'));
    QString mantissa = scientific.mid(negative ? 1 : 0, e - (negative ? 1 : 0));
    const int exponent = scientific.mid(e + 1).toInt();
    qsizetype point = mantissa.indexOf(QLatin1Char('.'));
    if (point < 0)
        point = mantissa.size();
    mantissa.remove(QLatin1Char('.'));
    const qsizetype position = point + exponent; // digits before the point
    QString text;
    if (position <= 0)
        text = QStringLiteral("0.") + QString(-position, QLatin1Char('0')) + mantissa;
    else if (position >= mantissa.size())
        text = mantissa + QString(position - mantissa.size(), QLatin1Char('0'));
    else
        text = mantissa.left(position) + QLatin1Char('.') + mantissa.mid(position);
    return negative ? QLatin1Char('-') + text : text;
}

// Shortest round-trip text of a float or double; plain digits rather than 1e+06 for the
// magnitudes a PLC program meets every day; always a '.' or an exponent.
template <typename Real>
QString formatFloating(Real value)
{
    if (std::isnan(value))
        return QStringLiteral("NaN");
    if (std::isinf(value))
        return value > 0 ? QStringLiteral("+Inf") : QStringLiteral("-Inf");
    std::array<char, 64> buffer{};
    // std::to_chars without a precision gives the shortest round-trip form of the type.
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    QString text = QString::fromLatin1(buffer.data(), result.ptr - buffer.data());
    const Real magnitude = std::fabs(value);
    if (text.contains(QLatin1Char('e')) && magnitude >= Real(1e-5) && magnitude < Real(1e16))
        text = withoutExponent(text);
    if (!text.contains(QLatin1Char('.')) && !text.contains(QLatin1Char('e')))
        text += QStringLiteral(".0");
    return text;
}

} // namespace

QString formatReal(double value)
{
    return formatFloating(value);
}

QString formatReal(float value)
{
    return formatFloating(value);
}

QString formatDuration(std::int64_t nanoseconds)
{
    if (nanoseconds == 0)
        return QStringLiteral("T#0s");
    QString text = QStringLiteral("T#");
    // Negate in unsigned arithmetic so INT64_MIN does not overflow.
    std::uint64_t rest = static_cast<std::uint64_t>(nanoseconds);
    if (nanoseconds < 0) {
        text += QLatin1Char('-');
        rest = 0 - rest;
    }
    struct Unit {
        std::uint64_t nanoseconds;
        const char *suffix;
    };
    static constexpr std::array<Unit, 7> units{{
        {86'400'000'000'000ULL, "d"},
        {3'600'000'000'000ULL, "h"},
        {60'000'000'000ULL, "m"},
        {1'000'000'000ULL, "s"},
        {1'000'000ULL, "ms"},
        {1'000ULL, "us"},
        {1ULL, "ns"},
    }};
    for (const Unit &unit : units) {
        const std::uint64_t count = rest / unit.nanoseconds;
        rest %= unit.nanoseconds;
        if (count != 0)
            text += QString::number(count) + QLatin1String(unit.suffix);
    }
    return text;
}

namespace {

constexpr std::int64_t kNsPerDay = 86'400'000'000'000LL;

// Floor division, so times before 1970 still give a date and a time in [0, 24h).
std::int64_t floorDiv(std::int64_t a, std::int64_t b)
{
    return a / b - ((a % b != 0) && ((a < 0) != (b < 0)) ? 1 : 0);
}

// Proleptic Gregorian date of a day count since 1970-01-01 (H. Hinnant's civil_from_days).
QString dateText(std::int64_t days)
{
    days += 719468;
    const std::int64_t era = floorDiv(days, 146097);
    const std::int64_t doe = days - era * 146097;
    const std::int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const std::int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const std::int64_t mp = (5 * doy + 2) / 153;
    const std::int64_t day = doy - (153 * mp + 2) / 5 + 1;
    const std::int64_t month = mp < 10 ? mp + 3 : mp - 9;
    const std::int64_t year = yoe + era * 400 + (month <= 2 ? 1 : 0);
    return QStringLiteral("%1-%2-%3").arg(year, 4, 10, QLatin1Char('0')).arg(month, 2, 10, QLatin1Char('0')).arg(day, 2, 10, QLatin1Char('0'));
}

QString clockText(std::int64_t ns)
{
    const std::int64_t seconds = ns / 1'000'000'000LL;
    const std::int64_t fraction = ns % 1'000'000'000LL;
    QString text = QStringLiteral("%1:%2:%3")
                       .arg(seconds / 3600, 2, 10, QLatin1Char('0'))
                       .arg(seconds / 60 % 60, 2, 10, QLatin1Char('0'))
                       .arg(seconds % 60, 2, 10, QLatin1Char('0'));
    if (fraction != 0) {
        QString digits = QStringLiteral("%1").arg(fraction, 9, 10, QLatin1Char('0'));
        while (digits.endsWith(QLatin1Char('0')))
            digits.chop(1);
        text += QLatin1Char('.') + digits;
    }
    return text;
}

// Control characters as $hh in a STRING, $hhhh in a WSTRING (IEC 61131-3: two hex digits per
// byte, four per WCHAR), so the text reads back to the same value.
QString quoted(const QString &value, QChar quote, int hexDigits)
{
    QString text(quote);
    for (const QChar c : value) {
        if (c == quote || c == QLatin1Char('$')) {
            text += QLatin1Char('$');
            text += c;
        } else if (c == QLatin1Char('\n')) {
            text += QStringLiteral("$N");
        } else if (c == QLatin1Char('\r')) {
            text += QStringLiteral("$R");
        } else if (c == QLatin1Char('\t')) {
            text += QStringLiteral("$T");
        } else if (c == QLatin1Char('\f')) {
            text += QStringLiteral("$P");
        } else if (c.unicode() < 0x20) {
            text += QStringLiteral("$%1").arg(c.unicode(), hexDigits, 16, QLatin1Char('0')).toUpper();
        } else {
            text += c;
        }
    }
    text += quote;
    return text;
}

} // namespace

QString formatDate(std::int64_t nanoseconds)
{
    return QStringLiteral("D#") + dateText(floorDiv(nanoseconds, kNsPerDay));
}

QString formatTimeOfDay(std::int64_t nanoseconds)
{
    return QStringLiteral("TOD#") + clockText(nanoseconds - floorDiv(nanoseconds, kNsPerDay) * kNsPerDay);
}

QString formatDateAndTime(std::int64_t nanoseconds)
{
    const std::int64_t days = floorDiv(nanoseconds, kNsPerDay);
    return QStringLiteral("DT#") + dateText(days) + QLatin1Char('-') + clockText(nanoseconds - days * kNsPerDay);
}

QString formatString(const QString &value)
{
    return quoted(value, QLatin1Char('\''), 2);
}

QString formatWString(const QString &value)
{
    return quoted(value, QLatin1Char('"'), 4);
}

} // namespace iec::interp
