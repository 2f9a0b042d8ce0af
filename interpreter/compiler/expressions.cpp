// Expressions: names and places, implicit conversions, operators and constant folding.
#include "interpreter/compiler/codegen.h"
#include "interpreter/compiler/typeutil.h"

#include <QCoreApplication>

#include <cmath>
#include <cstring>
#include <utility>

namespace iec::interp::detail {

using namespace ast;

namespace {

// Relational operators to their opcode family; arithmetic ones likewise.
struct OperatorInfo {
    const char *text;
    std::uint16_t family;
    bool comparison;
};
constexpr OperatorInfo kOperators[] = {
    {"+", op::Add, false}, {"-", op::Sub, false}, {"*", op::Mul, false}, {"/", op::Div, false},
    {"MOD", op::Mod, false}, {"AND", op::And, false}, {"OR", op::Or, false}, {"XOR", op::Xor, false},
    {"=", op::Eq, true}, {"<>", op::Ne, true}, {"<", op::Lt, true}, {"<=", op::Le, true},
    {">", op::Gt, true}, {">=", op::Ge, true},
};
const OperatorInfo *operatorInfo(const QString &text)
{
    for (const OperatorInfo &o : kOperators) {
        if (text == QLatin1String(o.text))
            return &o;
    }
    return nullptr;
}

// Time and date arithmetic (IEC 61131-3 table 30) on the short forms; L forms are looked up
// through their short form and give an L result.
struct TimeRule {
    const char *op;
    Elem left, right, result;
};
constexpr TimeRule kTimeRules[] = {
    {"+", Elem::Time, Elem::Time, Elem::Time}, {"-", Elem::Time, Elem::Time, Elem::Time},
    {"+", Elem::Tod, Elem::Time, Elem::Tod},   {"-", Elem::Tod, Elem::Time, Elem::Tod},
    {"+", Elem::Dt, Elem::Time, Elem::Dt},     {"-", Elem::Dt, Elem::Time, Elem::Dt},
    {"-", Elem::Date, Elem::Date, Elem::Time}, {"-", Elem::Tod, Elem::Tod, Elem::Time},
    {"-", Elem::Dt, Elem::Dt, Elem::Time},
};
} // namespace

Value Codegen::operandValue(std::uint32_t operand, const Type *type) const
{
    Value v;
    v.kind = Value::Kind::Operand;
    v.type = type;
    v.operand = operand;
    return v;
}

Value Codegen::constantValue(const Type *type, const ConstValue &value, bool untyped) const
{
    Value v;
    v.kind = Value::Kind::Constant;
    v.type = type;
    v.constant = value;
    v.untyped = untyped;
    return v;
}

std::uint32_t Codegen::temp(const Type *type)
{
    const std::uint32_t align = std::max<std::uint32_t>(type->align, 1);
    m_tempTop = (m_tempTop + align - 1) / align * align;
    const std::uint32_t offset = m_tempTop;
    m_tempTop += std::max<std::uint32_t>(type->size, 1);
    m_tempMax = std::max(m_tempMax, m_tempTop);
    const std::uint32_t operand = kTempMarker | offset;
    if (!type->isElementary()) {
        // Temporaries are reused, so a string's capacity (and any aggregate's initial state) is
        // set when the temporary is taken, from a constant holding the type's initial value.
        static const ConstValue none;
        const std::uint32_t initial = constantOperand(type, none);
        if (type->kind == TypeKind::String)
            instr(op::Mov4, operand, initial); // capacity and an empty length
        else
            instr(op::MovN, operand, initial, 0, type->size);
    }
    return operand;
}

std::uint32_t Codegen::constantOperand(const Type *type, const ConstValue &value)
{
    // Build the bytes in a scratch image slot, then share identical constants.
    const std::uint32_t offset = allocate(type->size, std::max<std::uint32_t>(type->align, 1));
    if (value.kind == ConstValue::Kind::None)
        writeInitial(offset, type, nullptr);
    else
        writeConstant(offset, type, value, {});
    auto &image = m_module->initialImage;
    QByteArray k(reinterpret_cast<const char *>(image.data() + offset), static_cast<qsizetype>(type->size));
    k.prepend(QByteArray::number(quintptr(type->kind == TypeKind::Elementary ? elem(type->elem) : type)) + ':');
    if (const auto it = m_constants.constFind(k); it != m_constants.constEnd()) {
        image.resize(offset);
        return *it;
    }
    m_constants.insert(k, offset);
    return offset;
}

std::uint32_t Codegen::materialize(const Value &value)
{
    if (value.kind == Value::Kind::Operand)
        return value.operand;
    // An invalid value (no type) comes only after an error was reported, so no code will run; it
    // was taken as a constant of no type (found by fuzz_il: CONCAT with a string of NULs).
    if (!value.type)
        return 0;
    return constantOperand(value.type, value.constant);
}

void Codegen::emitMove(std::uint32_t to, std::uint32_t from, const Type *type)
{
    if (!type || to == from)
        return;
    // Q%1 := T%1.Q right after the timer ran with its inputs: the timer's instruction copies Q.
    if (type->kind == TypeKind::Elementary && type->size == 1 && here() > m_pouCodeStart && m_lastTarget != here()) {
        Instr &last = m_module->code.back();
        if (last.op == op::NativeFbArgs && last.e == 0 && (last.a & kOffsetMask) + 16 <= kOffsetMask && from == last.a + 16) {
            last.e = to; // Q is at offset 16 of TON, TOF and TP (nativeblocks.h)
            return;
        }
    }
    if (type->kind == TypeKind::String) {
        instr(op::StrMov, to, from, 0, 0, type->wide ? 3 : 0);
        return;
    }
    switch (type->size) {
    case 1: instr(op::Mov1, to, from); return;
    case 2: instr(op::Mov2, to, from); return;
    case 4: instr(op::Mov4, to, from); return;
    case 8: instr(op::Mov8, to, from); return;
    default: instr(op::MovN, to, from, 0, type->size); return;
    }
}

// ---------------------------------------------------------------------------- places

Place Codegen::memberPlace(const Place &base, const Member &member, const QString &text)
{
    // A located variable (x AT %QX0.1) is the process image's, whichever instance names it.
    if (!member.address.isEmpty() && !member.byReference) {
        if (const auto address = parseImageAddress(member.address)) {
            Place p = imagePlace(*address, member.type, text);
            p.readOnly = member.constant;
            p.readOnlyReason = QCoreApplication::translate("iec::interp::Compiler", "%1 is a constant and cannot be changed.").arg(text);
            return p;
        }
    }
    Place p;
    p.type = member.type;
    p.text = text;
    p.fbPou = member.type->kind == TypeKind::FunctionBlock ? member.type->pou : -1;
    p.readOnly = base.readOnly || member.constant;
    p.readOnlyReason = base.readOnly ? base.readOnlyReason : QCoreApplication::translate("iec::interp::Compiler", "%1 is a constant and cannot be changed.").arg(text);
    if (base.fbPou >= 0 && !p.readOnly && member.kind != VarKind::Input) {
        // From outside, an FB's inputs may be set; its outputs and internals only read.
        p.readOnly = true;
        p.readOnlyReason = member.kind == VarKind::Output
            ? QCoreApplication::translate("iec::interp::Compiler", "%1 is an output of the function block and can only be read.").arg(text)
            : QCoreApplication::translate("iec::interp::Compiler", "%1 is internal to the function block.").arg(text);
    }
    std::uint32_t slot = 0;
    bool slotIsPointer = false; // slot holds the address of the member (not the member itself)
    if (base.kind == Place::Kind::Direct) {
        slot = base.operand + member.offset;
    } else if (base.kind == Place::Kind::Indirect) {
        slot = temp(elem(Elem::UDInt));
        instr(op::PtrAdd, slot, base.operand, 0, member.offset);
        slotIsPointer = true;
    } else {
        return {};
    }
    if (member.byReference) {
        // The member holds the address of the variable passed to VAR_IN_OUT.
        if (slotIsPointer) {
            const std::uint32_t address = temp(elem(Elem::UDInt));
            instr(op::Load4, address, slot);
            slot = address;
        }
        p.kind = Place::Kind::Indirect;
        p.operand = slot;
        return p;
    }
    p.kind = slotIsPointer ? Place::Kind::Indirect : Place::Kind::Direct;
    p.operand = slot;
    return p;
}

// INT#40000 or BYTE#-1: a typed integer literal must lie in its type's range (it never wraps).
bool Codegen::typedLiteralFits(const ConstValue &value, const Type *type, const Expr &expr)
{
    if (value.kind != ConstValue::Kind::Int || type->kind != TypeKind::Elementary || type->elem == Elem::Bool)
        return true;
    const ElemInfo &e = info(type->elem);
    if ((!e.isInt && !e.isBit) || fits(value, type->elem))
        return true;
    if (e.size >= 8) {
        error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "The value %1 does not fit into %2.").arg(expr.text, typeName(type)));
        return false;
    }
    const IntRange range = rangeOf(type->elem);
    error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "The value %1 does not fit into %2 (%3 to %4).").arg(expr.text, typeName(type)).arg(range.low).arg(range.high));
    return false;
}

