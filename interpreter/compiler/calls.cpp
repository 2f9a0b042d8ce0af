// Calls of functions, function blocks and standard functions.
#include "interpreter/compiler/codegen.h"

#include <QCoreApplication>

#include <algorithm>

namespace iec::interp::detail {

using namespace ast;

std::vector<Codegen::Argument> Codegen::arguments(const std::vector<CallArg> &args)
{
    std::vector<Argument> out;
    for (const CallArg &a : args) {
        Argument arg;
        arg.name = a.name;
        arg.isOutput = a.isOutput;
        arg.negated = a.negatedOutput;
        arg.expr = &a.value;
        arg.location = a.value.location;
        out.push_back(arg);
    }
    return out;
}

std::optional<NativeBlock> Codegen::nativeBlock(const Type *fbType) const
{
    if (!m_options.nativeStandardBlocks || fbType->pou < 0 || !m_pous[size_t(fbType->pou)].fromLibrary)
        return std::nullopt;
    static const std::pair<const char *, NativeBlock> blocks[] = {{"TON", NativeBlock::Ton}, {"TOF", NativeBlock::Tof}, {"TP", NativeBlock::Tp}};
    for (const auto &[name, block] : blocks) {
        if (fbType->name != QLatin1String(name))
            continue;
        // The C++ version reads the instance with the layout of the ST declaration; use it only
        // when the layout is the one it expects.
        static const std::pair<const char *, std::uint32_t> layout[] = {{"IN", 0}, {"PT", 8}, {"Q", 16}, {"ET", 24}, {"START", 32}};
        for (const auto &[member, offset] : layout) {
            const Member *m = fbType->member(QLatin1String(member));
            if (!m || m->offset != offset)
                return std::nullopt;
        }
        if (fbType->members.size() != 6 || fbType->members[5].offset != 40 || fbType->members[5].type->elem != Elem::Bool)
            return std::nullopt;
        return block;
    }
    return std::nullopt;
}

void Codegen::noteCall(int callee, SourceLocation at)
{
    if (m_pou)
        m_calls[m_pou->index].push_back({callee, at});
}

namespace {

// Every value of `inner` lies in the subrange of `outer` (or `outer` has none).
bool subrangeWithin(const Type *inner, const Type *outer)
{
    if (!outer->subrange)
        return true;
    return inner->subrange && inner->subrange->first >= outer->subrange->first && inner->subrange->second <= outer->subrange->second;
}

} // namespace

// Elements and members are written by the callee without knowing the caller's subrange, so a
// subrange must be the same on both sides (or absent on both).
bool Codegen::sameStoredType(const Type *parameter, const Type *variable) const
{
    return sameInOutType(parameter, variable) && (parameter == variable || parameter->subrange == variable->subrange);
}

bool Codegen::sameInOutType(const Type *parameter, const Type *variable) const
{
    if (parameter == variable)
        return true;
    if (!parameter || !variable || parameter->kind != variable->kind)
        return false;
    if (parameter->kind == TypeKind::String)
        return parameter->wide == variable->wide; // the capacity travels with the string and is checked on writes
    if (parameter->size != variable->size)
        return false;
    switch (parameter->kind) {
    case TypeKind::Elementary:
        return parameter->elem == variable->elem;
    case TypeKind::String:
        return false; // handled above
    case TypeKind::Enum:
        return parameter->enumNames == variable->enumNames;
    case TypeKind::Array:
        if (parameter->dims.size() != variable->dims.size())
            return false;
        for (size_t d = 0; d < parameter->dims.size(); ++d) {
            if (parameter->dims[d].count() != variable->dims[d].count())
                return false;
        }
        return sameStoredType(parameter->element, variable->element);
    case TypeKind::FunctionBlock:
        return parameter->pou == variable->pou;
    case TypeKind::Pointer:
    case TypeKind::Reference:
        return true; // addresses: any pointer stands for any other (CODESYS)
    case TypeKind::Interface:
        return parameter->pou == variable->pou;
    case TypeKind::Struct:
        if (parameter->members.size() != variable->members.size())
            return false;
        for (size_t i = 0; i < parameter->members.size(); ++i) {
            const Member &a = parameter->members[i], &b = variable->members[i];
            if (a.offset != b.offset || !sameStoredType(a.type, b.type))
                return false;
        }
        return true;
    }
    return false;
}

Place Codegen::inOutVariable(const Member &parameter, const Argument &a, const QString &callee)
{
    if (a.expr && a.expr->kind == ExprKind::Error)
        return {}; // the parser has said what is wrong
    const size_t before = m_diagnostics.all().size();
    const bool variableLike = a.expr
        && (a.expr->kind == ExprKind::Name || a.expr->kind == ExprKind::Member || a.expr->kind == ExprKind::Index
            || a.expr->kind == ExprKind::DirectAddress);
    const Place target = variableLike ? resolvePlace(*a.expr, true) : Place{};
    if (target.kind != Place::Kind::Direct && target.kind != Place::Kind::Indirect) {
        if (m_diagnostics.all().size() == before) // not when the expression already said what is wrong
            error(a.location, QCoreApplication::translate("iec::interp::Compiler", "VAR_IN_OUT %1 of %2 needs a variable, not a value.").arg(parameter.name, callee),
                  QCoreApplication::translate("iec::interp::Compiler", "it may change what it is given; pass a variable"));
        return {};
    }
    if (target.readOnly) {
        error(a.location, target.readOnlyReason.isEmpty() ? QCoreApplication::translate("iec::interp::Compiler", "%1 cannot be changed.").arg(target.text) : target.readOnlyReason,
              QCoreApplication::translate("iec::interp::Compiler", "VAR_IN_OUT %1 of %2 may change the variable it is given").arg(parameter.name, callee));
        return {};
    }
    if (!sameInOutType(parameter.type, target.type)) {
        error(a.location, QCoreApplication::translate("iec::interp::Compiler", "VAR_IN_OUT %1 of %2 needs a variable of type %3, not %4.")
                              .arg(parameter.name, callee, typeName(parameter.type), typeName(target.type)),
              QCoreApplication::translate("iec::interp::Compiler", "VAR_IN_OUT passes the variable itself, so no conversion is possible; use a variable of type %1").arg(typeName(parameter.type)));
        return {};
    }
    return target;
}

std::uint32_t Codegen::inOutAddress(const Place &variable)
{
    if (variable.kind == Place::Kind::Indirect)
        return variable.operand;
    const std::uint32_t address = temp(elem(Elem::UDInt));
    instr(op::Lea, address, variable.operand);
    return address;
}

void Codegen::checkInOutBefore(const Member &parameter, const Place &variable, SourceLocation at, std::vector<InOutCheck> &after)
{
    if (parameter.type->kind != TypeKind::Elementary)
        return; // arrays and structs of subranges must match exactly (sameInOutType)
    if (!subrangeWithin(variable.type, parameter.type))
        checkSubrange(read(variable), parameter.type, at);
    if (!subrangeWithin(parameter.type, variable.type))
        after.push_back({variable, at});
}

void Codegen::checkInOutAfter(const std::vector<InOutCheck> &after)
{
    for (const InOutCheck &c : after)
        checkSubrange(read(c.variable), c.variable.type, c.location);
}

Value Codegen::compileCall(const Expr &call, bool asStatement, const Place *destination)
{
    const Expr &callee = call.operands.front();
    // IEC 61131-3 has formal calls (every argument named) and positional ones, not a mix: in
    // F(1, b := 2) it is unclear which parameter the 1 is for.
    const auto named = std::count_if(call.callArgs.begin(), call.callArgs.end(), [](const CallArg &a) { return !a.name.isEmpty(); });
    if (named > 0 && named < static_cast<std::ptrdiff_t>(call.callArgs.size())) {
        error(call.location, QCoreApplication::translate("iec::interp::Compiler", "A call gives either all its arguments by name or none; here only some have a name."),
              QCoreApplication::translate("iec::interp::Compiler", "write each argument as name := value"));
        return {};
    }
    if (callee.kind == ExprKind::Name && !m_pouIndex.contains(key(callee.text))) {
        if (auto intrinsic = pointerFunction(callee.text, call.callArgs, call.location))
            return *intrinsic;
    }
    if (auto method = methodCall(callee, call.callArgs, call.location, asStatement, destination))
        return *method;
    // SUPER^(): the body of the block this one extends, on the same instance.
    if (callee.kind == ExprKind::Deref && callee.operands.front().kind == ExprKind::Name
        && callee.operands.front().text.compare(QLatin1String("SUPER"), Qt::CaseInsensitive) == 0 && !unusableVar(QStringLiteral("SUPER"))) {
        const int base = baseOf(currentClass());
        if (base < 0 || m_pou->methodOf >= 0) {
            error(call.location, QCoreApplication::translate("iec::interp::Compiler", "SUPER^() calls the body of the block this one extends; it is only known in such a block's body."));
            return {};
        }
        noteCall(base, call.location);
        instr(op::CallFb, kInstanceRelative, 0, 0, 0, static_cast<std::uint16_t>(base));
        return {};
    }
    if (callAction(callee, call.callArgs, call.location, asStatement))
        return {};
    std::optional<Place> instance;
    if (callee.kind == ExprKind::Member || callee.kind == ExprKind::Index || callee.kind == ExprKind::Deref) {
        instance = resolvePlace(callee);
        if (instance->kind == Place::Kind::Invalid)
            return {};
    } else if (m_pou && m_pou->frame && m_pou->frame->member(callee.text)
               && !(m_pou->kind == PouKind::Function && callee.text.compare(m_pou->name, Qt::CaseInsensitive) == 0)) {
        // (A function's own name is its result variable; calling it is recursion, reported as such.)
        instance = resolvePlace(callee);
    } else if (m_globals.contains(key(callee.text))) {
        instance = resolvePlace(callee);
    } else if (callee.kind == ExprKind::Name && unusableVar(callee.text)) {
        return {}; // an instance whose type is unknown: reported with its declaration
    }
    return callNamed(callee.text, instance ? &*instance : nullptr, arguments(call.callArgs), call.location, asStatement, destination);
}

bool Codegen::callAction(const Expr &callee, const std::vector<ast::CallArg> &args, SourceLocation at, bool asStatement)
{
    if (!m_pou)
        return false;
    int action = -1;
    Place instance;
    if (callee.kind == ExprKind::Name) {
        // Act(); inside the POU: a variable of the same name wins.
        if (m_pou->kind == PouKind::Function || (m_pou->frame && m_pou->frame->member(callee.text)))
            return false;
        action = actionIndex(m_pou->index, callee.text);
        instance.kind = Place::Kind::Direct;
        instance.operand = kInstanceRelative; // the instance that is running
    } else if (callee.kind == ExprKind::Member) {
        // Inst.Act(); only through names and members, so that looking does not emit code.
        const Expr *e = &callee.operands.front();
        while (e->kind == ExprKind::Member)
            e = &e->operands.front();
        if (e->kind != ExprKind::Name)
            return false;
        instance = resolvePlace(callee.operands.front(), false);
        if (instance.kind == Place::Kind::Invalid || !instance.type || instance.type->kind != TypeKind::FunctionBlock
            || instance.type->member(callee.text))
            return false;
        action = actionIndex(instance.type->pou, callee.text);
    }
    if (action < 0)
        return false;
    if (!asStatement) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "A function block call is a statement of its own."));
        return true;
    }
    if (!args.empty()) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "The action %1 takes no arguments.").arg(m_module->pous[size_t(action)].name));
        return true;
    }
    instr(instance.kind == Place::Kind::Direct ? op::CallFb : op::CallFbPtr, instance.operand, 0, 0, 0, static_cast<std::uint16_t>(action));
    return true;
}

