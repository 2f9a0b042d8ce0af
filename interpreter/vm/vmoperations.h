#pragma once

// The operations of the VM's instructions that are more than one line (wrapping arithmetic,
// shifts, conversions, BCD, text of numbers, strings in the image): vm.cpp's interpreter loop
// calls them. Private to interpreter/vm.
#include "interpreter/vm/bytecode.h"
#include "interpreter/vm/imagebytes.h"
#include "interpreter/vm/nativeblocks.h"

#include "interpreter/compiler/literals.h"
#include "interpreter/runtime/valueformat.h"

#include <QString>

#include <algorithm>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <type_traits>

namespace iec::interp::vmops {

inline std::optional<std::int64_t> parseLiteralValue(const QString &text, TextFormat format);

using image::load;
using image::store;

// Integer arithmetic wraps around like the IEC type: computed in 64-bit unsigned and cut to T.
template<typename T>
T wrapAdd(T a, T b)
{
    if constexpr (std::is_integral_v<T>)
        return static_cast<T>(static_cast<std::uint64_t>(a) + static_cast<std::uint64_t>(b));
    else
        return a + b;
}
template<typename T>
T wrapSub(T a, T b)
{
    if constexpr (std::is_integral_v<T>)
        return static_cast<T>(static_cast<std::uint64_t>(a) - static_cast<std::uint64_t>(b));
    else
        return a - b;
}
template<typename T>
T wrapMul(T a, T b)
{
    if constexpr (std::is_integral_v<T>)
        return static_cast<T>(static_cast<std::uint64_t>(a) * static_cast<std::uint64_t>(b));
    else
        return a * b;
}
template<typename T>
T negate(T a)
{
    if constexpr (std::is_integral_v<T>)
        return static_cast<T>(0 - static_cast<std::uint64_t>(a));
    else
        return -a;
}


// Division and MOD: false when dividing an integer by zero. INT_MIN / -1 wraps.
template<typename T>
bool divide(T a, T b, T &out)
{
    if constexpr (std::is_integral_v<T>) {
        if (b == 0)
            return false;
        if constexpr (std::is_signed_v<T>) {
            if (b == T(-1)) {
                out = negate<T>(a);
                return true;
            }
        }
    }
    out = static_cast<T>(a / b);
    return true;
}
template<typename T>
bool modulo(T a, T b, T &out)
{
    if constexpr (std::is_integral_v<T>) {
        if (b == 0)
            return false;
        if constexpr (std::is_signed_v<T>) {
            if (b == T(-1)) {
                out = 0;
                return true;
            }
        }
        out = static_cast<T>(a % b);
    } else {
        out = std::fmod(a, b);
    }
    return true;
}
template<typename T>
T absValue(T a)
{
    if constexpr (std::is_unsigned_v<T>)
        return a;
    else
        return a < 0 ? negate<T>(a) : a;
}
template<typename T>
T bitAnd(T a, T b)
{
    if constexpr (std::is_integral_v<T>)
        return static_cast<T>(a & b);
    else
        return a;
}
template<typename T>
T bitOr(T a, T b)
{
    if constexpr (std::is_integral_v<T>)
        return static_cast<T>(a | b);
    else
        return a;
}
template<typename T>
T bitXor(T a, T b)
{
    if constexpr (std::is_integral_v<T>)
        return static_cast<T>(a ^ b);
    else
        return a;
}
template<typename T>
T bitNot(T a)
{
    if constexpr (std::is_integral_v<T>)
        return static_cast<T>(~a);
    else
        return a;
}
template<typename T>
bool getBit(T v, unsigned bit)
{
    if constexpr (std::is_integral_v<T>)
        return ((static_cast<std::uint64_t>(v) >> bit) & 1u) != 0;
    else
        return false;
}
template<typename T>
T setBit(T old, unsigned bit, bool value)
{
    if constexpr (std::is_integral_v<T>) {
        const std::uint64_t mask = std::uint64_t{1} << bit;
        const std::uint64_t v = static_cast<std::uint64_t>(old);
        return static_cast<T>(value ? (v | mask) : (v & ~mask));
    } else {
        return old;
    }
}
template<typename T>
QString toText(T v, TextFormat format)
{
    if constexpr (std::is_integral_v<T>) {
        switch (format) {
        case TextFormat::Bool: return formatBool(v != 0);
        case TextFormat::Duration: return formatDuration(static_cast<std::int64_t>(v));
        case TextFormat::Date: return formatDate(static_cast<std::int64_t>(v));
        case TextFormat::TimeOfDay: return formatTimeOfDay(static_cast<std::int64_t>(v));
        case TextFormat::DateAndTime: return formatDateAndTime(static_cast<std::int64_t>(v));
        case TextFormat::Hex: return QStringLiteral("16#") + QString::number(static_cast<std::uint64_t>(v), 16);
        case TextFormat::Number: break;
        }
    }
    if constexpr (std::is_floating_point_v<T>) {
        QString text = formatReal(v); // REAL prints its own shortest digits, not the widened double's
        if (text.endsWith(QLatin1String(".0")))
            text.chop(2);
        return text;
    }
    else if constexpr (std::is_signed_v<T>)
        return formatInteger(static_cast<std::int64_t>(v));
    else
        return formatUnsigned(static_cast<std::uint64_t>(v));
}
template<typename T>
T fromText(const QString &text, TextFormat format)
{
    if constexpr (std::is_integral_v<T>) {
        if (format != TextFormat::Number && format != TextFormat::Hex) {
            const auto value = parseLiteralValue(text, format);
            return value ? static_cast<T>(*value) : T(0);
        }
    }
    if constexpr (std::is_floating_point_v<T>) {
        bool ok = false;
        const double v = text.toDouble(&ok);
        return ok ? static_cast<T>(v) : T(0);
    } else {
        // 42, -42, 16#2A, INT#5: the integer literals of the language.
        const auto value = decodeInteger(splitTypedLiteral(text).body);
        if (!value)
            return T(0);
        return static_cast<T>(value->negative ? 0 - value->magnitude : value->magnitude);
    }
}

// STRING_TO_BOOL/TIME/DATE/TOD/DT: the text of a literal, with or without its T#/D#/... prefix.
inline std::optional<std::int64_t> parseLiteralValue(const QString &text, TextFormat format)
{
    const LiteralParts parts = splitTypedLiteral(text);
    switch (format) {
    case TextFormat::Bool:
        if (text.compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0 || text == QLatin1String("1"))
            return 1;
        return 0;
    case TextFormat::Duration: return decodeDuration(parts.body);
    case TextFormat::Date: return decodeDate(parts.body);
    case TextFormat::TimeOfDay: return decodeTimeOfDay(parts.body);
    case TextFormat::DateAndTime: return decodeDateAndTime(parts.body);
    case TextFormat::Number:
    case TextFormat::Hex: break;
    }
    return std::nullopt;
}

template<typename T>
constexpr unsigned kBits = sizeof(T) * 8;

template<typename T>
T shiftLeft(T a, std::uint64_t n)
{
    if constexpr (std::is_integral_v<T>)
        return n >= kBits<T> ? T(0) : static_cast<T>(static_cast<std::uint64_t>(a) << n);
    else
        return a;
}
template<typename T>
T shiftRight(T a, std::uint64_t n)
{
    if constexpr (std::is_integral_v<T>) {
        using U = std::make_unsigned_t<T>;
        return n >= kBits<T> ? T(0) : static_cast<T>(static_cast<U>(a) >> n);
    } else {
        return a;
    }
}
template<typename T>
T rotateLeft(T a, std::uint64_t n)
{
    if constexpr (std::is_integral_v<T>) {
        n %= kBits<T>;
        return n == 0 ? a : static_cast<T>(shiftLeft(a, n) | shiftRight(a, kBits<T> - n));
    } else {
        return a;
    }
}
template<typename T>
T rotateRight(T a, std::uint64_t n)
{
    if constexpr (std::is_integral_v<T>) {
        n %= kBits<T>;
        return n == 0 ? a : static_cast<T>(shiftRight(a, n) | shiftLeft(a, kBits<T> - n));
    } else {
        return a;
    }
}

// REAL to integer rounds to the nearest integer, halves away from zero; values beyond the
// integer type's range give its limit, NaN gives 0 (never undefined behaviour).
template<typename To, typename From>
To convert(From v)
{
    if constexpr (std::is_floating_point_v<From> && std::is_integral_v<To>) {
        const double r = std::round(static_cast<double>(v));
        if (!(r == r))
            return To(0);
        if (r >= static_cast<double>(std::numeric_limits<To>::max()))
            return std::numeric_limits<To>::max();
        if (r <= static_cast<double>(std::numeric_limits<To>::min()))
            return std::numeric_limits<To>::min();
        return static_cast<To>(r);
    } else {
        return static_cast<To>(v);
    }
}

inline double applyMath(MathFn fn, double x)
{
    switch (fn) {
    case MathFn::Sqrt: return std::sqrt(x);
    case MathFn::Ln: return std::log(x);
    case MathFn::Log: return std::log10(x);
    case MathFn::Exp: return std::exp(x);
    case MathFn::Sin: return std::sin(x);
    case MathFn::Cos: return std::cos(x);
    case MathFn::Tan: return std::tan(x);
    case MathFn::Asin: return std::asin(x);
    case MathFn::Acos: return std::acos(x);
    case MathFn::Atan: return std::atan(x);
    case MathFn::Trunc: return std::trunc(x);
    case MathFn::Round: return std::round(x);
    case MathFn::Count: break;
    }
    return x;
}

template<typename T>
std::uint64_t toBcd(T value)
{
    std::uint64_t v = static_cast<std::uint64_t>(value), out = 0;
    for (unsigned shift = 0; v != 0 && shift < 64; shift += 4, v /= 10)
        out |= (v % 10) << shift;
    return out;
}

inline std::uint64_t fromBcd(std::uint64_t bcd)
{
    std::uint64_t out = 0, scale = 1;
    for (; bcd != 0; bcd >>= 4, scale *= 10)
        out += (bcd & 0xf) * scale;
    return out;
}

template<typename T>
T bcd(T v, bool toBinary)
{
    if constexpr (std::is_integral_v<T>)
        return static_cast<T>(toBinary ? fromBcd(static_cast<std::uint64_t>(v)) : toBcd(v));
    else
        return v;
}

// The index c * d + e of op::LoadIdxMA, wrapped like the index expression's type.
template<typename T>
std::int64_t mulAddOf(const std::uint8_t *c, const std::uint8_t *d, const std::uint8_t *e)
{
    // In 64-bit unsigned: 16-bit operands would be promoted to int, whose overflow is undefined.
    using W = std::uint64_t;
    return static_cast<T>(static_cast<W>(load<T>(c)) * static_cast<W>(load<T>(d)) + static_cast<W>(load<T>(e)));
}
inline std::int64_t mulAddIndex(VT vt, const std::uint8_t *c, const std::uint8_t *d, const std::uint8_t *e)
{
    if (vt == VT::I32)
        return mulAddOf<std::int32_t>(c, d, e);
    if (vt == VT::I16)
        return mulAddOf<std::int16_t>(c, d, e);
    return mulAddOf<std::int64_t>(c, d, e);
}

inline std::int64_t readIndex(const IndexDescriptor &dsc, const std::uint8_t *p)
{
    // DINT and INT indices first, as plain (well predicted) branches; the rest through a table.
    if (dsc.indexType == VT::I32)
        return load<std::int32_t>(p);
    if (dsc.indexType == VT::I16)
        return load<std::int16_t>(p);
    switch (dsc.indexType) {
    case VT::I8: return load<std::int8_t>(p);
    case VT::I16: return load<std::int16_t>(p);
    case VT::I32: return load<std::int32_t>(p);
    case VT::U8: return load<std::uint8_t>(p);
    case VT::U16: return load<std::uint16_t>(p);
    case VT::U32: return load<std::uint32_t>(p);
    default: return load<std::int64_t>(p); // I64; a U64 beyond 2^63 is out of range anyway
    }
}

// Strings in the image: capacity (uint16), length (uint16), then 1- or 2-byte characters.
// A string in memory: capacity and length (16 bits each), then the characters, ended by a NUL
// when shorter than the capacity. As in CODESYS, a string ends at its first NUL: a program may
// build one through a pointer to its characters (OSCAT's BYTE_TO_STRH writes two characters and a
// 0 from ADR of its result), so the length read is the NUL's position, and the stored one only
// records what the VM wrote. The capacity is memory a pointer can overwrite too: it is not trusted
// beyond `end`, the end of the memory the string lies in, and a string whose header does not fit
// there is empty and holds nothing.
struct StringRef {
    std::uint8_t *p;
    bool wide;
    const std::uint8_t *end;
    bool fits() const { return end - p >= 4; }
    std::uint16_t capacity() const
    {
        if (!fits())
            return 0;
        const std::ptrdiff_t room = (end - p - 4) / (wide ? 2 : 1);
        return static_cast<std::uint16_t>(std::min<std::ptrdiff_t>(load<std::uint16_t>(p), room));
    }
    std::uint16_t length() const
    {
        const std::uint16_t limit = capacity();
        for (std::uint16_t i = 0; i < limit; ++i) {
            if (at(i) == 0)
                return i;
        }
        return limit;
    }
    char16_t at(int i) const { return wide ? load<char16_t>(p + 4 + 2 * i) : char16_t(p[4 + i]); }
};


} // namespace iec::interp::vmops