// A global CONSTANT by its value, before the global variables are declared: the POUs and types are
// laid out first, and CODESYS projects size arrays and strings with global constants
// (STR : STRING(STRING_LENGTH), ARRAY[0..N] OF ...). Nothing when `name` is no such constant; an
// invalid place when it is one without a value (its declaration's message says why).
std::optional<Place> Codegen::earlyGlobalConstant(const QString &name)
{
    // Each list with the name its messages go under (declareGlobals's).
    std::vector<std::pair<const std::vector<VarSection> *, QString>> lists;
    const ConfigurationDecl *config = nullptr;
    for (const CompilationUnit *u : m_units) {
        lists.emplace_back(&u->globals, QString());
        if (!config && !u->configurations.empty())
            config = &u->configurations.front();
    }
    if (config) {
        lists.emplace_back(&config->globals, config->name);
        for (const ResourceDecl &r : config->resources)
            lists.emplace_back(&r.globals, config->name);
    }
    for (const auto &[sections, owner] : lists) {
        for (const VarSection &section : *sections) {
            if (!section.constant)
                continue;
            for (const VarDecl &v : section.vars) {
                if (v.name.compare(name, Qt::CaseInsensitive) != 0 || v.init.kind != Initializer::Kind::Expression)
                    continue;
                // Evaluated in the global scope, once (evalConstOnce also finds a constant that
                // is defined in terms of itself).
                PouInfo *const pou = std::exchange(m_pou, nullptr);
                const PouInfo *const declaring = std::exchange(m_declaring, nullptr);
                const QString pouName = std::exchange(m_pouName, owner);
                const Type *type = resolveType(v.type);
                bool reported = false;
                const auto value = evalConstOnce(*v.init.value, true, reported);
                const Value typed = value && type ? coerce(*value, type, v.location) : Value{};
                m_pou = pou;
                m_declaring = declaring;
                m_pouName = pouName;
                if (typed.kind != Value::Kind::Constant)
                    return Place {}; // found, and its own message says why it has no value
                Place p;
                p.text = name;
                p.kind = Place::Kind::Constant;
                p.type = type;
                p.constant = typed.constant;
                p.readOnly = true;
                return p;
            }
        }
    }
    return std::nullopt;
}

// A global variable by its declaration (also reached as List.Variable through a global list).
Place Codegen::globalPlace(const GlobalVar &global, const QString &name)
{
    if (global.located && !global.constant)
        return imagePlace(*global.located, global.type, name);
    Place p;
    p.text = name;
    p.type = global.type;
    p.fbPou = global.type->kind == TypeKind::FunctionBlock ? global.type->pou : -1;
    if (global.constant && global.value) {
        p.kind = Place::Kind::Constant;
        p.constant = *global.value;
    } else {
        p.kind = Place::Kind::Direct;
        p.operand = global.offset;
    }
    p.readOnly = global.constant;
    p.readOnlyReason = QCoreApplication::translate("iec::interp::Compiler", "%1 is a constant and cannot be changed.").arg(name);
    return p;
}