Value Codegen::callNamed(const QString &name, const Place *callee, std::vector<Argument> args, SourceLocation at,
                         bool asStatement, const Place *destination)
{
    if (callee) {
        if (callee->kind == Place::Kind::Invalid)
            return {};
        const bool program = callee->fbPou >= 0 && m_pous[size_t(callee->fbPou)].kind == PouKind::Program; // CAL PRG1
        if (callee->type->kind != TypeKind::FunctionBlock && !program) {
            error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 is a %2, not a function block; it cannot be called.").arg(callee->text, typeName(callee->type)));
            return {};
        }
        if (!asStatement) {
            error(at, QCoreApplication::translate("iec::interp::Compiler", "A function block call is a statement of its own."),
                  QCoreApplication::translate("iec::interp::Compiler", "call %1(...); then read its outputs, e.g. %1.Q").arg(callee->text));
            return {};
        }
        callFunctionBlock(*callee, args, at);
        return {};
    }
    if (const int index = m_pouIndex.value(key(name), -1); index >= 0) {
        PouInfo &pou = m_pous[size_t(index)];
        if (pou.kind == PouKind::Function)
            return callUserFunction(pou, args, at, destination);
        if (pou.kind == PouKind::Program) {
            // CODESYS: PRG1(); runs the program's one instance, like a function block's.
            const Place instance = programPlace(pou, name, at);
            if (instance.kind == Place::Kind::Invalid)
                return {};
            if (!asStatement) {
                error(at, QCoreApplication::translate("iec::interp::Compiler", "A program call is a statement of its own."),
                      QCoreApplication::translate("iec::interp::Compiler", "call %1(...); then read its outputs, e.g. %1.Out").arg(name));
                return {};
            }
            callFunctionBlock(instance, args, at);
            return {};
        }
        error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 is a function block type; declare an instance (e.g. inst : %1;) and call that.").arg(name));
        return {};
    }
    // Standard functions take their arguments as values.
    std::vector<Value> values;
    std::vector<QString> names;
    for (const Argument &a : args) {
        if (a.isOutput) {
            error(a.location, QCoreApplication::translate("iec::interp::Compiler", "%1 has no outputs to connect with '=>'.").arg(name));
            return {};
        }
        values.push_back(a.value ? *a.value : compileExpr(*a.expr));
        names.push_back(a.name.toUpper());
        if (!values.back().valid())
            return {};
    }
    if (auto result = standardFunction(name.toUpper(), values, names, at, destination))
        return *result;
    if (const QString library = vendorLibraryOf(name.toUpper()); !library.isEmpty()) {
        missingVendorLibrary(name, library, at);
        return {};
    }
    error(at, QCoreApplication::translate("iec::interp::Compiler", "Unknown function '%1'.").arg(name));
    return {};
}

