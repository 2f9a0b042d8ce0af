// The standard functions of IEC 61131-3: one table, each entry naming its parameters and the
// code that compiles it. Type conversions (*_TO_*, TRUNC, BCD) are recognised by their names.
#include "interpreter/compiler/codegen.h"
#include "interpreter/compiler/typeutil.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <functional>

namespace iec::interp::detail {

namespace {

using Handler = std::function<Value(Codegen &, std::vector<Value> &, SourceLocation, const Place *)>;

struct StdFunction {
    const char *name;
    std::vector<const char *> parameters; // formal names; the last repeats for extensible ones
    bool extensible;
    Handler compile;
};

struct MathEntry {
    const char *name;
    MathFn fn;
    double (*fold)(double);
};
const MathEntry kMath[] = {
    {"SQRT", MathFn::Sqrt, [](double x) { return std::sqrt(x); }},
    {"LN", MathFn::Ln, [](double x) { return std::log(x); }},
    {"LOG", MathFn::Log, [](double x) { return std::log10(x); }},
    {"EXP", MathFn::Exp, [](double x) { return std::exp(x); }},
    {"SIN", MathFn::Sin, [](double x) { return std::sin(x); }},
    {"COS", MathFn::Cos, [](double x) { return std::cos(x); }},
    {"TAN", MathFn::Tan, [](double x) { return std::tan(x); }},
    {"ASIN", MathFn::Asin, [](double x) { return std::asin(x); }},
    {"ACOS", MathFn::Acos, [](double x) { return std::acos(x); }},
    {"ATAN", MathFn::Atan, [](double x) { return std::atan(x); }},
};

// Real functions accept a REAL/LREAL, or a value that widens to one.
const Type *realTypeFor(Codegen &g, const Value &v)
{
    if (v.untyped)
        return g.elem(Elem::LReal);
    if (isReal(v.type))
        return v.type;
    if (v.type->kind == TypeKind::Elementary && implicitlyConvertible(v.type->elem, Elem::Real))
        return g.elem(Elem::Real);
    if (v.type->kind == TypeKind::Elementary && implicitlyConvertible(v.type->elem, Elem::LReal))
        return g.elem(Elem::LReal);
    return nullptr;
}

Value mathFunction(Codegen &g, const MathEntry &m, Value v, SourceLocation at)
{
    const Type *type = realTypeFor(g, v);
    if (!type) {
        g.error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 needs a REAL or LREAL, not %2.").arg(QLatin1String(m.name), typeName(v.type)));
        return {};
    }
    v = g.coerce(v, type, at);
    if (!v.valid())
        return {};
    if (v.kind == Value::Kind::Constant) {
        ConstValue c;
        c.kind = ConstValue::Kind::Real;
        c.r = m.fold(v.constant.kind == ConstValue::Kind::Real ? v.constant.r : double(v.constant.i));
        if (type->elem == Elem::Real) // stored as a REAL, as the VM stores it, before it is used further
            c.r = static_cast<float>(c.r);
        return g.constantValue(type, c, v.untyped);
    }
    const std::uint32_t out = g.temp(type);
    g.instr(typedOp(op::Math, vtOf(*type)), out, v.operand, 0, 0, static_cast<std::uint16_t>(m.fn));
    return g.operandValue(out, type);
}

// The common type of several values, or nullptr with a message.
const Type *commonOf(Codegen &g, const std::vector<Value> &values, size_t from, const char *name, SourceLocation at)
{
    const Type *type = nullptr;
    bool allUntyped = true;
    for (size_t i = from; i < values.size(); ++i) {
        if (values[i].untyped)
            continue;
        allUntyped = false;
        type = type ? g.commonType(type, values[i].type) : values[i].type;
        if (!type) {
            g.error(at, QCoreApplication::translate("iec::interp::Compiler", "The inputs of %1 have types that do not go together (%2).").arg(QLatin1String(name), typeName(values[i].type)));
            return nullptr;
        }
    }
    if (allUntyped) {
        // Only literals: the smallest of INT, DINT, LINT (or REAL, LREAL) that holds them all,
        // as a literal has in CODESYS.
        bool real = false, fitsInt = true, fitsDint = true, fitsFloat = true;
        for (size_t i = from; i < values.size(); ++i) {
            const ConstValue &c = values[i].constant;
            if (realLiteral(values[i])) {
                real = true;
                fitsFloat = fitsFloat && c.kind == ConstValue::Kind::Real && double(float(c.r)) == c.r;
                continue;
            }
            // Computed from literals at run time: the literals it may be, when known.
            std::int64_t low = c.i, high = c.i;
            if (values[i].kind == Value::Kind::Operand) {
                low = values[i].literalRange ? values[i].literalRange->first : INT64_MIN;
                high = values[i].literalRange ? values[i].literalRange->second : INT64_MAX;
            }
            fitsInt = fitsInt && !c.bigUnsigned && low >= -32768 && high <= 32767;
            fitsDint = fitsDint && !c.bigUnsigned && low >= INT32_MIN && high <= INT32_MAX;
        }
        if (real)
            return g.elem(fitsFloat ? Elem::Real : Elem::LReal);
        return g.elem(fitsInt ? Elem::Int : fitsDint ? Elem::DInt : Elem::LInt);
    }
    for (size_t i = from; i < values.size(); ++i) {
        if (values[i].untyped && values[i].constant.kind == ConstValue::Kind::Real && isIntegral(type))
            type = g.elem(implicitlyConvertible(type->elem, Elem::Real) ? Elem::Real : Elem::LReal);
    }
    return type;
}

Value chain(Codegen &g, const char *op, std::vector<Value> &args, SourceLocation at)
{
    Value acc = args[0];
    for (size_t i = 1; i < args.size(); ++i)
        acc = g.binary(QLatin1String(op), acc, args[i], at);
    return acc;
}

// GT(a, b, c) is a > b AND b > c.
Value compareChain(Codegen &g, const char *op, std::vector<Value> &args, SourceLocation at)
{
    Value result = g.binary(QLatin1String(op), args[0], args[1], at);
    for (size_t i = 2; i < args.size() && result.valid(); ++i)
        result = g.binary(QStringLiteral("AND"), result, g.binary(QLatin1String(op), args[i - 1], args[i], at), at);
    return result;
}

bool allLiterals(const std::vector<Value> &values)
{
    return std::all_of(values.begin(), values.end(), [](const Value &v) { return v.untyped && v.kind == Value::Kind::Constant; });
}

bool allUntyped(const std::vector<Value> &values)
{
    return std::all_of(values.begin(), values.end(), [](const Value &v) { return v.untyped; });
}

// A literal's type from where it goes: s := MUX(k, 1, 2) with s : SINT makes the literals SINT
// (commonOf would make them INT, which a SINT cannot take). nullptr when that does not apply.
const Type *literalsTypeFrom(const std::vector<Value> &values, const Place *destination)
{
    const Type *to = destination ? destination->type : nullptr;
    if (!to || to->kind != TypeKind::Elementary || !(isIntegral(to) || isReal(to) || (isBits(to) && to->elem != Elem::Bool)) || !allUntyped(values))
        return nullptr;
    for (const Value &v : values) {
        const bool integer = !realLiteral(v);
        if (!integer && !isReal(to))
            return nullptr;
        if (integer && !isReal(to) && v.kind == Value::Kind::Constant && !fits(v.constant, to->elem) && !v.bitPattern)
            return nullptr;
    }
    return to;
}

Value minMax(Codegen &g, bool max, std::vector<Value> &args, SourceLocation at)
{
    if (allLiterals(args)) {
        // MAX(1, 2) of literals is the literal 2, which then fits any number type it is given to.
        size_t chosen = 0;
        for (size_t i = 1; i < args.size(); ++i) {
            const Value greater = g.binary(QStringLiteral(">"), args[i], args[chosen], at);
            if (!greater.valid() || greater.kind != Value::Kind::Constant)
                return {};
            if ((greater.constant.i != 0) == max)
                chosen = i;
        }
        return args[chosen];
    }
    const Type *type = commonOf(g, args, 0, max ? "MAX" : "MIN", at);
    if (!type)
        return {};
    if (!type->isElementary() || type->kind == TypeKind::Enum) {
        g.error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 needs numbers, times or bit strings.").arg(max ? QStringLiteral("MAX") : QStringLiteral("MIN")));
        return {};
    }
    Value acc = g.coerce(args[0], type, at);
    for (size_t i = 1; i < args.size() && acc.valid(); ++i) {
        const Value next = g.coerce(args[i], type, at);
        if (!next.valid())
            return {};
        if (acc.kind == Value::Kind::Constant && next.kind == Value::Kind::Constant) {
            const Value greater = g.binary(QStringLiteral(">"), next, acc, at);
            if (greater.valid() && (greater.constant.i != 0) == max)
                acc = next;
            continue;
        }
        const std::uint32_t out = g.temp(type);
        g.instr(typedOp(max ? op::Max : op::Min, vtOf(*type)), out, g.materialize(acc), g.materialize(next));
        acc = g.operandValue(out, type);
    }
    return acc;
}

// SEL and MUX: evaluate all inputs (IEC evaluates every argument), then pick one.
Value select(Codegen &g, const Value &selector, std::vector<Value> inputs, const char *name, SourceLocation at, const Place *destination)
{
    if (selector.kind == Value::Kind::Constant && allLiterals(inputs)) {
        // SEL(TRUE, 1, 2) of literals is the literal 2.
        const std::int64_t k = selector.constant.i;
        if (k >= 0 && k < std::int64_t(inputs.size()))
            return inputs[size_t(k)];
    }
    const Type *fromDestination = literalsTypeFrom(inputs, destination);
    // Literals alone with a selector known only at run time: the result is computed as LINT (or
    // LREAL) and takes the type its use needs, as the literals would (ROR(SEL(b, 0, 16#08), 3)).
    const bool fromLiterals = !fromDestination && selector.kind != Value::Kind::Constant && allUntyped(inputs);
    const Type *type = fromDestination ? fromDestination
        : fromLiterals ? g.elem(std::any_of(inputs.begin(), inputs.end(), realLiteral) ? Elem::LReal : Elem::LInt)
                       : commonOf(g, inputs, 0, name, at);
    if (!type)
        return {};
    std::optional<std::pair<std::int64_t, std::int64_t>> range;
    if (fromLiterals && !isReal(type)) {
        range = std::make_pair(INT64_MAX, INT64_MIN);
        for (const Value &v : inputs) {
            const auto r = v.kind == Value::Kind::Constant && !v.constant.bigUnsigned ? std::make_optional(std::make_pair(v.constant.i, v.constant.i)) : v.literalRange;
            if (!r) {
                range.reset();
                break;
            }
            range = std::make_pair(std::min(range->first, r->first), std::max(range->second, r->second));
        }
    }
    for (Value &v : inputs) {
        v = g.coerce(v, type, at);
        if (!v.valid())
            return {};
    }
    if (selector.kind == Value::Kind::Constant) {
        const std::int64_t k = selector.constant.i;
        if (k < 0 || k >= std::int64_t(inputs.size())) {
            g.error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 has no input %2.").arg(QLatin1String(name)).arg(k));
            return {};
        }
        return inputs[size_t(k)];
    }
    const std::uint32_t out = g.temp(type);
    g.emitMove(out, g.materialize(inputs[0]), type);
    for (size_t k = 1; k < inputs.size(); ++k) {
        std::uint32_t condition = selector.operand;
        if (selector.type->elem != Elem::Bool) {
            ConstValue c;
            c.kind = ConstValue::Kind::Int;
            c.i = std::int64_t(k);
            condition = g.binary(QStringLiteral("="), selector, g.constantValue(g.elem(Elem::LInt), c, true), at).operand;
        }
        const std::uint32_t skip = g.instr(op::Jz, 0, condition);
        g.emitMove(out, g.materialize(inputs[k]), type);
        g.patchJump(skip, g.here());
    }
    Value result = g.operandValue(out, type);
    result.untyped = fromLiterals;
    result.literalRange = range;
    return result;
}

// SHL(1, 3) of literals is a literal (8), which then fits any bit string it is given to.
std::optional<Value> foldLiteralShift(Codegen &g, std::uint16_t family, const Value &in, const Value &n)
{
    if ((family != op::Shl && family != op::Shr) || !in.untyped || in.kind != Value::Kind::Constant || in.constant.kind != ConstValue::Kind::Int
        || n.kind != Value::Kind::Constant || n.constant.kind != ConstValue::Kind::Int || (in.constant.i < 0 && !in.constant.bigUnsigned)
        || n.constant.i < 0)
        return std::nullopt;
    const auto bits = static_cast<std::uint64_t>(in.constant.i);
    const auto count = static_cast<std::uint64_t>(n.constant.i);
    const std::uint64_t result = count >= 64 ? 0 : family == op::Shl ? bits << count : bits >> count;
    ConstValue c;
    c.kind = ConstValue::Kind::Int;
    c.i = static_cast<std::int64_t>(result);
    c.bigUnsigned = result > std::uint64_t(INT64_MAX);
    Value shifted = g.constantValue(g.elem(Elem::LInt), c, true);
    shifted.bitPattern = true; // w := SHL(507, 9) keeps the low 16 bits of 259584 in a WORD
    return shifted;
}

// The bit string as wide as an integer type: INT -> WORD.
Elem bitsOfSize(std::uint32_t size)
{
    return size == 1 ? Elem::Byte : size == 2 ? Elem::Word : size == 4 ? Elem::DWord : Elem::LWord;
}

// SHL(i, n) of an integer, which CODESYS accepts (OSCAT: SHL(year, 14) = 0): its bits are shifted
// as those of the bit string of its size, and the result has its type; IEC wants a bit string, so
// a warning says so. SHR of a signed integer keeps its sign, as in CODESYS (OSCAT's SET_DATE needs
// SHR(-1, 1) = -1): a negative value is shifted as NOT SHR(NOT i, n).
Value shiftInteger(Codegen &g, std::uint16_t family, const char *name, const Value &in, const Value &count, SourceLocation at)
{
    const Elem bitsElem = bitsOfSize(in.type->size);
    g.warning(at, QCoreApplication::translate("iec::interp::Compiler",
                      "%1 of %2: IEC 61131-3 shifts bit strings only; as in CODESYS, its bits are shifted as those of a %3.")
                      .arg(QLatin1String(name), typeName(in.type), info(bitsElem).name));
    const Value bits = g.convertExplicit(in, g.elem(bitsElem), at);
    const Value n = g.convertExplicit(count, g.elem(Elem::ULInt), at);
    if (!bits.valid() || !n.valid())
        return {};
    const auto shifted = [&](const Value &value) {
        const std::uint32_t out = g.temp(bits.type);
        g.instr(typedOp(family, vtOf(*bits.type)), out, g.materialize(value), g.materialize(n));
        return g.operandValue(out, bits.type);
    };
    Value result = shifted(bits);
    if (qstrcmp(name, "SHR") == 0 && !info(in.type->elem).isUnsigned) {
        ConstValue ones;
        ones.kind = ConstValue::Kind::Int;
        ones.i = bits.type->size == 8 ? -1 : (std::int64_t(1) << (8 * bits.type->size)) - 1;
        ones.bigUnsigned = bits.type->size == 8;
        const Value allOnes = g.constantValue(bits.type, ones);
        const Value keptSign = g.binary(QStringLiteral("XOR"), shifted(g.binary(QStringLiteral("XOR"), bits, allOnes, at)), allOnes, at);
        ConstValue zero;
        zero.kind = ConstValue::Kind::Int;
        const Value negative = g.binary(QStringLiteral("<"), in, g.constantValue(in.type, zero), at);
        result = select(g, negative, {result, keptSign}, "SHR", at, nullptr);
    }
    return g.convertExplicit(result, in.type, at);
}

Value shift(Codegen &g, std::uint16_t family, const char *name, std::vector<Value> &args, SourceLocation at, const Place *destination)
{
    Value in = args[0];
    if (in.untyped) {
        // A negative literal takes the type of the signed integer the result goes to (as CODESYS:
        // i := SHR(-8, 2) is -2).
        const Type *destinationType = destination ? destination->type : nullptr;
        if (in.kind == Value::Kind::Constant && in.constant.kind == ConstValue::Kind::Int && in.constant.i < 0
            && !in.constant.bigUnsigned && destinationType && destinationType->kind == TypeKind::Elementary
            && isIntegral(destinationType) && !isBits(destinationType) && !info(destinationType->elem).isUnsigned)
            in = g.coerce(in, destinationType, at);
    }
    if (const auto folded = foldLiteralShift(g, family, in, args[1]))
        return *folded;
    if (in.untyped) {
        // A literal takes the width of the variable the result goes to (b := ROL(16#81, 1) rotates
        // a BYTE), else a DWORD.
        const Type *destinationType = destination ? destination->type : nullptr;
        const bool toBits = destinationType && destinationType->kind == TypeKind::Elementary && isBits(destinationType)
            && destinationType->elem != Elem::Bool && (in.kind != Value::Kind::Constant || fits(in.constant, destinationType->elem));
        in = g.coerce(in, toBits ? destinationType : g.elem(Elem::DWord), at);
    }
    if (!in.valid())
        return {};
    if (isIntegral(in.type) && !isBits(in.type) && in.type->kind == TypeKind::Elementary)
        return shiftInteger(g, family, name, in, args[1], at);
    if (!isBits(in.type) || in.type->elem == Elem::Bool) {
        g.error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 needs a bit string (BYTE, WORD, DWORD, LWORD), not %2.").arg(QLatin1String(name), typeName(in.type)),
                isIntegral(in.type) ? QCoreApplication::translate("iec::interp::Compiler", "convert it first, e.g. %1_TO_%2").arg(info(in.type->elem).name, info(Elem(int(Elem::Byte) + (in.type->size == 1 ? 0 : in.type->size == 2 ? 1 : in.type->size == 4 ? 2 : 3))).name) : QString());
        return {};
    }
    const Value n = g.convertExplicit(args[1], g.elem(Elem::ULInt), at);
    if (!n.valid())
        return {};
    const std::uint32_t out = g.temp(in.type);
    g.instr(typedOp(family, vtOf(*in.type)), out, g.materialize(in), g.materialize(n));
    return g.operandValue(out, in.type);
}

Value toDint(Codegen &g, const Value &v, SourceLocation at)
{
    if (!v.valid())
        return {};
    if (!v.untyped && !isIntegral(v.type)) {
        g.error(at, QCoreApplication::translate("iec::interp::Compiler", "A length or position must be an integer, not %1.").arg(typeName(v.type)));
        return {};
    }
    return v.untyped ? g.coerce(v, g.elem(Elem::DInt), at) : g.convertExplicit(v, g.elem(Elem::DInt), at);
}

bool needString(Codegen &g, const Value &v, const char *name, SourceLocation at)
{
    if (isString(v.type))
        return true;
    g.error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 needs a STRING or WSTRING, not %2.").arg(QLatin1String(name), typeName(v.type)));
    return false;
}

// A string function's result: a temporary string of `capacity` characters.
const Type *stringResult(Codegen &g, const Type *like, std::uint32_t capacity)
{
    return g.m_types->string(like->wide, std::max<std::uint32_t>(1, std::min<std::uint32_t>(capacity, 65535)));
}

Value intResult(Codegen &g, std::uint32_t dint)
{
    // String positions and lengths are INT, computed as DINT.
    const std::uint32_t out = g.temp(g.elem(Elem::Int));
    g.instr(convertOp(VT::I32, VT::I16), out, dint);
    return g.operandValue(out, g.elem(Elem::Int));
}

Value timeFunction(Codegen &g, const char *op, Elem left, Elem right, std::vector<Value> &args, SourceLocation at)
{
    const auto check = [&](const Value &v, Elem e) {
        if (v.untyped && (info(e).isInt || info(e).isReal))
            return true;
        if (v.type->kind == TypeKind::Elementary && (v.type->elem == e || (e == Elem::LInt && (isIntegral(v.type) || isReal(v.type)))))
            return true;
        g.error(at, QCoreApplication::translate("iec::interp::Compiler", "This time function needs a %1, not %2.").arg(QLatin1String(info(e).name), typeName(v.type)));
        return false;
    };
    if (!check(args[0], left) || !check(args[1], right))
        return {};
    return g.binary(QLatin1String(op), args[0], args[1], at);
}

const std::vector<StdFunction> &table()
{
    static const std::vector<StdFunction> functions = [] {
        std::vector<StdFunction> t;
        for (const MathEntry &m : kMath) {
            t.push_back({m.name, {"IN"}, false, [&m](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                             return mathFunction(g, m, a[0], at);
                         }});
        }
        t.push_back({"ABS", {"IN"}, false, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) -> Value {
                         Value v = a[0];
                         if (v.kind == Value::Kind::Constant) {
                             const Value negative = g.binary(QStringLiteral("<"), v, g.constantValue(g.elem(Elem::LInt), ConstValue{ConstValue::Kind::Int, 0, false, 0, {}, false}, true), at);
                             return negative.valid() && negative.constant.i ? g.unary(QStringLiteral("-"), v, at) : v;
                         }
                         if (!isIntegral(v.type) && !isReal(v.type)) {
                             g.error(at, QCoreApplication::translate("iec::interp::Compiler", "ABS needs a number, not %1.").arg(typeName(v.type)));
                             return {};
                         }
                         const std::uint32_t out = g.temp(v.type);
                         g.instr(typedOp(op::Abs, vtOf(*v.type)), out, v.operand);
                         return g.operandValue(out, v.type);
                     }});
        t.push_back({"TRUNC", {"IN"}, false, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *d) {
                         if (!a[0].untyped && !isReal(a[0].type)) {
                             g.error(at, QCoreApplication::translate("iec::interp::Compiler", "TRUNC needs a REAL or LREAL, not %1.").arg(typeName(a[0].type)));
                             return Value{};
                         }
                         // ANY_INT: the integer type it is assigned to (i := TRUNC(r) with i : INT), else
                         // DINT as in CODESYS 3.5 (CoDeSys 2.3's TRUNC gave INT).
                         const Type *to = d && d->type && d->type->kind == TypeKind::Elementary && isIntegral(d->type) ? d->type : g.elem(Elem::DInt);
                         return g.convertExplicit(a[0], to, at, true);
                     }});
        t.push_back({"EXPT", {"IN1", "IN2"}, false, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *d) {
                         return g.binary(QStringLiteral("**"), a[0], a[1], at, d);
                     }});
        struct Arith {
            const char *name;
            const char *op;
            bool extensible;
        };
        static const Arith arith[] = {{"ADD", "+", true}, {"MUL", "*", true}, {"SUB", "-", false}, {"DIV", "/", false},
                                      {"MOD", "MOD", false}, {"AND", "AND", true}, {"OR", "OR", true}, {"XOR", "XOR", true}};
        for (const Arith &ar : arith) {
            t.push_back({ar.name, {"IN1", "IN2"}, ar.extensible, [&ar](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                             return chain(g, ar.op, a, at);
                         }});
        }
        t.push_back({"NOT", {"IN"}, false, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *d) {
                         return g.unary(QStringLiteral("NOT"), a[0], at, d);
                     }});
        t.push_back({"MOVE", {"IN"}, false, [](Codegen &, std::vector<Value> &a, SourceLocation, const Place *) { return a[0]; }});
        struct Shift {
            const char *name;
            std::uint16_t family;
        };
        static const Shift shifts[] = {{"SHL", op::Shl}, {"SHR", op::Shr}, {"ROL", op::Rol}, {"ROR", op::Ror}};
        for (const Shift &s : shifts) {
            t.push_back({s.name, {"IN", "N"}, false, [&s](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *d) {
                             return shift(g, s.family, s.name, a, at, d);
                         }});
        }
        t.push_back({"SEL", {"G", "IN0", "IN1"}, false, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *d) {
                         const Value selector = g.coerce(a[0], g.boolType(), at, QCoreApplication::translate("iec::interp::Compiler", "(the G input of SEL)"));
                         if (!selector.valid())
                             return Value{};
                         return select(g, selector, {a[1], a[2]}, "SEL", at, d);
                     }});
        t.push_back({"MUX", {"K", "IN"}, true, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *d) {
                         if (!a[0].untyped && !isIntegral(a[0].type)) {
                             g.error(at, QCoreApplication::translate("iec::interp::Compiler", "The selector K of MUX must be an integer."));
                             return Value{};
                         }
                         return select(g, a[0], std::vector<Value>(a.begin() + 1, a.end()), "MUX", at, d);
                     }});
        t.push_back({"MAX", {"IN1", "IN2"}, true, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                         return minMax(g, true, a, at);
                     }});
        t.push_back({"MIN", {"IN1", "IN2"}, true, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                         return minMax(g, false, a, at);
                     }});
        t.push_back({"LIMIT", {"MN", "IN", "MX"}, false, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                         std::vector<Value> low{a[1], a[0]};
                         std::vector<Value> high{minMax(g, true, low, at), a[2]};
                         if (!high[0].valid())
                             return Value{};
                         return minMax(g, false, high, at);
                     }});
        struct Compare {
            const char *name;
            const char *op;
            bool extensible;
        };
        static const Compare compares[] = {{"GT", ">", true}, {"GE", ">=", true}, {"EQ", "=", true},
                                           {"LE", "<=", true}, {"LT", "<", true}, {"NE", "<>", false}};
        for (const Compare &c : compares) {
            t.push_back({c.name, {"IN1", "IN2"}, c.extensible, [&c](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                             return compareChain(g, c.op, a, at);
                         }});
        }
        // Strings.
        t.push_back({"LEN", {"IN"}, false, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                         if (!needString(g, a[0], "LEN", at))
                             return Value{};
                         const std::uint32_t n = g.temp(g.elem(Elem::DInt));
                         g.instr(op::StrLen, n, g.materialize(a[0]), 0, 0, a[0].type->wide ? 1 : 0);
                         return intResult(g, n);
                     }});
        for (const char *name : {"LEFT", "RIGHT"}) {
            const bool left = QLatin1String(name) == QLatin1String("LEFT");
            t.push_back({name, {"IN", "L"}, false, [left, name](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                             const Value l = toDint(g, a[1], at);
                             if (!needString(g, a[0], name, at) || !l.valid())
                                 return Value{};
                             const Type *result = stringResult(g, a[0].type, a[0].type->capacity);
                             const std::uint32_t out = g.temp(result);
                             g.instr(left ? op::StrLeft : op::StrRight, out, g.materialize(a[0]), g.materialize(l), 0, result->wide ? 1 : 0);
                             return g.operandValue(out, result);
                         }});
        }
        t.push_back({"MID", {"IN", "L", "P"}, false, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                         const Value l = toDint(g, a[1], at), p = toDint(g, a[2], at);
                         if (!needString(g, a[0], "MID", at) || !l.valid() || !p.valid())
                             return Value{};
                         const Type *result = stringResult(g, a[0].type, a[0].type->capacity);
                         const std::uint32_t out = g.temp(result);
                         g.instr(op::StrMid, out, g.materialize(a[0]), g.materialize(l), g.materialize(p), result->wide ? 1 : 0);
                         return g.operandValue(out, result);
                     }});
        t.push_back({"DELETE", {"IN", "L", "P"}, false, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                         const Value l = toDint(g, a[1], at), p = toDint(g, a[2], at);
                         if (!needString(g, a[0], "DELETE", at) || !l.valid() || !p.valid())
                             return Value{};
                         const Type *result = stringResult(g, a[0].type, a[0].type->capacity);
                         const std::uint32_t out = g.temp(result);
                         g.instr(op::StrDelete, out, g.materialize(a[0]), g.materialize(l), g.materialize(p), result->wide ? 1 : 0);
                         return g.operandValue(out, result);
                     }});
        t.push_back({"INSERT", {"IN1", "IN2", "P"}, false, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                         const Value p = toDint(g, a[2], at);
                         if (!needString(g, a[0], "INSERT", at) || !needString(g, a[1], "INSERT", at) || !p.valid())
                             return Value{};
                         const Type *result = stringResult(g, a[0].type, a[0].type->capacity + a[1].type->capacity);
                         const std::uint32_t out = g.temp(result);
                         g.instr(op::StrInsert, out, g.materialize(a[0]), g.materialize(g.coerce(a[1], a[0].type, at)), g.materialize(p), result->wide ? 1 : 0);
                         return g.operandValue(out, result);
                     }});
        t.push_back({"REPLACE", {"IN1", "IN2", "L", "P"}, false, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                         const Value l = toDint(g, a[2], at), p = toDint(g, a[3], at);
                         if (!needString(g, a[0], "REPLACE", at) || !needString(g, a[1], "REPLACE", at) || !l.valid() || !p.valid())
                             return Value{};
                         // L and P go to two neighbouring DINTs: the instruction has one operand for both.
                         const std::uint32_t pair = g.temp(g.elem(Elem::LInt));
                         g.instr(op::Mov4, pair, g.materialize(l));
                         g.instr(op::Mov4, pair + 4, g.materialize(p));
                         const Type *result = stringResult(g, a[0].type, a[0].type->capacity + a[1].type->capacity);
                         const std::uint32_t out = g.temp(result);
                         g.instr(op::StrReplace, out, g.materialize(a[0]), g.materialize(g.coerce(a[1], a[0].type, at)), pair, result->wide ? 1 : 0);
                         return g.operandValue(out, result);
                     }});
        t.push_back({"FIND", {"IN1", "IN2"}, false, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                         if (!needString(g, a[0], "FIND", at) || !needString(g, a[1], "FIND", at))
                             return Value{};
                         const std::uint32_t n = g.temp(g.elem(Elem::DInt));
                         g.instr(op::StrFind, n, g.materialize(a[0]), g.materialize(g.coerce(a[1], a[0].type, at)), 0, a[0].type->wide ? 1 : 0);
                         return intResult(g, n);
                     }});
        t.push_back({"CONCAT", {"IN1", "IN2"}, true, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                         Value acc = a[0];
                         if (!needString(g, acc, "CONCAT", at))
                             return Value{};
                         for (size_t i = 1; i < a.size(); ++i) {
                             if (!needString(g, a[i], "CONCAT", at))
                                 return Value{};
                             const Type *result = stringResult(g, acc.type, acc.type->capacity + a[i].type->capacity);
                             const std::uint32_t out = g.temp(result);
                             g.instr(op::StrConcat, out, g.materialize(acc), g.materialize(g.coerce(a[i], acc.type, at)), 0, result->wide ? 1 : 0);
                             acc = g.operandValue(out, result);
                         }
                         return acc;
                     }});
        // Time and date arithmetic as functions.
        struct TimeFn {
            const char *name;
            const char *op;
            Elem left, right;
        };
        static const TimeFn timeFns[] = {
            {"ADD_TIME", "+", Elem::Time, Elem::Time},       {"SUB_TIME", "-", Elem::Time, Elem::Time},
            {"MUL_TIME", "*", Elem::Time, Elem::LInt},       {"DIV_TIME", "/", Elem::Time, Elem::LInt},
            {"ADD_TOD_TIME", "+", Elem::Tod, Elem::Time},    {"ADD_DT_TIME", "+", Elem::Dt, Elem::Time},
            {"SUB_TOD_TIME", "-", Elem::Tod, Elem::Time},    {"SUB_DT_TIME", "-", Elem::Dt, Elem::Time},
            {"SUB_DATE_DATE", "-", Elem::Date, Elem::Date},  {"SUB_TOD_TOD", "-", Elem::Tod, Elem::Tod},
            {"SUB_DT_DT", "-", Elem::Dt, Elem::Dt},
        };
        for (const TimeFn &f : timeFns) {
            t.push_back({f.name, {"IN1", "IN2"}, false, [&f](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                             return timeFunction(g, f.op, f.left, f.right, a, at);
                         }});
        }
        // The virtual clock, for the standard timers.
        // CoDeSys 2.3's TIME() is the time since the PLC started: the same virtual clock.
        const auto now = [](Codegen &g, std::vector<Value> &, SourceLocation, const Place *) {
            const std::uint32_t out = g.temp(g.elem(Elem::Time));
            g.instr(op::Now, out);
            return g.operandValue(out, g.elem(Elem::Time));
        };
        t.push_back({"__SYSTIME", {}, false, now});
        t.push_back({"TIME", {}, false, now});
        // Beremiz LOGGER's message (utillib.cpp): a statement, no value.
        t.push_back({"__LOG", {"LEVEL", "MSG"}, false, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                         const Value level = a[0].type->kind == TypeKind::Enum ? g.convertExplicit(a[0], g.elem(Elem::Int), at)
                                                                               : g.coerce(a[0], g.elem(Elem::Int), at);
                         if (!level.valid() || !needString(g, a[1], "__LOG", at))
                             return Value{};
                         g.instr(op::Log, g.materialize(level), g.materialize(a[1]));
                         return Value{};
                     }});
        t.push_back({"CONCAT_DATE_TOD", {"IN1", "IN2"}, false, [](Codegen &g, std::vector<Value> &a, SourceLocation at, const Place *) {
                         if (a[0].type->elem != Elem::Date || a[1].type->elem != Elem::Tod || a[0].type->kind != TypeKind::Elementary) {
                             g.error(at, QCoreApplication::translate("iec::interp::Compiler", "CONCAT_DATE_TOD needs a DATE and a TIME_OF_DAY."));
                             return Value{};
                         }
                         Value d = a[0], tod = a[1];
                         d.type = tod.type = g.elem(Elem::LInt);
                         Value sum = g.binary(QStringLiteral("+"), d, tod, at);
                         sum.type = g.elem(Elem::Dt);
                         return sum;
                     }});
        return t;
    }();
    return functions;
}