Place Codegen::namePlace(const Expr &expr, bool reportUnknown)
{
    const QString &name = expr.text;
    Place p;
    p.text = name;
    if (const qsizetype hash = name.indexOf(QLatin1Char('#')); hash > 0) {
        const Type *t = namedType(name.left(hash), expr.location);
        if (!t)
            return {};
        qsizetype i = -1;
        for (qsizetype k = 0; t->kind == TypeKind::Enum && k < t->enumNames.size(); ++k) {
            if (t->enumNames[k].compare(name.mid(hash + 1), Qt::CaseInsensitive) == 0)
                i = k;
        }
        if (i < 0) {
            error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "%1 has no value %2.").arg(typeName(t), name.mid(hash + 1)));
            return {};
        }
        p.kind = Place::Kind::Constant;
        p.type = t;
        p.constant.kind = ConstValue::Kind::Int;
        p.constant.i = t->enumValues[size_t(i)];
        return p;
    }
    if (m_pou && m_pou->frame) {
        if (const Member *m = m_pou->frame->member(name)) {
            const std::uint32_t base = m_pou->kind == PouKind::Function ? m_pou->frameBase : kInstanceRelative;
            Place frame;
            frame.kind = Place::Kind::Direct;
            frame.operand = base;
            Place result = memberPlace(frame, *m, name);
            if (m->constant && m->init && m->init->kind == Initializer::Kind::Expression && m->type->isElementary()) {
                bool reported = false;
                if (auto value = evalConstOnce(*m->init->value, false, reported)) {
                    const Value typed = coerce(*value, m->type, expr.location);
                    if (typed.kind == Value::Kind::Constant) {
                        result.kind = Place::Kind::Constant;
                        result.constant = typed.constant;
                    }
                } else if (reported) {
                    return {}; // its own message says why it has no value
                }
            }
            return result;
        }
    }
    if (m_pou && m_pou->methodOf >= 0) {
        // In a method: after its own variables, those of its function block (on the instance).
        const PouInfo &owner = m_pous[size_t(m_pou->methodOf)];
        if (const Member *m = owner.frame ? owner.frame->member(name) : nullptr) {
            Place frame;
            frame.kind = Place::Kind::Direct;
            frame.operand = kInstanceRelative;
            return memberPlace(frame, *m, name);
        }
    }
    if ((name.compare(QLatin1String("THIS"), Qt::CaseInsensitive) == 0 || name.compare(QLatin1String("SUPER"), Qt::CaseInsensitive) == 0)
        && currentClass() >= 0)
        return selfPointer(name.compare(QLatin1String("SUPER"), Qt::CaseInsensitive) == 0, expr.location);
    if (m_declaring && m_declaring->ast) {
        // While a POU's variables are laid out, its own CONSTANTs are known by their values. Its own
        // variables hide a global constant of the same name, and have no value yet.
        for (const VarSection &section : m_declaring->ast->sections) {
            if (section.kind == VarKind::External || section.kind == VarKind::Global)
                continue;
            for (const VarDecl &v : section.vars) {
                if (v.name.compare(name, Qt::CaseInsensitive) != 0)
                    continue;
                if (!section.constant) {
                    if (reportUnknown)
                        error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "%1 is a variable, not a constant: it has no value before the program runs.").arg(name),
                              QCoreApplication::translate("iec::interp::Compiler", "declare it in VAR CONSTANT with an initial value"));
                    return {};
                }
                if (v.init.kind != Initializer::Kind::Expression)
                    continue;
                const Type *type = resolveType(v.type);
                bool reported = false;
                const auto value = evalConstOnce(*v.init.value, true, reported);
                const Value typed = value && type ? coerce(*value, type, v.location) : Value{};
                if (typed.kind != Value::Kind::Constant)
                    return {};
                p.kind = Place::Kind::Constant;
                p.type = type;
                p.constant = typed.constant;
                p.readOnly = true;
                return p;
            }
        }
    }
    if (const auto it = m_globals.constFind(key(name)); it != m_globals.constEnd())
        return globalPlace(*it, name);
    if (!m_globalsDeclared) {
        if (std::optional<Place> constant = earlyGlobalConstant(name))
            return *constant;
    }
    if (const auto it = m_enumValues.constFind(key(name)); it != m_enumValues.constEnd()) {
        if (it->ambiguous) {
            error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "%1 is a value of several enumerations.").arg(name),
                  QCoreApplication::translate("iec::interp::Compiler", "write the type in front, e.g. Type#%1").arg(name));
            return {};
        }
        p.kind = Place::Kind::Constant;
        p.type = it->type;
        p.constant.kind = ConstValue::Kind::Int;
        p.constant.i = it->value;
        return p;
    }
    if (const int pou = m_pouIndex.value(key(name), -1); pou >= 0 && m_pous[size_t(pou)].kind == PouKind::Program && m_pous[size_t(pou)].programInstances == 1)
        return programPlace(m_pous[size_t(pou)], name, expr.location); // PRG1.Out (CODESYS)
    if (key(name) == QLatin1String("MAX_STRING_LENGTH")) { // TwinCAT's Tc2_System: T_MaxString's length
        p.kind = Place::Kind::Constant;
        p.type = elem(Elem::UDInt);
        p.constant.kind = ConstValue::Kind::Int;
        p.constant.i = 255;
        p.readOnly = true;
        return p;
    }
    if (reportUnknown && !unusableVar(name)) {
        if (m_pouIndex.contains(key(name)))
            error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "%1 is a POU, not a variable.").arg(name));
        else
            error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "Unknown variable '%1'.").arg(name),
                  QCoreApplication::translate("iec::interp::Compiler", "declare it in a VAR section"));
    }
    return {};
}

bool Codegen::unusableVar(const QString &name) const
{
    return m_unusableVars.contains(QStringLiteral("-1:") + key(name))
        || (m_pou && m_unusableVars.contains(QString::number(m_pou->index) + QLatin1Char(':') + key(name)));
}

Place Codegen::resolvePlace(const Expr &expr, bool reportUnknown, bool derefReferences)
{
    const Place p = resolvePlaceRaw(expr, reportUnknown);
    return derefReferences ? dereferenced(p) : p;
}

Place Codegen::resolvePlaceRaw(const Expr &expr, bool reportUnknown)
{
    if (stackExhausted(expr.location))
        return {};
    switch (expr.kind) {
    case ExprKind::Name:
        return namePlace(expr, reportUnknown);
    case ExprKind::Deref:
        return pointee(expr, reportUnknown);
    case ExprKind::DirectAddress:
        return globalPlace(*directAddressVar(expr.text, expr.location), expr.text);
    case ExprKind::Member: {
        if (const Expr &b = expr.operands[0]; b.kind == ExprKind::Name && namePlace(b, false).kind == Place::Kind::Invalid) {
            // Color.Red, the CODESYS spelling of Color#Red, when Color is an enumeration and no variable.
            if (const Type *t = namedType(b.text, b.location, false); t && t->kind == TypeKind::Enum) {
                Expr qualified = b;
                qualified.text = b.text + QLatin1Char('#') + expr.text;
                return namePlace(qualified, reportUnknown);
            }
            // IO.Valve, a variable of the CODESYS global list IO, when IO is no variable.
            if (const GlobalList *list = globalList(b.text)) {
                const auto global = m_globals.constFind(key(expr.text));
                if (!list->variables.contains(expr.text, Qt::CaseInsensitive) || global == m_globals.constEnd()) {
                    error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "The global list %1 has no variable %2.").arg(b.text, expr.text));
                    return {};
                }
                return globalPlace(*global, b.text + QLatin1Char('.') + expr.text);
            }
        }
        const Place base = resolvePlace(expr.operands[0], reportUnknown);
        if (base.kind == Place::Kind::Invalid)
            return {};
        const QString text = base.text + QLatin1Char('.') + expr.text;
        if (base.type->kind != TypeKind::Struct && base.type->kind != TypeKind::FunctionBlock) {
            error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "%1 is a %2 and has no members.").arg(base.text, typeName(base.type)));
            return {};
        }
        const Member *m = base.type->member(expr.text);
        if (!m) {
            error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "%1 has no member %2.").arg(base.text, expr.text));
            return {};
        }
        if (base.kind == Place::Kind::Constant)
            return {};
        return memberPlace(base, *m, text);
    }
    case ExprKind::BitAccess: {
        Place base = resolvePlace(expr.operands[0], reportUnknown);
        if (base.kind == Place::Kind::Invalid)
            return {};
        const int bit = expr.text.toInt();
        if (base.type->kind != TypeKind::Elementary || !(info(base.type->elem).isBit || info(base.type->elem).isInt)
            || base.type->elem == Elem::Bool || bit >= int(base.type->size * 8)) {
            error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "%1 has no bit %2.").arg(base.text).arg(bit));
            return {};
        }
        if (base.kind == Place::Kind::Constant) {
            Place p = base;
            p.type = boolType();
            p.constant.i = (base.constant.i >> bit) & 1;
            return p;
        }
        Place p = base;
        p.kind = base.kind == Place::Kind::Direct ? Place::Kind::Bit : Place::Kind::IndirectBit;
        p.bit = bit;
        p.text = base.text + QLatin1Char('.') + expr.text;
        p.fbPou = -1;
        // The word's type stays in p.type until read() and store(), which use it for GetBit/SetBit.
        return p;
    }
    case ExprKind::Index: {
        Place base = resolvePlace(expr.operands[0], reportUnknown);
        if (base.kind == Place::Kind::Invalid)
            return {};
        const Type *array = base.type;
        if (array->kind != TypeKind::Array) {
            error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "%1 is not an array.").arg(base.text));
            return {};
        }
        const size_t count = expr.operands.size() - 1;
        if (count != array->dims.size()) {
            error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "%1 has %2 dimension(s) but %3 index(es) are given.").arg(base.text).arg(array->dims.size()).arg(count));
            return {};
        }
        // Stride of each dimension: the product of the later dimensions times the element size.
        std::vector<std::uint32_t> strides(count);
        std::uint32_t stride = array->element->size;
        for (size_t d = count; d-- > 0;) {
            strides[d] = stride;
            stride *= static_cast<std::uint32_t>(array->dims[d].count());
        }
        Place p = base;
        QStringList indexTexts;
        for (size_t d = 0; d < count; ++d) {
            const Expr &indexExpr = expr.operands[d + 1];
            const Dimension &dim = array->dims[d];
            Value index = compileExpr(indexExpr);
            if (!index.valid())
                return {};
            if (index.kind == Value::Kind::Constant && index.constant.kind == ConstValue::Kind::Int) {
                const std::int64_t i = index.constant.i;
                if (i < dim.low || i > dim.high) {
                    error(indexExpr.location, QCoreApplication::translate("iec::interp::Compiler", "The index %1 is outside the range %2..%3 of %4.").arg(i).arg(dim.low).arg(dim.high).arg(base.text));
                    return {};
                }
                const std::uint32_t offset = static_cast<std::uint32_t>(i - dim.low) * strides[d];
                if (p.kind == Place::Kind::Direct) {
                    p.operand += offset;
                } else if (offset != 0) {
                    const std::uint32_t t = temp(elem(Elem::UDInt));
                    instr(op::PtrAdd, t, p.operand, 0, offset);
                    p.operand = t;
                }
                indexTexts << QString::number(i);
                continue;
            }
            if (!isIntegral(index.type) && index.type->kind != TypeKind::Enum) {
                error(indexExpr.location, QCoreApplication::translate("iec::interp::Compiler", "An array index must be an integer, not %1.").arg(typeName(index.type)));
                return {};
            }
            IndexDescriptor descriptor;
            descriptor.low = dim.low;
            descriptor.count = dim.count();
            descriptor.stride = strides[d];
            descriptor.indexType = vtOf(*index.type);
            if (descriptor.indexType == VT::U64)
                descriptor.indexType = VT::I64;
            m_module->indexDescriptors.push_back(descriptor);
            const auto descriptorIndex = static_cast<std::uint16_t>(m_module->indexDescriptors.size() - 1);
            const std::uint32_t t = temp(elem(Elem::UDInt));
            instr(p.kind == Place::Kind::Direct ? op::Index : op::IndexPtr, t, p.operand, materialize(index), 0, descriptorIndex);
            p.kind = Place::Kind::Indirect;
            p.operand = t;
            indexTexts << QStringLiteral("...");
        }
        p.type = array->element;
        p.fbPou = array->element->kind == TypeKind::FunctionBlock ? array->element->pou : -1;
        p.text = base.text + QLatin1Char('[') + indexTexts.join(QLatin1Char(',')) + QLatin1Char(']');
        return p;
    }
    default:
        error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "This is not a variable."));
        return {};
    }
}

