// CODESYS pointers and references: POINTER TO / REF_TO with ADR, ^, byte arithmetic and SIZEOF;
// REFERENCE TO with REF= and __ISVALIDREF. An address is the image offset of a variable (4 bytes,
// 0 = nowhere); every dereference is checked (op::CheckPtr), so a null or wild pointer stops the
// program with a located fault instead of reading or writing outside the image.
#include "interpreter/compiler/codegen.h"
#include "interpreter/compiler/typeutil.h"

#include <QCoreApplication>

namespace iec::interp::detail {

using namespace ast;

namespace {

// Addresses: pointers, and interface variables (which compare with 0 and each other).
bool isPointer(const Type *t)
{
    return t && (t->kind == TypeKind::Pointer || t->kind == TypeKind::Interface);
}

// CODESYS's address of a STRING is that of its first character (OSCAT walks a string's bytes from
// ADR(s)); here a string starts with its capacity and length, these 4 bytes before.
constexpr std::uint32_t kStringHeader = 4;

} // namespace

// `address` moved by `bytes` (a UDINT operand), for the header of a string.
std::uint32_t Codegen::offsetAddress(std::uint32_t address, std::int64_t bytes)
{
    ConstValue offset;
    offset.kind = ConstValue::Kind::Int;
    offset.i = bytes < 0 ? -bytes : bytes;
    const Value moved = binary(bytes < 0 ? QStringLiteral("-") : QStringLiteral("+"), operandValue(address, elem(Elem::UDInt)),
        constantValue(elem(Elem::UDInt), offset), {});
    return materialize(moved);
}

// The place at `address` (an operand holding an image offset), checked for `type`'s size first.
// A string's address is that of its characters; its place starts at its header.
Place Codegen::checkedTarget(std::uint32_t address, const Type *type, const QString &text)
{
    if (isString(type)) {
        instr(op::CheckPtr, 0, address, 0, std::max<std::uint32_t>(type->size - kStringHeader, 1));
        address = offsetAddress(address, -std::int64_t(kStringHeader));
    }
    instr(op::CheckPtr, 0, address, 0, std::max<std::uint32_t>(type->size, 1));
    Place p;
    p.kind = Place::Kind::Indirect;
    p.type = type;
    p.operand = address;
    p.text = text;
    p.fbPou = type->kind == TypeKind::FunctionBlock ? type->pou : -1;
    return p;
}

// A REFERENCE TO variable stands for what it refers to.
Place Codegen::dereferenced(const Place &slot)
{
    if (slot.kind == Place::Kind::Invalid || !slot.type || slot.type->kind != TypeKind::Reference)
        return slot;
    std::uint32_t address = slot.operand;
    if (slot.kind == Place::Kind::Indirect) {
        address = temp(elem(Elem::UDInt));
        instr(op::Load4, address, slot.operand);
    } else if (slot.kind != Place::Kind::Direct) {
        return {};
    }
    return checkedTarget(address, slot.type->element, slot.text);
}

// p^: what the pointer p points to.
Place Codegen::pointee(const Expr &expr, bool reportUnknown)
{
    const Place base = resolvePlace(expr.operands.front(), reportUnknown);
    if (base.kind == Place::Kind::Invalid)
        return {};
    if (!base.type || base.type->kind != TypeKind::Pointer) {
        error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "%1 is a %2, not a pointer; only a pointer is dereferenced with ^.").arg(base.text, typeName(base.type)));
        return {};
    }
    const Value address = read(base);
    if (!address.valid())
        return {};
    return checkedTarget(materialize(address), base.type->element, expr.text);
}

// The image address of a variable, as a POINTER TO its type.
Value Codegen::addressOf(const Expr &expr, const QString &function)
{
    const Place p = resolvePlace(expr);
    if (p.kind == Place::Kind::Invalid)
        return {};
    if (p.kind != Place::Kind::Direct && p.kind != Place::Kind::Indirect) {
        error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "%1 needs a variable (not a constant or a single bit).").arg(function));
        return {};
    }
    const Type *pointer = m_types->pointer(p.type);
    const std::uint32_t out = temp(pointer);
    if (p.kind == Place::Kind::Direct)
        instr(op::Lea, out, p.operand);
    else
        instr(op::Mov4, out, p.operand);
    if (isString(p.type))
        return operandValue(offsetAddress(out, kStringHeader), pointer);
    return operandValue(out, pointer);
}

