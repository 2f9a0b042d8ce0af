#include "interpreter/runtime/valueformat.h"

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

QString formatReal(double value)
{
    if (std::isnan(value))
        return QStringLiteral("NaN");
    if (std::isinf(value))
        return value > 0 ? QStringLiteral("+Inf") : QStringLiteral("-Inf");
    std::array<char, 64> buffer{};
    // std::to_chars without a precision gives the shortest round-trip form.
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    QString text = QString::fromLatin1(buffer.data(), result.ptr - buffer.data());
    if (!text.contains(QLatin1Char('.')) && !text.contains(QLatin1Char('e')))
        text += QStringLiteral(".0");
    return text;
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

QString quoted(const QString &value, QChar quote)
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
            text += QStringLiteral("$%1").arg(c.unicode(), 2, 16, QLatin1Char('0')).toUpper();
        } else {
            text += c;
        }
    }
    text += quote;
    return text;
}

} // namespace

QString formatString(const QString &value)
{
    return quoted(value, QLatin1Char('\''));
}

QString formatWString(const QString &value)
{
    return quoted(value, QLatin1Char('"'));
}

} // namespace iec::interp