std::optional<std::uint16_t> Codegen::fusedIndexOp(const Place &p, bool load) const
{
    // The address of an element was just computed with op::Index into a temporary used only
    // here: the element is read or written with one LoadIdx/StoreIdx instead.
    if (p.kind != Place::Kind::Indirect || !lastWrites(p.operand) || m_module->code.back().op != op::Index
        || p.type->kind == TypeKind::String)
        return std::nullopt;
    switch (p.type->size) {
    case 1: return load ? op::LoadIdx1 : op::StoreIdx1;
    case 2: return load ? op::LoadIdx2 : op::StoreIdx2;
    case 4: return load ? op::LoadIdx4 : op::StoreIdx4;
    case 8: return load ? op::LoadIdx8 : op::StoreIdx8;
    default: return std::nullopt;
    }
}

Value Codegen::read(const Place &p, bool mayFuse)
{
    switch (p.kind) {
    case Place::Kind::Invalid:
        return {};
    case Place::Kind::Constant:
        return constantValue(p.type, p.constant);
    case Place::Kind::Direct:
        return operandValue(p.operand, p.type);
    case Place::Kind::Indirect: {
        const std::uint32_t t = temp(p.type);
        if (const auto fused = mayFuse ? fusedIndexOp(p, true) : std::nullopt) {
            std::vector<Instr> &code = m_module->code;
            Instr &index = code.back();
            // a[i * n + k]: the index computed by a MulAdd just before joins the load.
            const auto at = static_cast<std::uint32_t>(code.size() - 1);
            const VT indexType = m_module->indexDescriptors[index.aux].indexType;
            if (at >= m_pouCodeStart + 1 && m_lastTarget != at && (indexType == VT::I16 || indexType == VT::I32 || indexType == VT::I64)) {
                const Instr &mulAdd = code[at - 1];
                if (mulAdd.op == typedOp(op::MulAdd, indexType) && mulAdd.a == index.c && (mulAdd.a & kInstanceRelative) == 0
                    && (mulAdd.a & kTempMarker) != 0) {
                    const std::uint16_t ma = static_cast<std::uint16_t>(op::LoadIdxMA1 + (*fused - op::LoadIdx1));
                    Instr joined{ma, index.aux, t, index.b, mulAdd.b, mulAdd.c};
                    joined.e = mulAdd.d;
                    code.pop_back();
                    code.back() = joined;
                    return operandValue(t, p.type);
                }
            }
            index = {*fused, index.aux, t, index.b, index.c, 0};
            return operandValue(t, p.type);
        }
        static constexpr std::uint16_t loads[] = {op::Nop, op::Load1, op::Load2, op::Nop, op::Load4, op::Nop, op::Nop, op::Nop, op::Load8};
        if (p.type->size <= 8 && loads[p.type->size] != op::Nop && p.type->kind != TypeKind::String)
            instr(loads[p.type->size], t, p.operand);
        else
            instr(op::LoadN, t, p.operand, 0, p.type->size);
        // A string reached through an address (VAR_IN_OUT, a pointer) may be longer than its
        // declared type: the copy is of the declared size, so its capacity is the declared one.
        if (p.type->kind == TypeKind::String)
            instr(op::Mov2, t, constantOperand(p.type, ConstValue {}));
        return operandValue(t, p.type);
    }
    case Place::Kind::Bit:
    case Place::Kind::IndirectBit: {
        Place word = p;
        word.kind = p.kind == Place::Kind::Bit ? Place::Kind::Direct : Place::Kind::Indirect;
        const Value w = read(word);
        const std::uint32_t t = temp(boolType());
        instr(typedOp(op::GetBit, vtOf(*p.type)), t, w.operand, 0, static_cast<std::uint32_t>(p.bit));
        return operandValue(t, boolType());
    }
    }
    return {};
}

bool Codegen::checkSubrange(const Value &v, const Type *type, SourceLocation at)
{
    if (!type || !type->subrange)
        return true;
    const auto [low, high] = *type->subrange;
    if (v.kind == Value::Kind::Constant) {
        if (v.constant.kind == ConstValue::Kind::Int && (v.constant.i < low || v.constant.i > high)) {
            error(at, QCoreApplication::translate("iec::interp::Compiler", "The value %1 is outside the range %2..%3 of %4.")
                          .arg(v.constant.i).arg(low).arg(high).arg(typeName(type)));
            return false;
        }
        return true;
    }
    // Checked at run time like an array index: the same descriptor, and a fault with POU and line.
    IndexDescriptor descriptor;
    descriptor.low = low;
    descriptor.count = high - low + 1;
    descriptor.indexType = vtOf(*type) == VT::U64 ? VT::I64 : vtOf(*type);
    m_module->indexDescriptors.push_back(descriptor);
    instr(op::CheckRange, 0, materialize(v), 0, 0, static_cast<std::uint16_t>(m_module->indexDescriptors.size() - 1));
    return true;
}

