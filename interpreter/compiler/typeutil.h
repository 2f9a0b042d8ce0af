#pragma once

// Small facts about types and compile-time values shared by the code generator's files.

#include "interpreter/compiler/codegen.h"

#include <QCoreApplication>

namespace iec::interp::detail {

inline bool isNumeric(const Type *t)
{
    return t && t->kind == TypeKind::Elementary && (info(t->elem).isInt || info(t->elem).isReal);
}
inline bool isIntegral(const Type *t)
{
    return t && t->kind == TypeKind::Elementary && info(t->elem).isInt;
}
inline bool isReal(const Type *t)
{
    return t && t->kind == TypeKind::Elementary && info(t->elem).isReal;
}
inline bool isBits(const Type *t)
{
    return t && t->kind == TypeKind::Elementary && info(t->elem).isBit;
}
inline bool isTimeLike(const Type *t)
{
    return t && t->kind == TypeKind::Elementary && info(t->elem).isTimeLike;
}
inline bool isString(const Type *t)
{
    return t && t->kind == TypeKind::String;
}

// Cuts a 64-bit value to the width of `e`, sign-extending signed types: constant arithmetic
// wraps exactly like the VM.
inline std::int64_t wrapTo(std::int64_t v, Elem e)
{
    const ElemInfo &i = info(e);
    if (e == Elem::Bool)
        return v & 1;
    switch (i.size) {
    case 1: return i.isUnsigned ? std::int64_t(std::uint8_t(v)) : std::int64_t(std::int8_t(v));
    case 2: return i.isUnsigned ? std::int64_t(std::uint16_t(v)) : std::int64_t(std::int16_t(v));
    case 4: return i.isUnsigned ? std::int64_t(std::uint32_t(v)) : std::int64_t(std::int32_t(v));
    default: return v;
    }
}

// The range of an integer or bit type, as text for messages and as bounds.
struct IntRange {
    std::int64_t low;
    std::uint64_t high;
};
inline IntRange rangeOf(Elem e)
{
    const ElemInfo &i = info(e);
    if (e == Elem::Bool)
        return {0, 1};
    const unsigned bits = i.size * 8;
    if (i.isUnsigned)
        return {0, bits == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1};
    return {bits == 64 ? INT64_MIN : -(std::int64_t{1} << (bits - 1)),
            bits == 64 ? std::uint64_t(INT64_MAX) : (std::uint64_t{1} << (bits - 1)) - 1};
}

inline bool fits(const ConstValue &c, Elem e)
{
    const IntRange r = rangeOf(e);
    if (c.bigUnsigned)
        return r.high >= static_cast<std::uint64_t>(c.i);
    if (c.i < r.low)
        return false;
    return c.i < 0 || static_cast<std::uint64_t>(c.i) <= r.high;
}

// An untyped value that is a real literal (1.5) or was computed from real literals only.
inline bool realLiteral(const Value &v)
{
    return v.untyped && (v.constant.kind == ConstValue::Kind::Real || (v.kind == Value::Kind::Operand && isReal(v.type)));
}

inline QString constText(const ConstValue &c)
{
    switch (c.kind) {
    case ConstValue::Kind::Int: return c.bigUnsigned ? QString::number(static_cast<std::uint64_t>(c.i)) : QString::number(c.i);
    case ConstValue::Kind::Real: return QString::number(c.r);
    case ConstValue::Kind::String: return QLatin1Char('\'') + c.s + QLatin1Char('\'');
    case ConstValue::Kind::None: break;
    }
    return {};
}

inline double asReal(const ConstValue &c)
{
    if (c.kind == ConstValue::Kind::Real)
        return c.r;
    return c.bigUnsigned ? static_cast<double>(static_cast<std::uint64_t>(c.i)) : static_cast<double>(c.i);
}

inline Elem shortForm(Elem e)
{
    switch (e) {
    case Elem::LTime: return Elem::Time;
    case Elem::LDate: return Elem::Date;
    case Elem::LTod: return Elem::Tod;
    case Elem::Ldt: return Elem::Dt;
    default: return e;
    }
}
inline Elem longForm(Elem e)
{
    switch (e) {
    case Elem::Time: return Elem::LTime;
    case Elem::Date: return Elem::LDate;
    case Elem::Tod: return Elem::LTod;
    case Elem::Dt: return Elem::Ldt;
    default: return e;
    }
}

inline QString conversionHint(const Type *from, const Type *to)
{
    if (from && to && from->isElementary() && to->isElementary() && from->kind == TypeKind::Elementary
        && to->kind == TypeKind::Elementary)
        return QCoreApplication::translate("iec::interp::Compiler", "convert it explicitly, e.g. %1_TO_%2(...)").arg(info(from->elem).name, info(to->elem).name);
    return {};
}


} // namespace iec::interp::detail
