#pragma once

#include <QString>
#include <QList>
#include <QStringView>

#include <cstdint>
#include <optional>

namespace iec::interp {

// Values of literal tokens. The lexer uses these to decide whether a literal is well formed, the
// compiler to get its value, so a literal the editor colours as valid always compiles.

// The elementary type a typed literal names before its '#' (INT#5 -> "INT"); empty when none.
struct LiteralParts {
    QStringView typePrefix;
    QStringView body;
};
LiteralParts splitTypedLiteral(QStringView text);

// 42, 1_000, 2#1010, 8#17, 16#FF_FF, optionally with a leading sign. Sign and magnitude apart so
// that -9223372036854775808 and 16#FFFF_FFFF_FFFF_FFFF both fit.
struct IntegerValue {
    bool negative = false;
    std::uint64_t magnitude = 0;
};
std::optional<IntegerValue> decodeInteger(QStringView text);

// 1.5, -1.0E-3, 1e6, 2 (an integer body of a REAL#2 literal).
std::optional<double> decodeReal(QStringView text);

// The body of a duration literal: 1h2m3.5s, -5ms, 1d_2h, 100 (no unit: milliseconds, as CODESYS).
// Returns nanoseconds.
std::optional<std::int64_t> decodeDuration(QStringView body);

// DATE body 2024-01-01: nanoseconds since 1970-01-01 (midnight UTC).
std::optional<std::int64_t> decodeDate(QStringView body);
// TIME_OF_DAY body 12:00:00.5: nanoseconds since midnight.
std::optional<std::int64_t> decodeTimeOfDay(QStringView body);
// DATE_AND_TIME body 2024-01-01-12:00:00: nanoseconds since 1970-01-01.
std::optional<std::int64_t> decodeDateAndTime(QStringView body);

// 'text' or "text" including the quotes, with $ escapes ($$ $' $" $L $N $P $R $T $hh / $hhhh).
// A 'STRING' holds bytes, as the characters U+0000..U+00FF: a character written in it stands for
// its byte in Windows-1252 (so '€' is 16#80), $hh for the byte hh; a character Windows-1252 has no
// byte for is kept as it is (and refused where a STRING is made of it).
std::optional<QString> decodeString(QStringView quoted);

// STRING holds bytes in CODESYS's code page, Windows-1252, which is Latin-1 but for 16#80..16#9F
// (16#80 is €): the byte of a character (none when the code page has no such character), and the
// character of a byte.
std::optional<std::uint8_t> windows1252Byte(QChar c);
QChar windows1252Char(std::uint8_t byte);

// Which family a type prefix belongs to; Unknown for user types such as Color#Red.
enum class LiteralFamily { None, Bool, Integer, Real, Duration, Date, TimeOfDay, DateAndTime, String, WString, Unknown };
LiteralFamily literalFamilyOfPrefix(QStringView prefix);

} // namespace iec::interp