void Codegen::store(const Place &p, Value value, SourceLocation at)
{
    if (p.kind == Place::Kind::Invalid || !value.valid())
        return;
    if (p.kind == Place::Kind::Constant || p.readOnly) {
        error(at, p.readOnlyReason.isEmpty() ? QCoreApplication::translate("iec::interp::Compiler", "%1 is a constant and cannot be changed.").arg(p.text) : p.readOnlyReason);
        return;
    }
    if (p.type->kind == TypeKind::FunctionBlock) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "A function block instance cannot be assigned; call it instead."));
        return;
    }
    const bool bit = p.kind == Place::Kind::Bit || p.kind == Place::Kind::IndirectBit;
    const Value v = coerce(value, bit ? boolType() : p.type, at, p.text);
    if (!v.valid() || (!bit && !checkSubrange(v, p.type, at)))
        return;
    if (bit && p.type->subrange) {
        // A bit of a subrange variable: the changed word is checked before it is stored.
        Place word = p;
        word.kind = p.kind == Place::Kind::Bit ? Place::Kind::Direct : Place::Kind::Indirect;
        word.text = p.text.section(QLatin1Char('.'), 0, -2);
        const std::uint32_t changed = temp(p.type);
        emitMove(changed, read(word, false).operand, p.type);
        instr(typedOp(op::SetBit, vtOf(*p.type)), changed, materialize(v), 0, static_cast<std::uint32_t>(p.bit));
        store(word, operandValue(changed, p.type), at);
        return;
    }
    if (p.kind == Place::Kind::Direct) {
        if (v.kind == Value::Kind::Operand && v.operand == p.operand)
            return;
        emitMove(p.operand, materialize(v), p.type);
        return;
    }
    if (p.kind == Place::Kind::Bit) {
        instr(typedOp(op::SetBit, vtOf(*p.type)), p.operand, materialize(v), 0, static_cast<std::uint32_t>(p.bit));
        return;
    }
    // Through an address: strings and bits are read, changed and written back so that the
    // capacity check and the other bits stay right.
    static constexpr std::uint16_t stores[] = {op::Nop, op::Store1, op::Store2, op::Nop, op::Store4, op::Nop, op::Nop, op::Nop, op::Store8};
    if (p.kind == Place::Kind::IndirectBit || p.type->kind == TypeKind::String) {
        Place direct = p;
        direct.kind = Place::Kind::Indirect;
        const Value current = read(direct, false); // p.operand is needed for the store below
        if (p.kind == Place::Kind::IndirectBit)
            instr(typedOp(op::SetBit, vtOf(*p.type)), current.operand, materialize(v), 0, static_cast<std::uint32_t>(p.bit));
        else
            instr(op::StrMov, current.operand, materialize(v), 0, 0, p.type->wide ? 3 : 0);
        if (p.type->kind == TypeKind::String) {
            // The characters only: the string's own capacity stays (it may be larger than the
            // declared one the copy had).
            constexpr std::uint32_t header = 4;
            instr(op::StoreN, offsetAddress(p.operand, header), current.operand + header, 0, p.type->size - header);
            return;
        }
        const std::uint16_t storeOp = p.type->size <= 8 && stores[p.type->size] != op::Nop ? stores[p.type->size] : std::uint16_t(op::StoreN);
        instr(storeOp, p.operand, current.operand, 0, p.type->size);
        return;
    }
    const std::uint32_t source = materialize(v);
    if (const auto fused = fusedIndexOp(p, false)) {
        Instr &index = m_module->code.back();
        index = {*fused, index.aux, index.b, 0, index.c, source};
        return;
    }
    if (p.type->size <= 8 && stores[p.type->size] != op::Nop)
        instr(stores[p.type->size], p.operand, source);
    else
        instr(op::StoreN, p.operand, source, 0, p.type->size);
}

// ---------------------------------------------------------------------------- operators

const Type *Codegen::commonType(const Type *a, const Type *b) const
{
    if (!a || !b)
        return nullptr;
    if (a == b)
        return a;
    if (a->kind != TypeKind::Elementary || b->kind != TypeKind::Elementary) {
        if (a->kind == TypeKind::Enum && b->kind == TypeKind::Enum && a->name.compare(b->name, Qt::CaseInsensitive) == 0)
            return a;
        if (a->kind == TypeKind::String && b->kind == TypeKind::String && a->wide == b->wide)
            return a->capacity >= b->capacity ? a : b;
        return nullptr;
    }
    if (a->elem == b->elem)
        return elem(a->elem);
    // The smallest type both widen to, trying types from small to large.
    static constexpr Elem order[] = {Elem::SInt, Elem::USInt, Elem::Int, Elem::UInt, Elem::DInt, Elem::UDInt, Elem::LInt,
                                     Elem::ULInt, Elem::Real, Elem::LReal, Elem::Byte, Elem::Word, Elem::DWord, Elem::LWord,
                                     Elem::Time, Elem::LTime, Elem::Date, Elem::LDate, Elem::Tod, Elem::LTod, Elem::Dt, Elem::Ldt,
                                     Elem::Char, Elem::WChar};
    for (const Elem e : order) {
        if (implicitlyConvertible(a->elem, e) && implicitlyConvertible(b->elem, e))
            return elem(e);
    }
    return nullptr;
}

// Two integers or bit strings IEC gives no common type (WORD and INT, LINT and ULINT): CODESYS
// computes bit strings as the unsigned integer of their width, then in the wider type.
const Type *Codegen::integerCommonType(const Type *a, const Type *b) const
{
    const auto integerLike = [](const Type *t) { return t && t->kind == TypeKind::Elementary && t->elem != Elem::Bool && (info(t->elem).isInt || info(t->elem).isBit); };
    if (!integerLike(a) || !integerLike(b))
        return nullptr;
    const auto asInteger = [this](const Type *t) -> const Type * {
        if (!isBits(t))
            return t;
        static constexpr Elem unsignedOfSize[] = {Elem::USInt, Elem::USInt, Elem::UInt, Elem::UInt, Elem::UDInt, Elem::UDInt, Elem::UDInt, Elem::UDInt, Elem::ULInt};
        return elem(unsignedOfSize[t->size]);
    };
    if (const Type *t = commonType(asInteger(a), asInteger(b)))
        return t;
    return a->size >= b->size ? (a->size == b->size && info(b->elem).isUnsigned ? a : a->size > b->size ? a : b) : b;
}

Value Codegen::binary(const QString &opText, Value left, Value right, SourceLocation at, const Place *destination)
{
    // Two values from literals alone give one too (computed as LINT or LREAL).
    const bool fromLiterals = left.untyped && right.untyped;
    Value result = binaryTyped(opText, left, right, at, destination);
    if (fromLiterals && result.kind == Value::Kind::Operand && result.type != boolType())
        result.untyped = true;
    if (fromLiterals && result.kind == Value::Kind::Constant && result.untyped)
        result.bitPattern = left.bitPattern || right.bitPattern;
    return result;
}

