// Implicit conversions (the IEC widening rules) and the explicit *_TO_* conversions.
#include "interpreter/compiler/codegen.h"
#include "interpreter/compiler/typeutil.h"

#include <QCoreApplication>
#include <cmath>
#include <functional>

namespace iec::interp::detail {

using namespace ast;


// A value computed from literals alone at run time takes the type its use needs: an integer
// or bit string (each literal it may be must fit, as a literal must) or a real.
Value Codegen::coerceUntypedOperand(Value v, const Type *to, SourceLocation at, const std::function<Value()> &mismatch)
{
    const bool real = isReal(v.type);
    const bool toInteger = (isIntegral(to) || isBits(to)) && to->elem != Elem::Bool;
    if ((real && !isReal(to)) || (!real && !toInteger && !isReal(to)))
        return mismatch();
    if (v.literalRange && toInteger) {
        for (const std::int64_t end : {v.literalRange->first, v.literalRange->second}) {
            ConstValue c;
            c.kind = ConstValue::Kind::Int;
            c.i = end;
            if (!fits(c, to->elem)) {
                const IntRange r = rangeOf(to->elem);
                error(at, QCoreApplication::translate("iec::interp::Compiler", "The value %1 does not fit into %2 (%3 to %4).")
                              .arg(end).arg(typeName(to)).arg(r.low).arg(r.high));
                return {};
            }
        }
    }
    if (vtOf(*v.type) == vtOf(*to))
        return operandValue(v.operand, to);
    const std::uint32_t out = temp(to);
    instr(convertOp(vtOf(*v.type), vtOf(*to)), out, v.operand);
    return operandValue(out, to);
}

// A conversion CODESYS makes implicitly: true (with its warning, when CODESYS gives one), or
// false when it is refused.
bool Codegen::warnImplicit(const Type *from, const Type *to, SourceLocation at)
{
    const QString f = typeName(from), t = typeName(to);
    const QString hint = conversionHint(from, to);
    switch (implicitConversion(from->elem, to->elem)) {
    case ImplicitConversion::Widening:
    case ImplicitConversion::Silent:
        return true;
    case ImplicitConversion::LossOfInformation:
        warning(at, QCoreApplication::translate("iec::interp::Compiler", "Implicit conversion from %1 to %2: possible loss of information.").arg(f, t), hint);
        return true;
    case ImplicitConversion::SignedToUnsigned:
        warning(at, QCoreApplication::translate("iec::interp::Compiler", "Implicit conversion from signed type %1 to unsigned type %2: possible change of sign.").arg(f, t), hint);
        return true;
    case ImplicitConversion::UnsignedToSigned:
        warning(at, QCoreApplication::translate("iec::interp::Compiler", "Implicit conversion from unsigned type %1 to signed type %2: possible change of sign.").arg(f, t), hint);
        return true;
    case ImplicitConversion::Refused:
        break;
    }
    return false;
}

Value Codegen::coerce(Value v, const Type *to, SourceLocation at, const QString &context)
{
    if (!v.valid() || !to)
        return {};
    const Type *from = v.type;
    const QString where = context.isEmpty() ? QString() : QStringLiteral(" ") + context;
    const std::function<Value()> mismatch = [&]() {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "A value of type %1 cannot be used as %2%3 without a conversion.")
                      .arg(v.untyped ? (isReal(from) ? QStringLiteral("ANY_REAL") : QStringLiteral("ANY_INT")) : typeName(from), typeName(to), where),
              v.untyped ? QString() : conversionHint(from, to));
        return Value{};
    };
    if (v.untyped && v.kind == Value::Kind::Operand && to->kind == TypeKind::Elementary)
        return coerceUntypedOperand(v, to, at, mismatch);
    if (from == to)
        return v;
    if (const auto address = coercePointer(v, to, at))
        return *address;
    if (const auto object = interfaceOf(v, to, at))
        return *object;
    if (to->kind == TypeKind::Elementary && from->kind == TypeKind::Elementary && from->elem == to->elem && !v.untyped) {
        v.type = to; // an alias or subrange of the same elementary type
        return v;
    }
    if (v.kind == Value::Kind::Constant) {
        if (v.untyped && to->kind == TypeKind::Elementary) {
            if (v.constant.kind == ConstValue::Kind::Int && (isIntegral(to) || isBits(to))) {
                if (v.bitPattern && !fits(v.constant, to->elem)) {
                    ConstValue cut = v.constant;
                    cut.i = wrapTo(cut.i, to->elem);
                    cut.bigUnsigned = to->size == 8 && info(to->elem).isUnsigned && cut.i < 0;
                    return constantValue(to, cut);
                }
                if (!fits(v.constant, to->elem)) {
                    const IntRange r = rangeOf(to->elem);
                    error(at, QCoreApplication::translate("iec::interp::Compiler", "The value %1 does not fit into %2 (%3 to %4).")
                                  .arg(constText(v.constant), typeName(to)).arg(r.low).arg(r.high));
                    return {};
                }
                return constantValue(to, v.constant);
            }
            if (isReal(to)) {
                ConstValue c;
                c.kind = ConstValue::Kind::Real;
                c.r = asReal(v.constant);
                if (to->elem == Elem::Real)
                    c.r = static_cast<float>(c.r);
                return constantValue(to, c);
            }
            return mismatch();
        }
        if (from->kind == TypeKind::String && to->kind == TypeKind::Elementary && (to->elem == Elem::Char || to->elem == Elem::WChar)
            && v.constant.kind == ConstValue::Kind::String && (!from->wide || to->elem == Elem::WChar)) {
            // A CHAR literal is a one-character string: c : CHAR := 'A' (also CHAR#'A').
            if (v.constant.s.size() != 1) {
                error(at, QCoreApplication::translate("iec::interp::Compiler", "A %1 holds exactly one character, not %2.")
                              .arg(typeName(to)).arg(v.constant.s.size()));
                return {};
            }
            ConstValue c;
            c.kind = ConstValue::Kind::Int;
            c.i = v.constant.s.front().unicode();
            return constantValue(to, c);
        }
        if (from->kind == TypeKind::String && to->kind == TypeKind::String && from->wide == to->wide) {
            if (v.constant.s.size() > qsizetype(to->capacity)) {
                error(at, QCoreApplication::translate("iec::interp::Compiler", "The text has %1 characters but %2 holds only %3.")
                              .arg(v.constant.s.size()).arg(context.isEmpty() ? typeName(to) : context).arg(to->capacity));
                return {};
            }
            return constantValue(to, v.constant);
        }
        if (from->kind == TypeKind::Elementary && to->kind == TypeKind::Elementary && !implicitlyConvertible(from->elem, to->elem)
            && warnImplicit(from, to, at))
            return convertExplicit(v, to, at);
        if (from->kind == TypeKind::Elementary && to->kind == TypeKind::Elementary && implicitlyConvertible(from->elem, to->elem)) {
            ConstValue c = v.constant;
            if (isReal(to) && c.kind == ConstValue::Kind::Int) {
                c.kind = ConstValue::Kind::Real;
                c.r = asReal(v.constant);
            }
            return constantValue(to, c);
        }
        if (from->kind == TypeKind::Enum && to->kind == TypeKind::Enum && from->name.compare(to->name, Qt::CaseInsensitive) == 0)
            return constantValue(to, v.constant);
        return mismatch();
    }
    // A value in memory.
    if (from->kind == TypeKind::Elementary && to->kind == TypeKind::Elementary) {
        if (!implicitlyConvertible(from->elem, to->elem))
            return warnImplicit(from, to, at) ? convertExplicit(v, to, at) : mismatch();
        if (vtOf(*from) == vtOf(*to) && from->elem != Elem::Bool) {
            v.type = to; // same machine representation: TIME to LTIME, BYTE to ... (none differ)
            return v;
        }
        const std::uint32_t out = temp(to);
        instr(convertOp(vtOf(*from), vtOf(*to)), out, v.operand);
        return operandValue(out, to);
    }
    if (from->kind == TypeKind::String && to->kind == TypeKind::String && from->wide == to->wide) {
        v.type = to; // the capacity is checked when the text is stored
        return v;
    }
    if (from->kind == TypeKind::Array && to->kind == TypeKind::Array && from->size == to->size
        && from->element == to->element && from->dims.size() == to->dims.size()) {
        bool same = true;
        for (size_t i = 0; i < from->dims.size(); ++i)
            same = same && from->dims[i].count() == to->dims[i].count();
        if (same) {
            v.type = to;
            return v;
        }
    }
    return mismatch();
}