// Conversions, recognised by their names.
const QRegularExpression &conversionPattern()
{
    static const QRegularExpression pattern(QStringLiteral("^(?:([A-Z_]+?)_)?(TO_BCD|BCD_TO|TRUNC|TO)_([A-Z_]+)$"));
    return pattern;
}

} // namespace

std::optional<Value> Codegen::standardFunction(const QString &name, std::vector<Value> args, const std::vector<QString> &names,
                                               SourceLocation at, const Place *destination)
{
    const QRegularExpression &conversion = conversionPattern();
    static const QRegularExpression legacyBcd(QStringLiteral("^([A-Z]+)_TO_BCD$"));
    const auto single = [&](const char *what) {
        if (args.size() != 1) {
            error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 takes one argument.").arg(QLatin1String(what)));
            return false;
        }
        return true;
    };
    const auto bcd = [&](const Value &v, const Type *to, bool toBinary) -> Value {
        const Value bits = toBinary ? v : convertExplicit(v, to, at);
        if (!bits.valid())
            return {};
        const Type *work = toBinary ? v.type : to;
        const std::uint32_t out = temp(work);
        instr(typedOp(op::Bcd, vtOf(*work)), out, materialize(bits), 0, 0, toBinary ? 1 : 0);
        Value result = operandValue(out, work);
        return toBinary ? convertExplicit(result, to, at) : result;
    };
    static constexpr Elem bitsOfSize[] = {Elem::Byte, Elem::Byte, Elem::Word, Elem::Word, Elem::DWord, Elem::DWord, Elem::DWord, Elem::DWord, Elem::LWord};
    const auto constant = [&](Elem type, std::int64_t value) {
        return constantValue(elem(type), ConstValue{ConstValue::Kind::Int, value, false, 0, {}, false});
    };
    if (name == QLatin1String("INT_TO_BCD") && single("INT_TO_BCD")) {
        // CODESYS Util: INT_TO_BCD(I : INT) : BYTE, two BCD digits, 255 when I is not 0..99.
        const Value v = coerce(args[0], elem(Elem::Int), at);
        if (!v.valid())
            return Value{};
        const Value inRange = binary(QStringLiteral("AND"), binary(QStringLiteral(">="), v, constant(Elem::Int, 0), at),
                                     binary(QStringLiteral("<="), v, constant(Elem::Int, 99), at), at);
        return select(*this, inRange, {constant(Elem::Byte, 255), bcd(v, elem(Elem::Byte), false)}, "INT_TO_BCD", at, nullptr);
    }
    const bool byteArgument = args.size() == 1 && args[0].valid()
        && ((args[0].type->kind == TypeKind::Elementary && args[0].type->elem == Elem::Byte)
            || (args[0].untyped && args[0].kind == Value::Kind::Constant && args[0].constant.kind == ConstValue::Kind::Int && fits(args[0].constant, Elem::Byte)));
    if (name == QLatin1String("BCD_TO_INT") && byteArgument) {
        // CODESYS Util: BCD_TO_INT(B : BYTE) : INT, -1 when a digit is not 0..9 (wider bit
        // strings take the generic conversion below).
        const Value b = coerce(args[0], elem(Elem::Byte), at);
        const Value low = binary(QStringLiteral("AND"), b, constant(Elem::Byte, 15), at);
        const Value high = binary(QStringLiteral("AND"), b, constant(Elem::Byte, 240), at);
        const Value valid = binary(QStringLiteral("AND"), binary(QStringLiteral("<="), low, constant(Elem::Byte, 9), at),
                                   binary(QStringLiteral("<="), high, constant(Elem::Byte, 144), at), at);
        return select(*this, valid, {constant(Elem::Int, -1), bcd(b, elem(Elem::Int), true)}, "BCD_TO_INT", at, nullptr);
    }
    if (const auto m = legacyBcd.match(name); m.hasMatch() && !name.contains(QLatin1String("_TO_BCD_"))) {
        // INT_TO_BCD: the bit string of the same size holding the BCD digits.
        const Type *from = namedType(m.captured(1), at, false);
        if (from && isIntegral(from) && single("INT_TO_BCD")) {
            const Value v = coerce(args[0], from, at);
            return bcd(v, elem(bitsOfSize[from->size]), false);
        }
        // WORD_TO_BCD: a bit string read as a binary number, written back in BCD digits.
        if (from && isBits(from) && from->elem != Elem::Bool && single(qPrintable(name)))
            return bcd(coerce(args[0], from, at), from, false);
    }
    static const QRegularExpression genericBcd(QStringLiteral("^BCD_TO_([A-Z]+)$"));
    if (const auto m = genericBcd.match(name); m.hasMatch()) {
        // BCD_TO_INT(w): the BCD digits of any bit string as a number (a literal is taken as
        // the bit string of the result's size: BCD_TO_INT(16#1234) reads a WORD).
        const Type *to = namedType(m.captured(1), at, false);
        if (to && (isIntegral(to) || (isBits(to) && to->elem != Elem::Bool))) {
            if (!single(qPrintable(name)))
                return Value{};
            Value v = args[0];
            if (v.valid() && v.untyped)
                v = coerce(v, elem(bitsOfSize[to->size]), at);
            if (!v.valid())
                return Value{};
            if (!isBits(v.type) || v.type->elem == Elem::Bool) {
                error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 needs a bit string holding BCD digits.").arg(name));
                return Value{};
            }
            return bcd(v, to, true);
        }
    }
    if (const auto m = conversion.match(name); m.hasMatch()) {
        const QString fromName = m.captured(1), kind = m.captured(2), toName = m.captured(3);
        const Type *from = fromName.isEmpty() ? nullptr : namedType(fromName, at, false);
        const Type *to = namedType(toName, at, false);
        const bool known = to && (fromName.isEmpty() || from) && (to->isElementary() || to->kind == TypeKind::String);
        if (known) {
            if (!single(qPrintable(name)))
                return Value{};
            Value v = args[0];
            if (from) {
                const bool exact = v.type == from || (v.type->kind == TypeKind::Elementary && from->kind == TypeKind::Elementary && v.type->elem == from->elem)
                    || (v.type->kind == TypeKind::String && from->kind == TypeKind::String && v.type->wide == from->wide);
                if (!exact) {
                    v = coerce(v, from, at, QCoreApplication::translate("iec::interp::Compiler", "(the input of %1)").arg(name));
                    if (!v.valid())
                        return Value{};
                }
            }
            if (kind == QLatin1String("BCD_TO")) {
                if (!isBits(v.type) || v.type->elem == Elem::Bool) {
                    error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 needs a bit string holding BCD digits.").arg(name));
                    return Value{};
                }
                return bcd(v, to, true);
            }
            if (kind == QLatin1String("TO_BCD"))
                return bcd(v, to, false);
            return convertExplicit(v, to, at, kind == QLatin1String("TRUNC"));
        }
    }
    for (const StdFunction &f : table()) {
        if (name != QLatin1String(f.name))
            continue;
        // Put formal arguments (IN := x) in their positions.
        const size_t fixed = f.parameters.size();
        bool formal = false;
        for (const QString &n : names)
            formal = formal || !n.isEmpty();
        if (formal) {
            std::vector<Value> ordered(std::max(args.size(), fixed));
            std::vector<bool> set(ordered.size(), false);
            for (size_t i = 0; i < args.size(); ++i) {
                int position = -1;
                for (size_t p = 0; p < fixed; ++p) {
                    if (names[i] == QLatin1String(f.parameters[p]))
                        position = int(p);
                }
                if (position < 0 && f.extensible) {
                    // IN1, IN2, ... of extensible functions.
                    const QString base = QLatin1String(f.parameters.back()).chopped(QLatin1String(f.parameters.back()).endsWith(QLatin1Char('2')) ? 1 : 0);
                    bool ok = false;
                    const int n = names[i].startsWith(base) ? names[i].mid(base.size()).toInt(&ok) : -1;
                    if (ok)
                        position = base == QLatin1String("IN") && QLatin1String(f.parameters.back()) == QLatin1String("IN") ? n + 1 : n - 1;
                }
                if (position < 0 || size_t(position) >= ordered.size() || set[size_t(position)]) {
                    error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 has no parameter called %2.").arg(name, names[i]));
                    return Value{};
                }
                ordered[size_t(position)] = args[i];
                set[size_t(position)] = true;
            }
            args = ordered;
        }
        if (args.size() < fixed || (!f.extensible && args.size() > fixed)) {
            error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 takes %2%3 argument(s), not %4.").arg(name, f.extensible ? QCoreApplication::translate("iec::interp::Compiler", "at least ") : QString()).arg(fixed).arg(args.size()));
            return Value{};
        }
        for (const Value &v : args) {
            if (!v.valid()) {
                error(at, QCoreApplication::translate("iec::interp::Compiler", "An argument of %1 is missing.").arg(name));
                return Value{};
            }
        }
        return f.compile(*this, args, at, destination);
    }
    return std::nullopt;
}

} // namespace iec::interp::detail

namespace iec::interp {

bool isStandardFunctionName(const QString &name)
{
    const QString upper = name.trimmed().toUpper();
    if (upper.startsWith(QLatin1String("__"))) // compiler intrinsics, not for users
        return false;
    const auto &functions = detail::table();
    return std::any_of(functions.begin(), functions.end(), [&](const detail::StdFunction &f) { return upper == QLatin1String(f.name); })
        || detail::conversionPattern().match(upper).hasMatch();
}

const QRegularExpression &conversionNamePattern()
{
    return detail::conversionPattern();
}

} // namespace iec::interp