Value Codegen::binaryTyped(const QString &opText, Value left, Value right, SourceLocation at, const Place *destination)
{
    if (!left.valid() || !right.valid())
        return {};
    if (const auto addresses = pointerArithmetic(opText, left, right, at))
        return *addresses;
    // Exponentiation: the result is REAL or LREAL, the exponent any number.
    if (opText == QLatin1String("**")) {
        if (!isNumeric(left.type) || !isNumeric(right.type)) {
            error(at, QCoreApplication::translate("iec::interp::Compiler", "'**' needs numbers, not %1 and %2.").arg(typeName(left.type), typeName(right.type)));
            return {};
        }
        if (left.kind == Value::Kind::Constant && right.kind == Value::Kind::Constant) {
            ConstValue c;
            c.kind = ConstValue::Kind::Real;
            c.r = std::pow(asReal(left.constant), asReal(right.constant));
            const bool untyped = left.untyped;
            return constantValue(untyped ? elem(Elem::LReal) : (left.type->elem == Elem::Real ? elem(Elem::Real) : elem(Elem::LReal)), c, untyped);
        }
        const Type *result = left.untyped ? elem(Elem::LReal) : isReal(left.type) ? left.type
                             : implicitlyConvertible(left.type->elem, Elem::Real) ? elem(Elem::Real) : elem(Elem::LReal);
        const Value base = coerce(left, result, at);
        const Value exponent = right.untyped ? coerce(right, elem(Elem::LReal), at) : convertExplicit(right, elem(Elem::LReal), at);
        if (!base.valid() || !exponent.valid())
            return {};
        const std::uint32_t out = destination && destination->kind == Place::Kind::Direct && destination->type == result ? destination->operand : temp(result);
        instr(typedOp(op::Expt, vtOf(*result)), out, materialize(base), materialize(exponent));
        return operandValue(out, result);
    }
    const OperatorInfo *oi = operatorInfo(opText);
    if (!oi)
        return {};

    // Times and dates.
    if (isTimeLike(left.type) || isTimeLike(right.type)) {
        const bool scaling = (opText == QLatin1String("*") || opText == QLatin1String("/")) && isTimeLike(left.type) && (isNumeric(right.type));
        if (scaling) {
            const Type *timeType = left.type;
            if (isReal(right.type) || (right.untyped && right.constant.kind == ConstValue::Kind::Real)) {
                Value nanoseconds = left;
                nanoseconds.type = elem(Elem::LInt);
                Value asReal = convertExplicit(nanoseconds, elem(Elem::LReal), at);
                asReal = binary(opText, asReal, coerce(right, elem(Elem::LReal), at), at);
                asReal.type = elem(Elem::LReal);
                Value ns = convertExplicit(asReal, elem(Elem::LInt), at);
                ns.type = timeType;
                return ns;
            }
            Value asInt = left;
            asInt.type = elem(Elem::LInt);
            Value result = binary(opText, asInt, right.untyped ? right : convertExplicit(right, elem(Elem::LInt), at), at);
            result.type = timeType;
            return result;
        }
        if (!oi->comparison) {
            const Elem l = shortForm(left.type->elem), r = shortForm(right.type->elem);
            for (const TimeRule &rule : kTimeRules) {
                if (opText == QLatin1String(rule.op) && rule.left == l && rule.right == r && left.type->kind == TypeKind::Elementary
                    && right.type->kind == TypeKind::Elementary) {
                    const bool isLong = left.type->elem != l || right.type->elem != r;
                    const Type *result = elem(isLong ? longForm(rule.result) : rule.result);
                    Value a = left, b = right;
                    a.type = b.type = elem(Elem::LInt);
                    Value sum = binary(opText, a, b, at, nullptr);
                    sum.type = result;
                    return sum;
                }
            }
            error(at, QCoreApplication::translate("iec::interp::Compiler", "'%1' cannot combine %2 and %3.").arg(opText, typeName(left.type), typeName(right.type)));
            return {};
        }
    }

    // The type both operands are brought to.
    const Type *type = nullptr;
    if (left.untyped && right.untyped) {
        const bool real = realLiteral(left) || realLiteral(right);
        type = real ? elem(Elem::LReal) : elem(Elem::LInt);
    } else if (left.untyped || right.untyped) {
        const Value &literal = left.untyped ? left : right;
        const Type *other = left.untyped ? right.type : left.type;
        type = other;
        if (realLiteral(literal) && isIntegral(other))
            type = implicitlyConvertible(other->elem, Elem::Real) ? elem(Elem::Real) : elem(Elem::LReal);
    } else {
        type = commonType(left.type, right.type);
        if (!type)
            type = integerCommonType(left.type, right.type);
    }
    if (!type) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "'%1' cannot combine %2 and %3.").arg(opText, typeName(left.type), typeName(right.type)),
              conversionHint(right.type, left.type));
        return {};
    }
    // What each operator accepts.
    const bool arithmetic = oi->family == op::Add || oi->family == op::Sub || oi->family == op::Mul || oi->family == op::Div;
    const bool logic = oi->family == op::And || oi->family == op::Or || oi->family == op::Xor;
    const bool ordering = oi->family == op::Lt || oi->family == op::Le || oi->family == op::Gt || oi->family == op::Ge;
    // CODESYS also computes with bit strings (w + 1, as the unsigned integer of their width)
    // and combines integers bit by bit (i AND 16#FF).
    const bool bitString = isBits(type) && type->elem != Elem::Bool;
    bool allowed = true;
    if (arithmetic)
        allowed = isNumeric(type) || bitString;
    else if (oi->family == op::Mod)
        allowed = isIntegral(type) || bitString;
    else if (logic)
        allowed = isBits(type) || isIntegral(type) || (left.untyped && right.untyped);
    else if (ordering)
        allowed = type->kind != TypeKind::Enum && (type->isElementary() || isString(type));
    else
        allowed = type->isElementary() || isString(type);
    if (!allowed) {
        const QString kind = logic ? QCoreApplication::translate("iec::interp::Compiler", "BOOL or a bit string (BYTE, WORD, ...)")
                             : oi->family == op::Mod ? QCoreApplication::translate("iec::interp::Compiler", "integers")
                                                     : QCoreApplication::translate("iec::interp::Compiler", "numbers");
        error(at, QCoreApplication::translate("iec::interp::Compiler", "'%1' needs %2, not %3.").arg(opText, kind, typeName(type)));
        return {};
    }
    const Type *resultType = oi->comparison ? boolType() : type;

    // Both known: fold.
    if (left.kind == Value::Kind::Constant && right.kind == Value::Kind::Constant && !isString(type)) {
        const Value a = left.untyped && right.untyped ? left : coerce(left, type, at);
        const Value b = left.untyped && right.untyped ? right : coerce(right, type, at);
        if (!a.valid() || !b.valid())
            return {};
        ConstValue c;
        c.kind = ConstValue::Kind::Int;
        if (isReal(type)) {
            const double x = asReal(a.constant), y = asReal(b.constant);
            switch (oi->family) {
            case op::Add: c.r = x + y; break;
            case op::Sub: c.r = x - y; break;
            case op::Mul: c.r = x * y; break;
            case op::Div: c.r = x / y; break;
            case op::Eq: c.i = x == y; break;
            case op::Ne: c.i = x != y; break;
            case op::Lt: c.i = x < y; break;
            case op::Le: c.i = x <= y; break;
            case op::Gt: c.i = x > y; break;
            case op::Ge: c.i = x >= y; break;
            default: break;
            }
            if (!oi->comparison) {
                c.kind = ConstValue::Kind::Real;
                if (type->elem == Elem::Real)
                    c.r = static_cast<float>(c.r);
            }
        } else {
            const std::int64_t x = a.constant.i, y = b.constant.i;
            const bool isUnsigned = type->kind == TypeKind::Elementary && info(type->elem).isUnsigned;
            const auto ux = static_cast<std::uint64_t>(x), uy = static_cast<std::uint64_t>(y);
            if ((oi->family == op::Div || oi->family == op::Mod) && y == 0) {
                error(at, QCoreApplication::translate("iec::interp::Compiler", "Division by zero."));
                return {};
            }
            switch (oi->family) {
            case op::Add: c.i = static_cast<std::int64_t>(ux + uy); break;
            case op::Sub: c.i = static_cast<std::int64_t>(ux - uy); break;
            case op::Mul: c.i = static_cast<std::int64_t>(ux * uy); break;
            case op::Div: c.i = isUnsigned ? static_cast<std::int64_t>(ux / uy) : (y == -1 ? static_cast<std::int64_t>(0 - ux) : x / y); break;
            case op::Mod: c.i = isUnsigned ? static_cast<std::int64_t>(ux % uy) : (y == -1 ? 0 : x % y); break;
            case op::And: c.i = x & y; break;
            case op::Or: c.i = x | y; break;
            case op::Xor: c.i = x ^ y; break;
            case op::Eq: c.i = x == y; break;
            case op::Ne: c.i = x != y; break;
            case op::Lt: c.i = isUnsigned ? ux < uy : x < y; break;
            case op::Le: c.i = isUnsigned ? ux <= uy : x <= y; break;
            case op::Gt: c.i = isUnsigned ? ux > uy : x > y; break;
            case op::Ge: c.i = isUnsigned ? ux >= uy : x >= y; break;
            default: break;
            }
            if (!oi->comparison && !(left.untyped && right.untyped) && type->kind == TypeKind::Elementary)
                c.i = wrapTo(c.i, type->elem);
        }
        const bool untyped = left.untyped && right.untyped && !oi->comparison;
        return constantValue(resultType, c, untyped);
    }

    const Value a = coerce(left, type, at);
    const Value b = coerce(right, type, at);
    if (!a.valid() || !b.valid())
        return {};
    if (isString(type)) {
        // Strings compare through StrCmp (-1, 0, 1) and an integer comparison with 0.
        const Type *dint = elem(Elem::DInt);
        const std::uint32_t cmp = temp(dint);
        instr(op::StrCmp, cmp, materialize(a), materialize(b), 0, type->wide ? 1 : 0);
        const std::uint32_t out = destination && destination->kind == Place::Kind::Direct && destination->type == resultType ? destination->operand : temp(resultType);
        instr(typedOp(oi->family, VT::I32), out, cmp, constantOperand(dint, ConstValue{ConstValue::Kind::Int, 0, false, 0, {}, false}));
        return operandValue(out, resultType);
    }
    const VT vt = vtOf(*type);
    const std::uint32_t out = destination && destination->kind == Place::Kind::Direct && destination->type == resultType
        ? destination->operand
        : temp(resultType);
    // x AND NOT y, the normally closed contact of every ladder rung: one instruction.
    if (oi->family == op::And && type->elem == Elem::Bool && type->kind == TypeKind::Elementary) {
        for (const bool rightNegated : {true, false}) {
            const Value &negated = rightNegated ? b : a;
            const Value &other = rightNegated ? a : b;
            if (negated.kind == Value::Kind::Operand && lastWrites(negated.operand) && m_module->code.back().op == op::BoolNot
                && !(other.kind == Value::Kind::Operand && other.operand == negated.operand)) {
                const std::uint32_t source = m_module->code.back().b;
                m_module->code.pop_back();
                instr(op::BoolAndNot, out, materialize(other), source);
                return operandValue(out, resultType);
            }
        }
    }
    // (x AND y) OR z and (x OR y) AND z, the series and parallel contacts of a rung: the inner
    // operation just computed into a temporary joins the outer one.
    if ((oi->family == op::Or || oi->family == op::And) && type->elem == Elem::Bool && type->kind == TypeKind::Elementary) {
        const std::uint16_t inner = typedOp(oi->family == op::Or ? op::And : op::Or, VT::U8);
        for (const bool rightInner : {true, false}) {
            const Value &joined = rightInner ? b : a;
            const Value &other = rightInner ? a : b;
            if (joined.kind == Value::Kind::Operand && lastWrites(joined.operand) && m_module->code.back().op == inner
                && !(other.kind == Value::Kind::Operand && other.operand == joined.operand)) {
                const Instr last = m_module->code.back();
                m_module->code.pop_back();
                // (a AND NOT b) OR (c AND d), the classic rung: one instruction.
                if (oi->family == op::Or && other.kind == Value::Kind::Operand && lastWrites(other.operand)
                    && m_module->code.back().op == op::BoolAndNot && last.b != other.operand && last.c != other.operand) {
                    const Instr andNot = m_module->code.back();
                    m_module->code.pop_back();
                    instr(op::BoolAndNotOrAnd, out, andNot.b, andNot.c, last.b);
                    Instr &fused = m_module->code.back();
                    fused.e = last.c;
                    if ((fused.a & fused.b & fused.c & fused.d & fused.e & kInstanceRelative) != 0) {
                        fused.op = op::BoolAndNotOrAndRel;
                        for (std::uint32_t *x : {&fused.a, &fused.b, &fused.c, &fused.d, &fused.e})
                            *x &= kOffsetMask;
                    }
                    return operandValue(out, resultType);
                }
                instr(oi->family == op::Or ? op::BoolAndOr : op::BoolOrAnd, out, last.b, last.c, materialize(other));
                return operandValue(out, resultType);
            }
        }
    }
    // b * c + d, an element's index i * n + j or a sum of products: one MulAdd.
    if (oi->family == op::Add && type->kind == TypeKind::Elementary && (isIntegral(type) || isReal(type))) {
        for (const bool rightProduct : {true, false}) {
            const Value &product = rightProduct ? b : a;
            const Value &other = rightProduct ? a : b;
            if (product.kind == Value::Kind::Operand && lastWrites(product.operand) && m_module->code.back().op == typedOp(op::Mul, vt)
                && !(other.kind == Value::Kind::Operand && other.operand == product.operand)) {
                const Instr last = m_module->code.back();
                m_module->code.pop_back();
                instr(typedOp(op::MulAdd, vt), out, last.b, last.c, materialize(other));
                return operandValue(out, resultType);
            }
        }
    }
    instr(typedOp(oi->family, vt), out, materialize(a), materialize(b));
    return operandValue(out, resultType);
}