void Codegen::callFunctionBlock(const Place &instance, const std::vector<Argument> &args, SourceLocation at)
{
    const Type *fbType = instance.type;
    noteCall(fbType->pou, at);
    // Inside the call the instance's inputs may be written, whatever the caller could do.
    Place inner = instance;
    inner.fbPou = -1;
    inner.readOnly = false;
    std::vector<const Member *> positional;
    for (const Member &m : fbType->members) {
        if (m.kind == VarKind::Input || m.kind == VarKind::InOut)
            positional.push_back(&m);
    }
    // TON(IN := x, PT := t): the most common call of all, one instruction with its two inputs.
    if (const auto native = nativeBlock(fbType); native && instance.kind == Place::Kind::Direct && args.size() == 2) {
        const Argument *in = nullptr, *pt = nullptr;
        for (const Argument &a : args) {
            if (a.name.compare(QLatin1String("IN"), Qt::CaseInsensitive) == 0 && !a.isOutput)
                in = &a;
            else if (a.name.compare(QLatin1String("PT"), Qt::CaseInsensitive) == 0 && !a.isOutput)
                pt = &a;
        }
        if (in && pt) {
            const Value inValue = coerce(in->value ? *in->value : compileExpr(*in->expr), boolType(), in->location, QStringLiteral("IN"));
            const Value ptValue = coerce(pt->value ? *pt->value : compileExpr(*pt->expr), elem(Elem::Time), pt->location, QStringLiteral("PT"));
            if (inValue.valid() && ptValue.valid())
                instr(op::NativeFbArgs, instance.operand, materialize(inValue), materialize(ptValue), 0, static_cast<std::uint16_t>(*native));
            return;
        }
    }
    size_t next = 0;
    std::vector<std::pair<const Member *, const Argument *>> outputs;
    std::vector<InOutCheck> inOutChecks;
    std::vector<const Member *> inOutGiven;
    for (const Argument &a : args) {
        const Member *m = nullptr;
        if (a.name.isEmpty()) {
            if (next < positional.size())
                m = positional[next++];
            else {
                error(a.location, QCoreApplication::translate("iec::interp::Compiler", "%1 takes only %2 input(s).").arg(typeName(fbType)).arg(positional.size()));
                return;
            }
        } else {
            m = fbType->member(a.name);
            if (!m || m->kind == VarKind::Local || m->kind == VarKind::Temp) {
                error(a.location, QCoreApplication::translate("iec::interp::Compiler", "%1 has no input or output called %2.").arg(typeName(fbType), a.name));
                continue;
            }
        }
        if (a.isOutput) {
            if (m->kind != VarKind::Output) {
                error(a.location, QCoreApplication::translate("iec::interp::Compiler", "%1 is not an output of %2; connect inputs with ':='.").arg(m->name, typeName(fbType)));
                continue;
            }
            outputs.push_back({m, &a});
            continue;
        }
        if (m->kind == VarKind::Output) {
            error(a.location, QCoreApplication::translate("iec::interp::Compiler", "%1 is an output of %2; connect it with '=>'.").arg(m->name, typeName(fbType)),
                  QCoreApplication::translate("iec::interp::Compiler", "write %1 => variable").arg(m->name));
            continue;
        }
        if (m->kind == VarKind::InOut) {
            inOutGiven.push_back(m);
            const Place target = inOutVariable(*m, a, typeName(fbType));
            if (target.kind == Place::Kind::Invalid)
                continue;
            Member slot = *m;
            slot.byReference = false;
            slot.type = elem(Elem::UDInt);
            const Place slotPlace = memberPlace(inner, slot, m->name);
            store(slotPlace, operandValue(inOutAddress(target), elem(Elem::UDInt)), a.location);
            // After the address is taken: reading first could fold the element's address away.
            checkInOutBefore(*m, target, a.location, inOutChecks);
            continue;
        }
        const Value value = a.value ? *a.value : compileExpr(*a.expr);
        store(memberPlace(inner, *m, instance.text + QLatin1Char('.') + m->name), value, a.location);
    }
    // A VAR_IN_OUT left out would be used through whatever address its slot still holds.
    for (const Member *m : positional) {
        if (m->kind == VarKind::InOut && std::find(inOutGiven.begin(), inOutGiven.end(), m) == inOutGiven.end()) {
            error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 needs a variable for its VAR_IN_OUT %2.").arg(instance.text, m->name),
                  QCoreApplication::translate("iec::interp::Compiler", "pass it in every call, e.g. %1(%2 := variable)").arg(instance.text, m->name));
            return;
        }
    }
    if (const auto native = nativeBlock(fbType)) {
        instr(instance.kind == Place::Kind::Direct ? op::NativeFb : op::NativeFbPtr, instance.operand, 0, 0, 0, static_cast<std::uint16_t>(*native));
    } else if (instance.kind == Place::Kind::Direct) {
        instr(op::CallFb, instance.operand, 0, 0, 0, static_cast<std::uint16_t>(fbType->pou));
    } else {
        instr(op::CallFbPtr, instance.operand, 0, 0, 0, static_cast<std::uint16_t>(fbType->pou));
    }
    checkInOutAfter(inOutChecks);
    for (const auto &[m, a] : outputs) {
        if (!a->expr || a->expr->kind == ExprKind::Error)
            continue; // Q => (left open)
        Value value = read(memberPlace(inner, *m, m->name));
        if (a->negated)
            value = unary(QStringLiteral("NOT"), value, a->location);
        store(resolvePlace(*a->expr), value, a->location);
    }
}

