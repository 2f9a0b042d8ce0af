// Instruction List: the accumulator (current result) is a compile-time Value, so IL compiles to
// the same typed instructions as ST. Deferred operations "MUL (" push the operator and the
// current result; ")" pops them and applies the operator to the result inside the brackets.
#include "interpreter/compiler/codegen.h"
#include "interpreter/compiler/typeutil.h"

#include <QCoreApplication>
#include <QScopeGuard>

namespace iec::interp::detail {

using namespace ast;

namespace {

struct IlOperator {
    const char *name;
    const char *st; // the ST operator it applies
};
constexpr IlOperator kBinary[] = {
    {"AND", "AND"}, {"OR", "OR"}, {"XOR", "XOR"}, {"ADD", "+"}, {"SUB", "-"}, {"MUL", "*"}, {"DIV", "/"},
    {"MOD", "MOD"}, {"GT", ">"},   {"GE", ">="}, {"EQ", "="},  {"NE", "<>"}, {"LE", "<="}, {"LT", "<"},
};
const char *binaryOperator(const QString &op)
{
    for (const IlOperator &o : kBinary) {
        if (op == QLatin1String(o.name))
            return o.st;
    }
    return nullptr;
}

// FB input operators: "S1 FF28" sets FF28.S1 to the current result and calls FF28.
constexpr const char *kFbInputOperators[] = {"S1", "R1", "CLK", "CU", "CD", "PV", "IN", "PT"};

bool isFbInputOperator(const QString &op)
{
    return std::any_of(std::begin(kFbInputOperators), std::end(kFbInputOperators), [&](const char *n) { return op == QLatin1String(n); });
}

// What an instruction does with the current result, for deciding which labels need it.
enum class CurrentUse { Passes, Reads, Defines, Ends, Jumps };

CurrentUse currentUse(const IlInstruction &ins)
{
    const QString &op = ins.op;
    if (op.isEmpty() || op == QLatin1String("CAL"))
        return CurrentUse::Passes;
    if (op == QLatin1String("LD") || op == QLatin1String("LDN"))
        return CurrentUse::Defines;
    if (op == QLatin1String("JMP"))
        return CurrentUse::Jumps;
    if (op == QLatin1String("RET"))
        return CurrentUse::Ends;
    const bool knownOperator = binaryOperator(op) || op == QLatin1String("ST") || op == QLatin1String("STN") || op == QLatin1String("S")
        || op == QLatin1String("R") || op == QLatin1String(")") || op == QLatin1String("NOT") || op.startsWith(QLatin1String("JMP"))
        || op.startsWith(QLatin1String("CAL")) || op.startsWith(QLatin1String("RET")) || isFbInputOperator(op);
    if (!knownOperator && !ins.operand && !ins.callArgs.empty() && !ins.openParen)
        return CurrentUse::Defines; // a function with formal arguments only
    return CurrentUse::Reads;
}

// The labels (upper case) after which the current result is read before it is loaded anew: a
// jump to them carries its current result along (IEC 61131-3: a jump does not change it).
QSet<QString> labelsReadingCurrent(const std::vector<IlInstruction> &list)
{
    QHash<QString, size_t> at;
    for (size_t i = 0; i < list.size(); ++i) {
        if (!list[i].label.isEmpty() && !at.contains(key(list[i].label)))
            at.insert(key(list[i].label), i);
    }
    QSet<QString> live;
    for (auto it = at.constBegin(); it != at.constEnd(); ++it) {
        // Follow the code from the label through unconditional jumps until the current result
        // is read, loaded anew or the body ends.
        QSet<size_t> visited;
        for (size_t i = it.value(); i < list.size() && !visited.contains(i);) {
            visited.insert(i);
            const CurrentUse use = currentUse(list[i]);
            if (use == CurrentUse::Reads)
                live.insert(it.key());
            if (use == CurrentUse::Reads || use == CurrentUse::Defines || use == CurrentUse::Ends)
                break;
            if (use == CurrentUse::Jumps) {
                const auto target = list[i].operand ? at.constFind(key(list[i].operand->text)) : at.constEnd();
                if (target == at.constEnd())
                    break;
                i = target.value();
                continue;
            }
            ++i;
        }
    }
    return live;
}

} // namespace

// The type the current result has after a label that several paths reach: the first typed one,
// else a literal's own type (INT, DINT or LINT; LREAL).
const Type *Codegen::ilJoinType(const std::vector<Value> &arriving)
{
    for (const Value &v : arriving) {
        if (v.valid() && !v.untyped)
            return v.type;
    }
    for (const Value &v : arriving) {
        if (!v.valid())
            continue;
        if (v.constant.kind == ConstValue::Kind::Real || isReal(v.type))
            return elem(Elem::LReal);
        if (v.kind == Value::Kind::Constant)
            return elem(fits(v.constant, Elem::Int) ? Elem::Int : fits(v.constant, Elem::DInt) ? Elem::DInt : Elem::LInt);
        return v.type;
    }
    return nullptr;
}

void Codegen::compileIl(const std::vector<IlInstruction> &list)
{
    struct Deferred {
        const char *op;
        Value saved;
        SourceLocation location;
        bool negate = false; // ANDN( ... ): the result of the brackets is negated
    };
    std::vector<Deferred> stack;
    Value current;
    QHash<QString, std::uint32_t> labels;
    std::vector<std::pair<std::uint32_t, const IlInstruction *>> jumps;
    const std::uint32_t tempMark = m_tempTop;

    // A jump keeps the current result: where the code after a label reads it, every path to the
    // label leaves its current result in one variable of the label (its join), and the code
    // after the label reads that variable. Jumps forward go through a stub placed before the
    // label that stores the value they carry; jumps back store it before they jump.
    struct PendingJump {
        std::uint32_t pc;
        Value carried;
        const IlInstruction *ins;
    };
    struct Join {
        bool placed = false;
        Place slot;
        std::vector<PendingJump> pending;
    };
    const QSet<QString> labelsNeedingCurrent = labelsReadingCurrent(list);
    QHash<QString, Join> joins;
    bool reachable = true; // whether control can flow into the next instruction from the one before
    const auto placeJoin = [&](Join &join, const IlInstruction &ins) {
        join.placed = true;
        std::vector<Value> arriving;
        for (const PendingJump &p : join.pending)
            arriving.push_back(p.carried);
        if (reachable)
            arriving.push_back(current);
        const Type *type = ilJoinType(arriving);
        if (!type) {
            for (const PendingJump &p : join.pending)
                jumps.push_back({p.pc, p.ins});
            return;
        }
        join.slot.kind = Place::Kind::Direct;
        join.slot.type = type;
        join.slot.operand = allocate(type->size, std::max<std::uint32_t>(type->align, 1));
        join.slot.text = QCoreApplication::translate("iec::interp::Compiler", "(the current result at label %1)").arg(ins.label);
        writeInitial(join.slot.operand, type, nullptr);
        const std::uint32_t savedTop = m_tempTop;
        m_tempTop = m_tempMax; // above every temporary a jump's value may still be in
        std::optional<std::uint32_t> pastStubs;
        if (reachable && !join.pending.empty())
            pastStubs = instr(op::Jmp);
        std::vector<std::uint32_t> toLabel;
        for (const PendingJump &p : join.pending) {
            patchJump(p.pc, here());
            if (p.carried.valid())
                store(join.slot, p.carried, p.ins->location);
            toLabel.push_back(instr(op::Jmp));
        }
        if (pastStubs)
            patchJump(*pastStubs, here());
        else if (!toLabel.empty() && toLabel.back() + 1 == here()) {
            m_module->code.pop_back(); // the last stub runs into the label
            toLabel.pop_back();
        }
        if (reachable && current.valid())
            store(join.slot, current, ins.location);
        for (const std::uint32_t j : toLabel)
            patchJump(j, here());
        m_tempTop = savedTop;
        current = read(join.slot);
    };

    // After one "no current result" message the following instructions stay quiet until the
    // next LD: one mistake, one message.
    bool quiet = false;
    const auto needCurrent = [&](const IlInstruction &ins) {
        if (current.valid())
            return true;
        if (!quiet)
            error(ins.location, QCoreApplication::translate("iec::interp::Compiler", "%1 needs a current result; load one first with LD.").arg(ins.op));
        quiet = true;
        return false;
    };
    const auto operandValue = [&](const IlInstruction &ins, bool negate) -> Value {
        if (!ins.operand) {
            error(ins.location, QCoreApplication::translate("iec::interp::Compiler", "%1 needs an operand.").arg(ins.op));
            return {};
        }
        Value v = compileExpr(*ins.operand);
        return negate ? unary(QStringLiteral("NOT"), v, ins.location) : v;
    };
    const auto operandPlace = [&](const IlInstruction &ins) -> Place {
        if (!ins.operand) {
            error(ins.location, QCoreApplication::translate("iec::interp::Compiler", "%1 needs an operand.").arg(ins.op));
            return {};
        }
        return resolvePlace(*ins.operand);
    };
    // JMPC/CALC/RETC act when the current result is TRUE, the N forms when it is FALSE. For JMP the
    // returned jump goes to the label; for CAL and RET it skips them. Nothing for the plain forms.
    const auto conditionalSkip = [&](const IlInstruction &ins, const QString &base, bool invert = false) -> std::optional<std::uint32_t> {
        const QString modifier = ins.op.mid(base.size());
        if (modifier.isEmpty())
            return std::nullopt;
        if (!needCurrent(ins))
            return std::nullopt;
        const Value c = coerce(current, boolType(), ins.location, QCoreApplication::translate("iec::interp::Compiler", "(the condition of %1)").arg(ins.op));
        if (!c.valid())
            return std::nullopt;
        const bool jumpWhenTrue = (base == QLatin1String("JMP")) == (modifier == QLatin1String("C"));
        return branchIf(c, jumpWhenTrue != invert);
    };

    for (const IlInstruction &ins : list) {
        markLine(ins.location);
        // An instruction that reported an error leaves no current result; the ones after it stay
        // quiet about that until the next LD.
        const size_t diagnosticsBefore = m_diagnostics.all().size();
        const auto quietAfterError = qScopeGuard([&] {
            if (m_diagnostics.all().size() != diagnosticsBefore && !current.valid())
                quiet = true;
        });
        if (!ins.label.isEmpty()) {
            if (labels.contains(key(ins.label)))
                error(ins.location, QCoreApplication::translate("iec::interp::Compiler", "The label %1 is defined twice.").arg(ins.label));
            else if (labelsNeedingCurrent.contains(key(ins.label)))
                placeJoin(joins[key(ins.label)], ins);
            labels.insert(key(ins.label), here());
            markTarget(here());
            reachable = true;
        }
        const QString &op = ins.op;
        if (op.isEmpty())
            continue;
        if (stack.empty() && (op == QLatin1String("LD") || op == QLatin1String("LDN")))
            m_tempTop = tempMark; // a new expression: earlier temporaries are dead
        // The N modifier exists for AND, OR and XOR only (LDN and STN are handled apart): LEN is
        // a function, not LE negated.
        const bool negated = op == QLatin1String("ANDN") || op == QLatin1String("ORN") || op == QLatin1String("XORN");
        const QString base = negated ? op.chopped(1) : op;

        if (op == QLatin1String("LD") || op == QLatin1String("LDN")) {
            current = operandValue(ins, op == QLatin1String("LDN"));
            quiet = !current.valid();
        } else if (op == QLatin1String("ST") || op == QLatin1String("STN")) {
            if (needCurrent(ins))
                store(operandPlace(ins), op == QLatin1String("STN") ? unary(QStringLiteral("NOT"), current, ins.location) : current, ins.location);
        } else if (op == QLatin1String("S") || op == QLatin1String("R")) {
            if (!needCurrent(ins))
                continue;
            const Value c = coerce(current, boolType(), ins.location, QCoreApplication::translate("iec::interp::Compiler", "(the condition of %1)").arg(op));
            const Place target = operandPlace(ins);
            if (!c.valid() || target.kind == Place::Kind::Invalid)
                continue;
            const std::uint32_t skip = instr(op::Jz, 0, materialize(c));
            ConstValue value;
            value.kind = ConstValue::Kind::Int;
            value.i = op == QLatin1String("S") ? 1 : 0;
            store(target, constantValue(boolType(), value), ins.location);
            patchJump(skip, here());
        } else if (const char *stOp = binaryOperator(base)) {
            if (!needCurrent(ins))
                continue;
            if (ins.openParen) {
                // Keep the current result safe from the code inside the brackets.
                Value saved = current;
                if (saved.kind == Value::Kind::Operand) {
                    const std::uint32_t copy = temp(saved.type);
                    emitMove(copy, saved.operand, saved.type);
                    saved = Codegen::operandValue(copy, saved.type);
                }
                stack.push_back({stOp, saved, ins.location, negated});
                current = ins.operand ? operandValue(ins, false) : Value{};
                continue;
            }
            current = binary(QLatin1String(stOp), current, operandValue(ins, negated), ins.location);
        } else if (op == QLatin1String(")")) {
            if (stack.empty()) {
                error(ins.location, QCoreApplication::translate("iec::interp::Compiler", "This ')' has no matching operator with '('."));
                continue;
            }
            const Deferred d = stack.back();
            stack.pop_back();
            if (needCurrent(ins))
                current = binary(QLatin1String(d.op), d.saved, d.negate ? unary(QStringLiteral("NOT"), current, d.location) : current, d.location);
        } else if (op == QLatin1String("NOT")) {
            if (needCurrent(ins))
                current = unary(QStringLiteral("NOT"), current, ins.location);
        } else if (op == QLatin1String("JMP") || op == QLatin1String("JMPC") || op == QLatin1String("JMPCN")) {
            if (!ins.operand || ins.operand->kind != ExprKind::Name) {
                conditionalSkip(ins, QStringLiteral("JMP"));
                error(ins.location, QCoreApplication::translate("iec::interp::Compiler", "%1 needs a label to jump to.").arg(op));
                continue;
            }
            const bool conditional = op != QLatin1String("JMP");
            const QString target = key(ins.operand->text);
            Join *join = labelsNeedingCurrent.contains(target) && current.valid() ? &joins[target] : nullptr;
            // A conditional jump is taken when its BOOL current result is TRUE (JMPC) or FALSE
            // (JMPCN): that is the value it carries.
            Value carried = current;
            if (conditional && current.valid() && current.type == boolType()) {
                ConstValue taken;
                taken.kind = ConstValue::Kind::Int;
                taken.i = op == QLatin1String("JMPC") ? 1 : 0;
                carried = constantValue(boolType(), taken);
            }
            if (join && join->placed) {
                // Back to a label already compiled: store the value, then jump.
                std::optional<std::uint32_t> notTaken;
                if (conditional && !(notTaken = conditionalSkip(ins, QStringLiteral("JMP"), true)))
                    continue;
                if (join->slot.kind != Place::Kind::Invalid)
                    store(join->slot, carried, ins.location);
                jumps.push_back({instr(op::Jmp), &ins});
                if (notTaken)
                    patchJump(*notTaken, here());
            } else {
                const auto skip = conditionalSkip(ins, QStringLiteral("JMP"));
                if (conditional && !skip)
                    continue;
                const std::uint32_t jump = skip ? *skip : instr(op::Jmp);
                if (join)
                    join->pending.push_back({jump, carried, &ins});
                else
                    jumps.push_back({jump, &ins});
            }
            reachable = conditional;
        } else if (op == QLatin1String("CAL") || op == QLatin1String("CALC") || op == QLatin1String("CALCN")) {
            const auto skip = conditionalSkip(ins, QStringLiteral("CAL"));
            if (!ins.operand || !callAction(*ins.operand, ins.callArgs, ins.location, true)) {
                const Place instance = operandPlace(ins);
                if (instance.kind != Place::Kind::Invalid)
                    callNamed(ins.operand->text, &instance, arguments(ins.callArgs), ins.location, true, nullptr);
            }
            if (skip)
                patchJump(*skip, here());
        } else if (op == QLatin1String("RET") || op == QLatin1String("RETC") || op == QLatin1String("RETCN")) {
            const auto skip = conditionalSkip(ins, QStringLiteral("RET"));
            instr(op::Ret);
            if (skip)
                patchJump(*skip, here());
            reachable = op != QLatin1String("RET");
        } else if (isFbInputOperator(op)) {
            if (!needCurrent(ins))
                continue;
            const Place instance = operandPlace(ins);
            if (instance.kind == Place::Kind::Invalid)
                continue;
            if (instance.type->kind != TypeKind::FunctionBlock || !instance.type->member(op)) {
                error(ins.location, QCoreApplication::translate("iec::interp::Compiler", "%1 is not a function block with an input %2.").arg(instance.text, op));
                continue;
            }
            Argument input;
            input.name = op;
            input.value = current;
            input.location = ins.location;
            callFunctionBlock(instance, {input}, ins.location);
        } else if (!ins.operand && !ins.callArgs.empty() && !ins.openParen) {
            // A function with a formal argument list: the arguments are all it takes.
            current = callNamed(op, nullptr, arguments(ins.callArgs), ins.location, false, nullptr);
            quiet = !current.valid();
        } else {
            // A function: the current result is its first argument, the operands the others.
            if (!needCurrent(ins))
                continue;
            std::vector<Argument> args;
            Argument first;
            first.value = current;
            first.location = ins.location;
            args.push_back(first);
            if (ins.operand) {
                Argument a;
                a.expr = &*ins.operand;
                a.location = ins.operand->location;
                args.push_back(a);
            }
            for (Argument &a : arguments(ins.callArgs))
                args.push_back(a);
            current = callNamed(op, nullptr, args, ins.location, false, nullptr);
        }
    }
    if (!stack.empty())
        error(stack.back().location, QCoreApplication::translate("iec::interp::Compiler", "This '(' is never closed with ')'."));
    for (const Join &join : joins) {
        for (const PendingJump &p : join.pending) {
            if (!join.placed)
                jumps.push_back({p.pc, p.ins}); // to a label that does not exist: reported below
        }
    }
    for (const auto &[at, ins] : jumps) {
        const auto it = labels.constFind(key(ins->operand->text));
        if (it == labels.constEnd()) {
            error(ins->location, QCoreApplication::translate("iec::interp::Compiler", "There is no label %1 to jump to.").arg(ins->operand->text));
            continue;
        }
        patchJump(at, *it);
    }
}

} // namespace iec::interp::detail