Value Codegen::unary(const QString &opText, Value v, SourceLocation at, const Place *destination)
{
    if (!v.valid())
        return {};
    if (opText == QLatin1String("+"))
        return v;
    const bool negate = opText == QLatin1String("-");
    const Type *t = v.type;
    if (negate) {
        const bool signedNumber = (isIntegral(t) && !info(t->elem).isUnsigned) || isReal(t) || (isTimeLike(t) && shortForm(t->elem) == Elem::Time);
        if (!v.untyped && !signedNumber) {
            error(at, QCoreApplication::translate("iec::interp::Compiler", "A %1 cannot be negated.").arg(typeName(t)));
            return {};
        }
        if (v.kind == Value::Kind::Constant) {
            ConstValue c = v.constant;
            if (c.kind == ConstValue::Kind::Real)
                c.r = -c.r;
            else
                c.i = v.untyped ? static_cast<std::int64_t>(0 - static_cast<std::uint64_t>(c.i)) : wrapTo(static_cast<std::int64_t>(0 - static_cast<std::uint64_t>(c.i)), t->elem);
            c.bigUnsigned = false;
            return constantValue(t, c, v.untyped);
        }
        const std::uint32_t out = destination && destination->kind == Place::Kind::Direct && destination->type == t && !v.untyped ? destination->operand : temp(t);
        instr(typedOp(op::Neg, vtOf(*t)), out, v.operand);
        Value negated = operandValue(out, t);
        negated.untyped = v.untyped;
        if (v.literalRange && v.literalRange->first > INT64_MIN)
            negated.literalRange = std::make_pair(-v.literalRange->second, -v.literalRange->first);
        return negated;
    }
    // NOT
    // NOT 16#0F into a BYTE: an untyped literal takes the bit string type it is assigned to, or
    // DWORD, the type CODESYS gives such a constant.
    // Elsewhere it stays a literal, a bit pattern that takes the width of the bit string it is
    // combined with: w OR NOT 16#0159 with w : WORD is w OR 16#FEA6.
    if (v.untyped && v.kind == Value::Kind::Constant && v.constant.kind == ConstValue::Kind::Int && (v.constant.i >= 0 || v.bitPattern)) {
        const bool toBits = destination && destination->type && isBits(destination->type) && destination->type->elem != Elem::Bool;
        if (!toBits && !v.constant.bigUnsigned) {
            ConstValue c = v.constant;
            c.i = ~c.i;
            Value pattern = constantValue(elem(Elem::LInt), c, true);
            pattern.bitPattern = true;
            return pattern;
        }
        const Type *bits = toBits ? destination->type : elem(Elem::DWord);
        const ElemInfo &e = info(bits->elem);
        if (e.size >= 8 || v.bitPattern || v.constant.i < (std::int64_t(1) << (e.size * 8)))
            t = bits;
    }
    if (!isBits(t) && !isIntegral(t)) { // CODESYS: NOT of an integer inverts its bits
        error(at, QCoreApplication::translate("iec::interp::Compiler", "NOT needs BOOL or a bit string (BYTE, WORD, ...), not %1.").arg(v.untyped ? QCoreApplication::translate("iec::interp::Compiler", "an integer literal") : typeName(t)));
        return {};
    }
    if (v.kind == Value::Kind::Constant) {
        ConstValue c = v.constant;
        c.i = t->elem == Elem::Bool ? (c.i ^ 1) : wrapTo(~c.i, t->elem);
        return constantValue(t, c);
    }
    const std::uint32_t out = destination && destination->kind == Place::Kind::Direct && destination->type == t ? destination->operand : temp(t);
    if (t->elem == Elem::Bool)
        instr(op::BoolNot, out, v.operand);
    else
        instr(typedOp(op::Not, vtOf(*t)), out, v.operand);
    return operandValue(out, t);
}