// The one instance of a PROGRAM, for calls (PRG1();) and its variables (PRG1.Out).
Place Codegen::programPlace(const PouInfo &pou, const QString &name, SourceLocation at)
{
    if (pou.programInstances != 1 || !pou.frame) {
        error(at, QCoreApplication::translate("iec::interp::Compiler", "The program %1 runs in %2 instances; its name alone does not say which.").arg(name).arg(pou.programInstances),
              QCoreApplication::translate("iec::interp::Compiler", "give each instance its own program, or reach the values through a global variable"));
        return {};
    }
    Place p;
    p.kind = Place::Kind::Direct;
    p.type = pou.frame;
    p.operand = pou.programBase;
    p.text = name;
    p.fbPou = pou.index;
    return p;
}

Value Codegen::callUserFunction(PouInfo &fn, const std::vector<Argument> &args, SourceLocation at, const Place *destination,
                                const Place *instance)
{
    if (!layoutPou(fn))
        return {};
    noteCall(fn.index, at);
    Place frame;
    frame.kind = Place::Kind::Direct;
    frame.operand = fn.frameBase;
    std::vector<bool> given(fn.parameters.size(), false);
    std::vector<std::pair<const Member *, const Argument *>> outputs;
    // Every argument is computed before any is stored: an argument may call the same function,
    // whose variables are static.
    std::vector<Value> computed(args.size());
    for (size_t i = 0; i < args.size(); ++i) {
        const Member *m = args[i].name.isEmpty() ? nullptr : fn.frame->member(args[i].name);
        const bool byValue = !args[i].isOutput && !(m && m->kind == VarKind::InOut)
            && !(args[i].name.isEmpty() && i < fn.parameters.size() && fn.parameters[i]->kind == VarKind::InOut);
        if (byValue)
            computed[i] = args[i].value ? *args[i].value : compileExpr(*args[i].expr);
    }
    size_t next = 0;
    std::vector<InOutCheck> inOutChecks;
    for (const Argument &a : args) {
        const Member *m = nullptr;
        if (a.name.isEmpty()) {
            if (next >= fn.parameters.size()) {
                error(a.location, QCoreApplication::translate("iec::interp::Compiler", "%1 takes only %2 argument(s).").arg(fn.name).arg(fn.parameters.size()));
                return {};
            }
            m = fn.parameters[next++];
        } else {
            m = fn.frame->member(a.name);
            if (!m || (m->kind != VarKind::Input && m->kind != VarKind::InOut && m->kind != VarKind::Output)
                || (fn.result && m->name.compare(fn.ast->name, Qt::CaseInsensitive) == 0)) {
                error(a.location, QCoreApplication::translate("iec::interp::Compiler", "%1 has no parameter called %2.").arg(fn.name, a.name));
                continue;
            }
        }
        if (a.isOutput || m->kind == VarKind::Output) {
            if (!a.isOutput || m->kind != VarKind::Output) {
                error(a.location, QCoreApplication::translate("iec::interp::Compiler", "Connect inputs of %1 with ':=' and outputs with '=>'.").arg(fn.name));
                continue;
            }
            outputs.push_back({m, &a});
            continue;
        }
        for (size_t k = 0; k < fn.parameters.size(); ++k) {
            if (fn.parameters[k] == m)
                given[k] = true;
        }
        if (m->kind == VarKind::InOut) {
            const Place target = inOutVariable(*m, a, fn.name);
            if (target.kind == Place::Kind::Invalid)
                continue;
            instr(op::Mov4, fn.frameBase + m->offset, inOutAddress(target));
            checkInOutBefore(*m, target, a.location, inOutChecks);
            continue;
        }
        const Value value = computed[size_t(&a - args.data())];
        store(memberPlace(frame, *m, m->name), value, a.location);
    }
    for (size_t k = 0; k < fn.parameters.size(); ++k) {
        if (given[k])
            continue;
        const Member *m = fn.parameters[k];
        if (m->kind == VarKind::InOut) {
            error(at, QCoreApplication::translate("iec::interp::Compiler", "%1 needs a variable for its VAR_IN_OUT %2.").arg(fn.name, m->name));
            return {};
        }
        emitMove(fn.frameBase + m->offset, fn.templateOffset + m->offset, m->type);
    }
    if (instance) // a method runs on its instance
        instr(instance->kind == Place::Kind::Direct ? op::CallFb : op::CallFbPtr, instance->operand, 0, 0, 0, static_cast<std::uint16_t>(fn.index));
    else
        instr(op::CallFn, 0, 0, 0, 0, static_cast<std::uint16_t>(fn.index));
    checkInOutAfter(inOutChecks);
    for (const auto &[m, a] : outputs) {
        Value value = operandValue(fn.frameBase + m->offset, m->type);
        if (a->negated)
            value = unary(QStringLiteral("NOT"), value, a->location);
        if (a->expr && a->expr->kind != ExprKind::Error)
            store(resolvePlace(*a->expr), value, a->location);
    }
    if (!fn.result)
        return {};
    const Member *result = fn.frame->member(fn.ast->name); // a method's result is named like the method
    // The result is copied out at once: a second call of the same function reuses its variables.
    const std::uint32_t out = destination && destination->kind == Place::Kind::Direct && destination->type == fn.result
        ? destination->operand
        : temp(fn.result);
    emitMove(out, fn.frameBase + result->offset, fn.result);
    return operandValue(out, fn.result);
}

} // namespace iec::interp::detail