// ADR, REF, SIZEOF and __ISVALIDREF; nullopt when `name` is none of them.
std::optional<Value> Codegen::pointerFunction(const QString &name, const std::vector<CallArg> &args, SourceLocation at)
{
    const QString upper = name.toUpper();
    const bool adr = upper == QLatin1String("ADR") || upper == QLatin1String("REF");
    const bool size = upper == QLatin1String("SIZEOF");
    const bool valid = upper == QLatin1String("__ISVALIDREF");
    if (!adr && !size && !valid)
        return std::nullopt;
    if (args.size() != 1 || !args.front().name.isEmpty()) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 takes one argument.").arg(upper));
        return Value{};
    }
    const Expr &arg = args.front().value;
    if (adr)
        return addressOf(arg, upper);
    if (size) {
        // SIZEOF(INT) or SIZEOF(variable): a constant that takes the type its use needs.
        const Type *type = nullptr;
        if (arg.kind == ExprKind::Name && namePlace(arg, false).kind == Place::Kind::Invalid)
            type = namedType(arg.text, arg.location);
        else if (const Place p = resolvePlace(arg); p.kind != Place::Kind::Invalid)
            type = p.kind == Place::Kind::Bit || p.kind == Place::Kind::IndirectBit ? boolType() : p.type;
        if (!type)
            return Value{};
        ConstValue c;
        c.kind = ConstValue::Kind::Int;
        // A string's size as CODESYS counts it, its characters and the NUL (ADR(s) + SIZEOF(s) is
        // just past it); the capacity and length before them are not the program's.
        c.i = isString(type) ? (type->capacity + 1) * (type->wide ? 2 : 1) : type->size;
        return constantValue(elem(Elem::LInt), c, true);
    }
    // __ISVALIDREF(r): whether the reference r refers to a variable.
    const Place slot = resolvePlace(arg, true, false);
    if (slot.kind == Place::Kind::Invalid)
        return Value{};
    if (!slot.type || slot.type->kind != TypeKind::Reference) {
        error(arg.location, QCoreApplication::translate("iec::interp::Compiler", "__ISVALIDREF needs a REFERENCE TO variable, not %1.").arg(typeName(slot.type)));
        return Value{};
    }
    Place raw = slot;
    raw.type = elem(Elem::UDInt);
    ConstValue zero;
    zero.kind = ConstValue::Kind::Int;
    return binary(QStringLiteral("<>"), read(raw), constantValue(elem(Elem::UDInt), zero), at);
}

// r REF= x: r refers to x from now on.
void Codegen::referenceAssignment(const Stmt &s)
{
    Place slot = resolvePlace(s.target, true, false);
    if (slot.kind == Place::Kind::Invalid)
        return;
    if (!slot.type || slot.type->kind != TypeKind::Reference) {
        error(s.target.location, QCoreApplication::translate("iec::interp::Compiler", "REF= needs a REFERENCE TO variable on its left, not %1.").arg(typeName(slot.type)),
              QCoreApplication::translate("iec::interp::Compiler", "to assign a value write :="));
        return;
    }
    const Place target = resolvePlace(s.value);
    if (target.kind == Place::Kind::Invalid)
        return;
    if ((target.kind != Place::Kind::Direct && target.kind != Place::Kind::Indirect) || !sameInOutType(slot.type->element, target.type)) {
        error(s.value.location, QCoreApplication::translate("iec::interp::Compiler", "%1 can refer to a variable of type %2, not to %3.")
                                    .arg(slot.text, typeName(slot.type->element), target.kind == Place::Kind::Constant ? QCoreApplication::translate("iec::interp::Compiler", "a constant") : typeName(target.type)));
        return;
    }
    slot.type = elem(Elem::UDInt);
    // A reference to a string holds its characters' address, as ADR does (checkedTarget).
    const std::uint32_t address = inOutAddress(target);
    store(slot, operandValue(isString(target.type) ? offsetAddress(address, kStringHeader) : address, elem(Elem::UDInt)), s.location);
}