// ---------------------------------------------------------------------------- expressions

namespace {

bool isShortCircuit(const Expr &expr)
{
    return expr.kind == ExprKind::Binary
        && (expr.text == QLatin1String("AND_THEN") || expr.text == QLatin1String("OR_ELSE"));
}

} // namespace

// a AND_THEN b, a OR_ELSE b (CODESYS): b is evaluated only when a does not decide the result.
Value Codegen::shortCircuit(const Expr &expr)
{
    const bool andThen = expr.text == QLatin1String("AND_THEN");
    const QString name = andThen ? QStringLiteral("AND_THEN") : QStringLiteral("OR_ELSE");
    const auto operand = [&](const Expr &e) {
        const Value v = compileExpr(e);
        if (v.valid() && v.type != boolType()) {
            error(e.location, QCoreApplication::translate("iec::interp::Compiler", "%1 combines BOOL values, not %2.").arg(name, typeName(v.type)));
            return Value{};
        }
        return v;
    };
    const Value left = operand(expr.operands[0]);
    if (!left.valid())
        return {};
    if (left.kind == Value::Kind::Constant) {
        if ((left.constant.i != 0) != andThen)
            return left; // FALSE AND_THEN ..., TRUE OR_ELSE ...
        return operand(expr.operands[1]);
    }
    const std::uint32_t out = temp(boolType());
    emitMove(out, left.operand, boolType());
    const std::uint32_t decided = instr(andThen ? op::Jz : op::Jnz, 0, out);
    const Value right = operand(expr.operands[1]);
    if (!right.valid())
        return {};
    emitMove(out, materialize(right), boolType());
    patchJump(decided, here());
    return operandValue(out, boolType());
}

Value Codegen::compileExpr(const Expr &expr, const Place *destination)
{
    if (stackExhausted(expr.location))
        return {};
    switch (expr.kind) {
    case ExprKind::Literal: {
        const Type *type = nullptr;
        bool untyped = false;
        const auto value = literalValue(expr, &type, &untyped);
        if (!value || !type) {
            error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "'%1' is not a valid literal.").arg(expr.text));
            return {};
        }
        if (!untyped && !typedLiteralFits(*value, type, expr))
            return {};
        return constantValue(type, *value, untyped);
    }
    case ExprKind::Name:
    case ExprKind::Member:
    case ExprKind::Index:
    case ExprKind::BitAccess:
    case ExprKind::Deref:
    case ExprKind::DirectAddress: {
        if (expr.kind == ExprKind::Member || (expr.kind == ExprKind::Name && currentClass() >= 0)) {
            if (auto property = propertyRead(expr)) // obj.P, or P inside its block
                return *property;
        }
        const Place p = resolvePlace(expr);
        if (p.kind == Place::Kind::Invalid)
            return {};
        if (p.kind == Place::Kind::Indirect && p.type->kind == TypeKind::FunctionBlock) {
            // An instance behind an address stays where it is (only an interface is made of it).
            Value v = operandValue(p.operand, p.type);
            v.instanceAddress = true;
            return v;
        }
        return read(p);
    }
    case ExprKind::Unary:
        return unary(expr.text, compileExpr(expr.operands[0]), expr.location, destination);
    case ExprKind::Binary: {
        if (isShortCircuit(expr))
            return shortCircuit(expr);
        // 1 + 2 + ... + n leans left: its left operands are walked with a loop, so that only
        // nesting the parser limits recurses, never the length of a chain.
        std::vector<const Expr *> chain;
        const Expr *leftmost = &expr;
        while (leftmost->kind == ExprKind::Binary && !isShortCircuit(*leftmost)) {
            chain.push_back(leftmost);
            leftmost = &leftmost->operands[0];
        }
        Value left = compileExpr(*leftmost);
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            const Expr &node = **it;
            const Value right = compileExpr(node.operands[1]);
            left = binary(node.text, left, right, node.location, &node == &expr ? destination : nullptr);
        }
        return left;
    }
    case ExprKind::Call:
        return compileCall(expr, false, destination);
    case ExprKind::Error:
        return {};
    }
    return {};
}

} // namespace iec::interp::detail