Value Codegen::convertExplicit(Value v, const Type *to, SourceLocation at, bool truncate)
{
    if (!v.valid() || !to)
        return {};
    const Type *from = v.type;
    if (v.untyped && v.kind == Value::Kind::Constant) {
        // A literal converts like a value of the smallest type that holds it.
        if (v.constant.kind == ConstValue::Kind::Real)
            from = elem(Elem::LReal);
        else
            from = fits(v.constant, Elem::DInt) ? elem(Elem::DInt) : elem(Elem::LInt);
        v = coerce(v, from, at);
        if (!v.valid())
            return {};
    }
    if (from->kind == TypeKind::Enum || to->kind == TypeKind::Enum) {
        // Enumerations convert to and from their base integer type.
        const Type *base = elem(from->kind == TypeKind::Enum ? from->elem : to->elem);
        if (from->kind == TypeKind::Enum)
            v.type = base;
        if (to->kind == TypeKind::Enum) {
            Value converted = convertExplicit(v, base, at, truncate);
            converted.type = to;
            return converted;
        }
        return convertExplicit(v, to, at, truncate);
    }
    if (from->kind == TypeKind::String || to->kind == TypeKind::String) {
        const auto format = [&](const Type *t) {
            if (!t->isElementary())
                return TextFormat::Number;
            switch (shortForm(t->elem)) {
            case Elem::Bool: return TextFormat::Bool;
            case Elem::Time: return TextFormat::Duration;
            case Elem::Date: return TextFormat::Date;
            case Elem::Tod: return TextFormat::TimeOfDay;
            case Elem::Dt: return TextFormat::DateAndTime;
            case Elem::Byte: case Elem::Word: case Elem::DWord: case Elem::LWord: return TextFormat::Hex;
            default: return TextFormat::Number;
            }
        };
        if (from->kind == TypeKind::String && to->kind == TypeKind::String) {
            const Type *result = m_types->string(to->wide, std::max(from->capacity, to->kind == TypeKind::String ? to->capacity : 80u));
            const std::uint32_t out = temp(result);
            instr(op::StrMov, out, materialize(v), 0, 0, (to->wide ? 1 : 0) | (from->wide ? 2 : 0));
            return operandValue(out, result);
        }
        if (to->kind == TypeKind::String && from->kind == TypeKind::Elementary && (from->elem == Elem::Char || from->elem == Elem::WChar)) {
            // CHAR_TO_STRING('A') is 'A', not the character's code: a one-character string
            // (capacity, length, then the character, as the VM lays strings out).
            const Type *result = m_types->string(to->wide, 1);
            const std::uint32_t out = temp(result);
            const std::uint32_t one = constantOperand(elem(Elem::UInt), ConstValue{ConstValue::Kind::Int, 1, false, 0, {}, false});
            instr(op::Mov2, out + 2, one);
            const Type *character = elem(to->wide ? Elem::WChar : Elem::Char);
            if (from->size == character->size)
                instr(to->wide ? op::Mov2 : op::Mov1, out + 4, materialize(v));
            else
                instr(convertOp(vtOf(*from), vtOf(*character)), out + 4, materialize(v)); // CHAR_TO_WSTRING, WCHAR_TO_STRING
            return operandValue(out, result);
        }
        if (to->kind == TypeKind::String) {
            if (!from->isElementary()) {
                error(at, QCoreApplication::translate("iec::interp::Compiler", "A %1 cannot be converted to text.").arg(typeName(from)));
                return {};
            }
            const Type *result = m_types->string(to->wide, 80);
            const std::uint32_t out = temp(result);
            instr(typedOp(op::ToStr, vtOf(*from)), out, materialize(v), 0, 0,
                 static_cast<std::uint16_t>(static_cast<int>(format(from)) << 1 | (to->wide ? 1 : 0)));
            return operandValue(out, result);
        }
        if (!to->isElementary()) {
            error(at, QCoreApplication::translate("iec::interp::Compiler", "Text cannot be converted to %1.").arg(typeName(to)));
            return {};
        }
        if (to->kind == TypeKind::Elementary && (to->elem == Elem::Char || to->elem == Elem::WChar)) {
            // STRING_TO_CHAR('65') is '6': the first character, or the character 0 of an empty text.
            const std::uint32_t source = materialize(v);
            const std::uint32_t out = temp(to);
            const ConstValue zero{ConstValue::Kind::Int, 0, false, 0, {}, false};
            emitMove(out, constantOperand(to, zero), to);
            const std::uint32_t length = temp(elem(Elem::DInt));
            instr(op::StrLen, length, source, 0, 0, from->wide ? 1 : 0);
            const Value empty = binary(QStringLiteral("="), operandValue(length, elem(Elem::DInt)), constantValue(elem(Elem::DInt), zero), at);
            const std::uint32_t skip = instr(op::Jnz, 0, empty.operand);
            const Type *character = elem(from->wide ? Elem::WChar : Elem::Char);
            if (character->size == to->size)
                instr(to->size == 2 ? op::Mov2 : op::Mov1, out, source + 4);
            else
                instr(convertOp(vtOf(*character), vtOf(*to)), out, source + 4);
            patchJump(skip, here());
            return operandValue(out, to);
        }
        const std::uint32_t out = temp(to);
        instr(typedOp(op::FromStr, vtOf(*to)), out, materialize(v), 0, 0,
             static_cast<std::uint16_t>(static_cast<int>(format(to)) << 1 | (from->wide ? 1 : 0)));
        return operandValue(out, to);
    }
    if (from->kind != TypeKind::Elementary || to->kind != TypeKind::Elementary) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "A %1 cannot be converted to %2.").arg(typeName(from), typeName(to)));
        return {};
    }
    if (from->elem == to->elem) {
        v.type = to;
        return v;
    }
    // Times and dates count in nanoseconds; as numbers they are milliseconds (TIME, TOD) or
    // seconds (DATE, DT) as in CODESYS, and the L forms stay in nanoseconds.
    const auto scale = [](Elem e) -> std::int64_t {
        switch (e) {
        case Elem::Time: case Elem::Tod: return 1'000'000;
        case Elem::Date: case Elem::Dt: return 1'000'000'000;
        default: return 1;
        }
    };
    constexpr std::int64_t kDay = 86'400'000'000'000LL;
    if (isTimeLike(from) && isTimeLike(to)) {
        const Elem f = shortForm(from->elem), t = shortForm(to->elem);
        if (f == Elem::Dt && (t == Elem::Date || t == Elem::Tod)) {
            // DT_TO_DATE keeps the day, DT_TO_TOD the time within it.
            const Type *lint = elem(Elem::LInt);
            const Value day = constantValue(lint, ConstValue{ConstValue::Kind::Int, kDay, false, 0, {}, false});
            Value asInt = v;
            asInt.type = lint;
            Value rest = binary(QStringLiteral("MOD"), asInt, day, at);
            Value result = t == Elem::Tod ? rest : binary(QStringLiteral("-"), asInt, rest, at);
            result.type = to;
            return result;
        }
        v.type = to;
        return v;
    }
    if (isTimeLike(from) || isTimeLike(to)) {
        const bool toTime = isTimeLike(to);
        const std::int64_t factor = scale(toTime ? to->elem : from->elem);
        const Type *numberType = toTime ? from : to;
        if (!isNumeric(numberType) && !isBits(numberType)) {
            error(at, QCoreApplication::translate("iec::interp::Compiler", "A %1 cannot be converted to %2.").arg(typeName(from), typeName(to)));
            return {};
        }
        const Type *work = isReal(numberType) ? elem(Elem::LReal) : elem(Elem::LInt);
        const ConstValue f = isReal(numberType) ? ConstValue{ConstValue::Kind::Real, 0, false, double(factor), {}, false}
                                                : ConstValue{ConstValue::Kind::Int, factor, false, 0, {}, false};
        Value asWork = v;
        if (toTime) {
            asWork = convertExplicit(v, work, at);
            Value scaled = factor == 1 ? asWork : binary(QStringLiteral("*"), asWork, constantValue(work, f), at);
            if (isReal(numberType))
                scaled = convertExplicit(scaled, elem(Elem::LInt), at);
            scaled.type = to;
            return scaled;
        }
        asWork.type = elem(Elem::LInt);
        if (isReal(numberType))
            asWork = convertExplicit(asWork, work, at);
        const Value scaled = factor == 1 ? asWork : binary(QStringLiteral("/"), asWork, constantValue(work, f), at);
        return convertExplicit(scaled, to, at);
    }
    if (to->elem == Elem::Bool) {
        ConstValue zero;
        zero.kind = isReal(from) ? ConstValue::Kind::Real : ConstValue::Kind::Int;
        return binary(QStringLiteral("<>"), v, constantValue(from, zero), at);
    }
    if (v.kind == Value::Kind::Constant) {
        ConstValue c = v.constant;
        if (isReal(to)) {
            // A ULINT or LWORD above 2^63 is held as a negative int64 once folded (a wrapped
            // product): its type, not the flag of the literal it came from, says it is unsigned.
            const bool unsigned64 = from->kind == TypeKind::Elementary && from->size == 8 && info(from->elem).isUnsigned
                && c.kind == ConstValue::Kind::Int;
            const double r = unsigned64 ? static_cast<double>(static_cast<std::uint64_t>(c.i)) : asReal(c);
            c = {};
            c.kind = ConstValue::Kind::Real;
            c.r = to->elem == Elem::Real ? static_cast<float>(r) : r;
        } else if (c.kind == ConstValue::Kind::Real) {
            // As the VM does: round (or truncate), then saturate to the target's range.
            const double r = truncate ? std::trunc(c.r) : std::round(c.r);
            const IntRange range = rangeOf(to->elem);
            c = {};
            c.kind = ConstValue::Kind::Int;
            if (!(r == r))
                c.i = 0;
            else if (r >= static_cast<double>(range.high))
                c.i = static_cast<std::int64_t>(range.high), c.bigUnsigned = range.high > std::uint64_t(INT64_MAX);
            else if (r <= static_cast<double>(range.low))
                c.i = range.low;
            else
                c.i = r >= 9.2e18 ? static_cast<std::int64_t>(static_cast<std::uint64_t>(r)) : static_cast<std::int64_t>(r);
        } else {
            c.i = wrapTo(c.i, to->elem);
            c.bigUnsigned = to->size == 8 && info(to->elem).isUnsigned && c.i < 0;
        }
        return constantValue(to, c);
    }
    std::uint32_t source = v.operand;
    if (truncate && isReal(from) && !isReal(to)) {
        const std::uint32_t t = temp(from);
        instr(typedOp(op::Math, vtOf(*from)), t, source, 0, 0, static_cast<std::uint16_t>(MathFn::Trunc));
        source = t;
    }
    const std::uint32_t out = temp(to);
    instr(convertOp(vtOf(*from), vtOf(*to)), out, source);
    return operandValue(out, to);
}

} // namespace iec::interp::detail