// Addresses compute as UDINT: p + n and p - n move by n bytes (CODESYS), p - q is their
// distance, and pointers compare with each other and with 0. nullopt when no operand is a pointer.
std::optional<Value> Codegen::pointerArithmetic(const QString &op, Value left, Value right, SourceLocation at)
{
    if (!isPointer(left.type) && !isPointer(right.type))
        return std::nullopt;
    const Type *pointerType = isPointer(left.type) ? left.type : right.type;
    const Type *address = elem(Elem::UDInt);
    const auto asAddress = [&](Value v) {
        if (isPointer(v.type)) {
            v.type = address;
            return v;
        }
        if (v.untyped || isIntegral(v.type) || isBits(v.type))
            return v.untyped ? coerce(v, address, at) : convertExplicit(v, address, at);
        error(at, QCoreApplication::translate("iec::interp::Compiler", "'%1' cannot combine %2 and %3.").arg(op, typeName(left.type), typeName(right.type)));
        return Value{};
    };
    const bool comparison = op == QLatin1String("=") || op == QLatin1String("<>") || op == QLatin1String("<") || op == QLatin1String(">")
        || op == QLatin1String("<=") || op == QLatin1String(">=");
    const bool shift = op == QLatin1String("+") || op == QLatin1String("-");
    if (!comparison && !shift) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "A pointer can only be moved with + and -, and compared."));
        return Value{};
    }
    const bool distance = op == QLatin1String("-") && isPointer(left.type) && isPointer(right.type);
    if (op == QLatin1String("+") && isPointer(left.type) && isPointer(right.type)) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "Two pointers cannot be added; add a number of bytes to one."));
        return Value{};
    }
    const Value a = asAddress(left), b = asAddress(right);
    if (!a.valid() || !b.valid())
        return Value{};
    Value result = binary(op, a, b, at);
    if (!result.valid() || comparison)
        return result;
    if (distance)
        return convertExplicit(result, elem(Elem::DInt), at);
    result.type = pointerType;
    result.untyped = false;
    return result;
}

// Conversions CODESYS makes between addresses and numbers: a pointer of one type to a pointer of
// another (ADR(x) to any POINTER TO), and pointers to and from the unsigned integers and bit
// strings of 32 and 64 bits and from 0. nullopt when neither side is a pointer.
std::optional<Value> Codegen::coercePointer(Value v, const Type *to, SourceLocation at)
{
    const bool fromPointer = v.type && v.type->kind == TypeKind::Pointer, toPointer = to->kind == TypeKind::Pointer;
    if (!fromPointer && !toPointer)
        return std::nullopt;
    const auto wideUnsigned = [](const Type *t) {
        return t && t->kind == TypeKind::Elementary && t->size >= 4 && ((info(t->elem).isInt && info(t->elem).isUnsigned) || (isBits(t) && t->elem != Elem::Bool));
    };
    if (fromPointer && toPointer) {
        v.type = to;
        return v;
    }
    if (toPointer) {
        if (v.untyped && v.kind == Value::Kind::Constant && v.constant.kind == ConstValue::Kind::Int && v.constant.i == 0)
            return constantValue(to, v.constant);
        if (!wideUnsigned(v.type) && !(v.type && isIntegral(v.type) && v.type->size >= 4))
            return std::nullopt;
        Value asAddress = convertExplicit(v, elem(Elem::UDInt), at);
        asAddress.type = to;
        return asAddress;
    }
    if (!wideUnsigned(to))
        return std::nullopt;
    v.type = elem(Elem::UDInt);
    return convertExplicit(v, to, at);
}

} // namespace iec::interp::detail
