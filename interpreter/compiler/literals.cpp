#include "interpreter/compiler/literals.h"

#include <array>
#include <cmath>
#include <limits>
#include <string_view>

namespace iec::interp {

namespace {

bool isDigit(QChar c)
{
    return c >= QLatin1Char('0') && c <= QLatin1Char('9');
}

int digitValue(QChar c)
{
    const char16_t u = c.unicode();
    if (u >= u'0' && u <= u'9')
        return u - u'0';
    if (u >= u'a' && u <= u'z')
        return u - u'a' + 10;
    if (u >= u'A' && u <= u'Z')
        return u - u'A' + 10;
    return 99;
}

bool equalsUpper(QStringView text, std::string_view upper)
{
    if (text.size() != static_cast<qsizetype>(upper.size()))
        return false;
    for (qsizetype i = 0; i < text.size(); ++i) {
        if (text[i].toUpper().unicode() != static_cast<char16_t>(upper[static_cast<size_t>(i)]))
            return false;
    }
    return true;
}

// Digits of `base` with single underscores between them; at least one digit.
std::optional<std::uint64_t> decodeDigits(QStringView text, unsigned base)
{
    if (text.isEmpty() || text.front() == QLatin1Char('_') || text.back() == QLatin1Char('_'))
        return std::nullopt;
    std::uint64_t value = 0;
    QChar previous;
    for (const QChar c : text) {
        if (c == QLatin1Char('_')) {
            if (previous == QLatin1Char('_'))
                return std::nullopt;
            previous = c;
            continue;
        }
        const int digit = digitValue(c);
        if (digit >= static_cast<int>(base))
            return std::nullopt;
        if (value > (UINT64_MAX - static_cast<unsigned>(digit)) / base)
            return std::nullopt; // does not fit 64 bits
        value = value * base + static_cast<unsigned>(digit);
        previous = c;
    }
    return value;
}

// Decimal digits with single underscores between them, however many (a REAL may have more digits
// than 64 bits hold: OSCAT writes PI with 36).
bool isDecimalDigits(QStringView text)
{
    if (text.isEmpty() || text.front() == QLatin1Char('_') || text.back() == QLatin1Char('_'))
        return false;
    QChar previous;
    for (const QChar c : text) {
        if (c == QLatin1Char('_') ? previous == QLatin1Char('_') : !c.isDigit() || c.unicode() > u'9')
            return false;
        previous = c;
    }
    return true;
}

// A decimal number with optional fraction as a double ("3", "3.5", "1_000.25"), rounded to the
// nearest double whatever its number of digits.
std::optional<double> decodeDecimal(QStringView text)
{
    const qsizetype dot = text.indexOf(QLatin1Char('.'));
    const QStringView whole = dot < 0 ? text : text.left(dot);
    if (!isDecimalDigits(whole))
        return std::nullopt;
    if (dot >= 0 && !isDecimalDigits(text.mid(dot + 1)))
        return std::nullopt;
    QString plain = text.toString();
    plain.remove(QLatin1Char('_'));
    bool ok = false;
    const double value = plain.toDouble(&ok);
    return ok ? std::optional<double>(value) : std::nullopt;
}

__extension__ typedef __int128 Wide128;

// A decimal number ("12", "1.5", "1_000.25") times a whole number of nanoseconds, exactly:
// doubles lose the last nanoseconds of long times, so T#64300d…ms printed and read back would
// differ (found by fuzz_values). Fractions below a nanosecond round to nearest.
std::optional<Wide128> scaledDecimal(QStringView text, std::int64_t unit)
{
    if (!decodeDecimal(text))
        return std::nullopt;
    // Past 2^64 the result overflows a time anyway; the bound keeps every product below 2^113.
    constexpr Wide128 kLimit = static_cast<Wide128>(1) << 64;
    Wide128 whole = 0;
    qsizetype i = 0;
    for (; i < text.size() && text[i] != QLatin1Char('.'); ++i) {
        if (text[i] == QLatin1Char('_'))
            continue;
        whole = whole * 10 + (text[i].unicode() - u'0');
        if (whole > kLimit)
            return std::nullopt;
    }
    Wide128 numerator = 0, denominator = 1;
    for (++i; i < text.size(); ++i) {
        if (text[i] == QLatin1Char('_') || denominator > kLimit / 10)
            continue; // digits beyond 19 decimals cannot change a nanosecond
        numerator = numerator * 10 + (text[i].unicode() - u'0');
        denominator *= 10;
    }
    const Wide128 fraction = (numerator * unit * 2 + denominator) / (denominator * 2);
    return whole * unit + fraction;
}

struct Date {
    int year = 0, month = 0, day = 0;
};

// Days from 1970-01-01 to a proleptic Gregorian date (H. Hinnant's days_from_civil).
std::int64_t daysFromCivil(Date d)
{
    const int y = d.year - (d.month <= 2 ? 1 : 0);
    const int era = (y >= 0 ? y : y - 399) / 400;
    const int yoe = y - era * 400;
    const int mp = (d.month + 9) % 12;
    const int doy = (153 * mp + 2) / 5 + d.day - 1;
    const int doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return static_cast<std::int64_t>(era) * 146097 + doe - 719468;
}

bool isLeap(int year)
{
    return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

std::optional<Date> parseDate(QStringView text)
{
    const auto parts = text.split(QLatin1Char('-'));
    if (parts.size() != 3)
        return std::nullopt;
    std::array<int, 3> numbers{};
    for (int i = 0; i < 3; ++i) {
        const auto value = decodeDigits(parts[i], 10);
        if (!value || *value > 99999)
            return std::nullopt;
        numbers[static_cast<size_t>(i)] = static_cast<int>(*value);
    }
    const Date date{numbers[0], numbers[1], numbers[2]};
    static constexpr std::array<int, 12> monthDays{31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (date.month < 1 || date.month > 12 || date.day < 1 || date.day > monthDays[static_cast<size_t>(date.month - 1)])
        return std::nullopt;
    if (date.month == 2 && date.day == 29 && !isLeap(date.year))
        return std::nullopt;
    return date;
}

} // namespace

LiteralParts splitTypedLiteral(QStringView text)
{
    // The prefix ends at the first '#' that follows an identifier; 16#FF has a digit prefix.
    const qsizetype hash = text.indexOf(QLatin1Char('#'));
    if (hash <= 0 || isDigit(text.front()) || text.front() == QLatin1Char('\'') || text.front() == QLatin1Char('"'))
        return {{}, text};
    for (qsizetype i = 0; i < hash; ++i) {
        const QChar c = text[i];
        if (!(c.isLetterOrNumber() || c == QLatin1Char('_')))
            return {{}, text};
    }
    return {text.left(hash), text.mid(hash + 1)};
}

std::optional<IntegerValue> decodeInteger(QStringView text)
{
    IntegerValue result;
    if (!text.isEmpty() && (text.front() == QLatin1Char('-') || text.front() == QLatin1Char('+'))) {
        result.negative = text.front() == QLatin1Char('-');
        text = text.mid(1);
    }
    unsigned base = 10;
    const qsizetype hash = text.indexOf(QLatin1Char('#'));
    if (hash >= 0) {
        const QStringView prefix = text.left(hash);
        if (prefix == u"2")
            base = 2;
        else if (prefix == u"8")
            base = 8;
        else if (prefix == u"16")
            base = 16;
        else
            return std::nullopt;
        text = text.mid(hash + 1);
    }
    const auto magnitude = decodeDigits(text, base);
    if (!magnitude)
        return std::nullopt;
    result.magnitude = *magnitude;
    return result;
}

std::optional<double> decodeReal(QStringView text)
{
    double sign = 1.0;
    if (!text.isEmpty() && (text.front() == QLatin1Char('-') || text.front() == QLatin1Char('+'))) {
        sign = text.front() == QLatin1Char('-') ? -1.0 : 1.0;
        text = text.mid(1);
    }
    qsizetype e = text.indexOf(QLatin1Char('e'), 0, Qt::CaseInsensitive);
    QStringView mantissa = e < 0 ? text : text.left(e);
    const auto value = decodeDecimal(mantissa);
    if (!value)
        return std::nullopt;
    double exponent = 0;
    if (e >= 0) {
        QStringView rest = text.mid(e + 1);
        double expSign = 1.0;
        if (!rest.isEmpty() && (rest.front() == QLatin1Char('-') || rest.front() == QLatin1Char('+'))) {
            expSign = rest.front() == QLatin1Char('-') ? -1.0 : 1.0;
            rest = rest.mid(1);
        }
        const auto digits = decodeDigits(rest, 10);
        if (!digits)
            return std::nullopt;
        exponent = expSign * static_cast<double>(*digits);
    }
    if (e < 0)
        return sign * *value;
    // Reparse the whole literal so 1.1E-3 is the nearest double, not 1.1 * 10^-3 rounded twice.
    QString plain = text.toString();
    plain.remove(QLatin1Char('_'));
    bool ok = false;
    const double exact = plain.toDouble(&ok);
    return sign * (ok ? exact : *value * std::pow(10.0, exponent));
}

std::optional<std::int64_t> decodeDuration(QStringView body)
{
    bool negative = false;
    if (!body.isEmpty() && (body.front() == QLatin1Char('-') || body.front() == QLatin1Char('+'))) {
        negative = body.front() == QLatin1Char('-');
        body = body.mid(1);
    }
    if (body.isEmpty())
        return std::nullopt;
    struct Unit {
        std::string_view name;
        std::int64_t nanoseconds;
    };
    // Longest names first so "ms" is not read as "m" followed by "s".
    static constexpr std::array<Unit, 7> units{{
        {"MS", 1'000'000},
        {"US", 1'000},
        {"NS", 1},
        {"D", 86'400'000'000'000},
        {"H", 3'600'000'000'000},
        {"M", 60'000'000'000},
        {"S", 1'000'000'000},
    }};
    Wide128 total = 0;
    qsizetype i = 0;
    int lastRank = -1;
    while (i < body.size()) {
        if (body[i] == QLatin1Char('_') && i > 0) {
            ++i;
            continue;
        }
        qsizetype start = i;
        while (i < body.size() && (isDigit(body[i]) || body[i] == QLatin1Char('.') || body[i] == QLatin1Char('_')))
            ++i;
        const QStringView number = body.mid(start, i - start);
        if (!decodeDecimal(number))
            return std::nullopt;
        if (i == body.size()) {
            if (start == 0) { // a bare number: milliseconds
                const auto ns = scaledDecimal(number, 1'000'000);
                if (!ns)
                    return std::nullopt;
                total = *ns;
                break;
            }
            return std::nullopt;
        }
        bool matched = false;
        for (size_t u = 0; u < units.size(); ++u) {
            const auto &unit = units[u];
            const qsizetype n = static_cast<qsizetype>(unit.name.size());
            if (i + n <= body.size() && equalsUpper(body.mid(i, n), unit.name)) {
                // A unit must be followed by a digit, '_' or the end (so "msx" is wrong).
                if (i + n < body.size() && !isDigit(body[i + n]) && body[i + n] != QLatin1Char('_'))
                    continue;
                // Units go from large to small: d, h, m, s, ms, us, ns.
                static constexpr std::array<int, 7> rank{4, 5, 6, 0, 1, 2, 3};
                if (rank[u] <= lastRank)
                    return std::nullopt;
                lastRank = rank[u];
                const auto ns = scaledDecimal(number, unit.nanoseconds);
                if (!ns)
                    return std::nullopt;
                total += *ns;
                i += n;
                matched = true;
                break;
            }
        }
        if (!matched)
            return std::nullopt;
    }
    // The most negative time has no positive counterpart: -(max + 1) is still a time.
    const Wide128 limit = static_cast<Wide128>(std::numeric_limits<std::int64_t>::max()) + (negative ? 1 : 0);
    if (total > limit)
        return std::nullopt;
    return static_cast<std::int64_t>(negative ? -total : total);
}

std::optional<std::int64_t> decodeDate(QStringView body)
{
    const auto date = parseDate(body);
    if (!date)
        return std::nullopt;
    // Dates count nanoseconds in 64 bits: about 292 years each way from 1970 (to 2262, with the
    // time of a DT added); a date beyond is refused, not wrapped (found by fuzz_values).
    constexpr std::int64_t kLastDay = 106'750;
    const std::int64_t days = daysFromCivil(*date);
    if (days > kLastDay || days < -kLastDay)
        return std::nullopt;
    return days * 86'400'000'000'000LL;
}

std::optional<std::int64_t> decodeTimeOfDay(QStringView body)
{
    const auto parts = body.split(QLatin1Char(':'));
    if (parts.size() < 2 || parts.size() > 3)
        return std::nullopt;
    const auto hours = decodeDigits(parts[0], 10);
    const auto minutes = decodeDigits(parts[1], 10);
    const auto seconds = parts.size() == 3 ? decodeDecimal(parts[2]) : std::optional<double>(0.0);
    if (!hours || !minutes || !seconds || *hours > 23 || *minutes > 59 || *seconds >= 60.0)
        return std::nullopt;
    return static_cast<std::int64_t>(*hours * 3600 + *minutes * 60) * 1'000'000'000LL
        + static_cast<std::int64_t>(std::llround(*seconds * 1e9));
}

std::optional<std::int64_t> decodeDateAndTime(QStringView body)
{
    // yyyy-mm-dd-hh:mm:ss: the date is everything before the third '-'.
    qsizetype dash = -1;
    for (int n = 0; n < 3; ++n) {
        dash = body.indexOf(QLatin1Char('-'), dash + 1);
        if (dash < 0)
            return std::nullopt;
    }
    const auto date = decodeDate(body.left(dash));
    const auto time = decodeTimeOfDay(body.mid(dash + 1));
    if (!date || !time)
        return std::nullopt;
    return *date + *time;
}

std::optional<QString> decodeString(QStringView quoted)
{
    if (quoted.size() < 2)
        return std::nullopt;
    const QChar quote = quoted.front();
    if ((quote != QLatin1Char('\'') && quote != QLatin1Char('"')) || quoted.back() != quote)
        return std::nullopt;
    const int hexDigits = quote == QLatin1Char('\'') ? 2 : 4;
    const QStringView inner = quoted.mid(1, quoted.size() - 2);
    QString result;
    for (qsizetype i = 0; i < inner.size(); ++i) {
        const QChar c = inner[i];
        if (c == quote)
            return std::nullopt; // an unescaped quote inside
        if (c != QLatin1Char('$')) {
            const std::optional<std::uint8_t> byte = quote == QLatin1Char('\'') ? windows1252Byte(c) : std::nullopt;
            result += byte ? QChar(char16_t(*byte)) : c;
            continue;
        }
        if (++i >= inner.size())
            return std::nullopt;
        const QChar e = inner[i].toUpper();
        switch (e.unicode()) {
        case u'$': result += QLatin1Char('$'); break;
        case u'\'': result += QLatin1Char('\''); break;
        case u'"': result += QLatin1Char('"'); break;
        case u'L':
        case u'N': result += QLatin1Char('\n'); break;
        case u'P': result += QLatin1Char('\f'); break;
        case u'R': result += QLatin1Char('\r'); break;
        case u'T': result += QLatin1Char('\t'); break;
        default: {
            const auto code = decodeDigits(inner.mid(i, hexDigits), 16);
            if (!code || inner.mid(i, hexDigits).contains(QLatin1Char('_')) || i + hexDigits > inner.size())
                return std::nullopt;
            result += QChar(static_cast<char16_t>(*code));
            i += hexDigits - 1;
        }
        }
    }
    return result;
}

namespace {

// Windows-1252's characters for 16#80..16#9F; the five bytes it leaves undefined keep the C1
// control characters Latin-1 gives them.
constexpr char16_t kWindows1252High[32] = {0x20AC, 0x0081, 0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6,
    0x2030, 0x0160, 0x2039, 0x0152, 0x008D, 0x017D, 0x008F, 0x0090, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2013,
    0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0x009D, 0x017E, 0x0178};

} // namespace

std::optional<std::uint8_t> windows1252Byte(QChar c)
{
    const char16_t u = c.unicode();
    if (u < 0x80 || (u >= 0xA0 && u <= 0xFF))
        return static_cast<std::uint8_t>(u);
    for (std::uint8_t i = 0; i < 32; ++i) {
        if (kWindows1252High[i] == u)
            return static_cast<std::uint8_t>(0x80 + i);
    }
    return std::nullopt;
}

QChar windows1252Char(std::uint8_t byte)
{
    return byte >= 0x80 && byte <= 0x9F ? QChar(kWindows1252High[byte - 0x80]) : QChar(char16_t(byte));
}

LiteralFamily literalFamilyOfPrefix(QStringView prefix)
{
    struct Entry {
        std::string_view name;
        LiteralFamily family;
    };
    static constexpr std::array<Entry, 35> table{{
        {"BOOL", LiteralFamily::Bool},
        {"SINT", LiteralFamily::Integer}, {"INT", LiteralFamily::Integer}, {"DINT", LiteralFamily::Integer},
        {"LINT", LiteralFamily::Integer}, {"USINT", LiteralFamily::Integer}, {"UINT", LiteralFamily::Integer},
        {"UDINT", LiteralFamily::Integer}, {"ULINT", LiteralFamily::Integer}, {"BYTE", LiteralFamily::Integer},
        {"WORD", LiteralFamily::Integer}, {"DWORD", LiteralFamily::Integer}, {"LWORD", LiteralFamily::Integer},
        {"REAL", LiteralFamily::Real}, {"LREAL", LiteralFamily::Real},
        {"T", LiteralFamily::Duration}, {"TIME", LiteralFamily::Duration}, {"LT", LiteralFamily::Duration},
        {"LTIME", LiteralFamily::Duration},
        {"D", LiteralFamily::Date}, {"DATE", LiteralFamily::Date}, {"LD", LiteralFamily::Date},
        {"LDATE", LiteralFamily::Date},
        {"TOD", LiteralFamily::TimeOfDay}, {"TIME_OF_DAY", LiteralFamily::TimeOfDay},
        {"LTOD", LiteralFamily::TimeOfDay}, {"LTIME_OF_DAY", LiteralFamily::TimeOfDay},
        {"DT", LiteralFamily::DateAndTime}, {"DATE_AND_TIME", LiteralFamily::DateAndTime},
        {"LDT", LiteralFamily::DateAndTime}, {"LDATE_AND_TIME", LiteralFamily::DateAndTime},
        {"STRING", LiteralFamily::String}, {"CHAR", LiteralFamily::String},
        {"WSTRING", LiteralFamily::WString}, {"WCHAR", LiteralFamily::WString},
    }};
    if (prefix.isEmpty())
        return LiteralFamily::None;
    for (const Entry &entry : table) {
        if (equalsUpper(prefix, entry.name))
            return entry.family;
    }
    return LiteralFamily::Unknown;
}

} // namespace iec::interp
