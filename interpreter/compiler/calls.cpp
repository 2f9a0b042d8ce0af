// Calls of functions, function blocks and standard functions.
#include "interpreter/compiler/codegen.h"

#include <QCoreApplication>

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

Value Codegen::compileCall(const Expr &call, bool asStatement, const Place *destination)
{
    const Expr &callee = call.operands.front();
    if (callAction(callee, call.callArgs, call.location, asStatement))
        return {};
    std::optional<Place> instance;
    if (callee.kind == ExprKind::Member || callee.kind == ExprKind::Index) {
        instance = resolvePlace(callee);
        if (instance->kind == Place::Kind::Invalid)
            return {};
    } else if (m_pou && m_pou->frame && m_pou->frame->member(callee.text)) {
        instance = resolvePlace(callee);
    } else if (m_globals.contains(key(callee.text))) {
        instance = resolvePlace(callee);
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
        if (callee->type->kind != TypeKind::FunctionBlock) {
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
        error(at, pou.kind == PouKind::Program ? QCoreApplication::translate("iec::interp::Compiler", "A program cannot be called from another POU; it runs in a task.")
                                               : QCoreApplication::translate("iec::interp::Compiler", "%1 is a function block type; declare an instance (e.g. inst : %1;) and call that.").arg(name));
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
            const Place target = resolvePlace(*a.expr);
            if (target.kind != Place::Kind::Direct && target.kind != Place::Kind::Indirect) {
                error(a.location, QCoreApplication::translate("iec::interp::Compiler", "VAR_IN_OUT %1 needs a variable.").arg(m->name));
                continue;
            }
            Member slot = *m;
            slot.byReference = false;
            slot.type = elem(Elem::UDInt);
            const Place slotPlace = memberPlace(inner, slot, m->name);
            const std::uint32_t address = target.kind == Place::Kind::Direct ? temp(elem(Elem::UDInt)) : target.operand;
            if (target.kind == Place::Kind::Direct)
                instr(op::Lea, address, target.operand);
            store(slotPlace, operandValue(address, elem(Elem::UDInt)), a.location);
            continue;
        }
        const Value value = a.value ? *a.value : compileExpr(*a.expr);
        store(memberPlace(inner, *m, instance.text + QLatin1Char('.') + m->name), value, a.location);
    }
    if (const auto native = nativeBlock(fbType)) {
        instr(instance.kind == Place::Kind::Direct ? op::NativeFb : op::NativeFbPtr, instance.operand, 0, 0, 0, static_cast<std::uint16_t>(*native));
    } else if (instance.kind == Place::Kind::Direct) {
        instr(op::CallFb, instance.operand, 0, 0, 0, static_cast<std::uint16_t>(fbType->pou));
    } else {
        instr(op::CallFbPtr, instance.operand, 0, 0, 0, static_cast<std::uint16_t>(fbType->pou));
    }
    for (const auto &[m, a] : outputs) {
        if (!a->expr || a->expr->kind == ExprKind::Error)
            continue; // Q => (left open)
        Value value = read(memberPlace(inner, *m, m->name));
        if (a->negated)
            value = unary(QStringLiteral("NOT"), value, a->location);
        store(resolvePlace(*a->expr), value, a->location);
    }
}

Value Codegen::callUserFunction(PouInfo &fn, const std::vector<Argument> &args, SourceLocation at, const Place *destination)
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
                || m->name.compare(fn.name, Qt::CaseInsensitive) == 0) {
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
            const Place target = a.expr ? resolvePlace(*a.expr) : Place{};
            if (target.kind != Place::Kind::Direct && target.kind != Place::Kind::Indirect) {
                error(a.location, QCoreApplication::translate("iec::interp::Compiler", "VAR_IN_OUT %1 needs a variable.").arg(m->name));
                continue;
            }
            std::uint32_t address = target.operand;
            if (target.kind == Place::Kind::Direct) {
                address = temp(elem(Elem::UDInt));
                instr(op::Lea, address, target.operand);
            }
            instr(op::Mov4, fn.frameBase + m->offset, address);
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
    instr(op::CallFn, 0, 0, 0, 0, static_cast<std::uint16_t>(fn.index));
    for (const auto &[m, a] : outputs) {
        Value value = operandValue(fn.frameBase + m->offset, m->type);
        if (a->negated)
            value = unary(QStringLiteral("NOT"), value, a->location);
        if (a->expr && a->expr->kind != ExprKind::Error)
            store(resolvePlace(*a->expr), value, a->location);
    }
    if (!fn.result)
        return {};
    const Member *result = fn.frame->member(fn.name);
    // The result is copied out at once: a second call of the same function reuses its variables.
    const std::uint32_t out = destination && destination->kind == Place::Kind::Direct && destination->type == fn.result
        ? destination->operand
        : temp(fn.result);
    emitMove(out, fn.frameBase + result->offset, fn.result);
    return operandValue(out, fn.result);
}

} // namespace iec::interp::detail
