// Instruction List: the accumulator (current result) is a compile-time Value, so IL compiles to
// the same typed instructions as ST. Deferred operations "MUL (" push the operator and the
// current result; ")" pops them and applies the operator to the result inside the brackets.
#include "interpreter/compiler/codegen.h"

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

} // namespace

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
    const auto conditionalSkip = [&](const IlInstruction &ins, const QString &base) -> std::optional<std::uint32_t> {
        const QString modifier = ins.op.mid(base.size());
        if (modifier.isEmpty())
            return std::nullopt;
        if (!needCurrent(ins))
            return std::nullopt;
        const Value c = coerce(current, boolType(), ins.location, QCoreApplication::translate("iec::interp::Compiler", "(the condition of %1)").arg(ins.op));
        if (!c.valid())
            return std::nullopt;
        const bool jumpWhenTrue = (base == QLatin1String("JMP")) == (modifier == QLatin1String("C"));
        return branchIf(c, jumpWhenTrue);
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
            labels.insert(key(ins.label), here());
            markTarget(here());
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
            const auto skip = conditionalSkip(ins, QStringLiteral("JMP"));
            if (!ins.operand || ins.operand->kind != ExprKind::Name) {
                error(ins.location, QCoreApplication::translate("iec::interp::Compiler", "%1 needs a label to jump to.").arg(op));
                continue;
            }
            if (skip) {
                jumps.push_back({*skip, &ins});
            } else if (op == QLatin1String("JMP")) {
                jumps.push_back({instr(op::Jmp), &ins});
            }
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
        } else if (std::any_of(std::begin(kFbInputOperators), std::end(kFbInputOperators), [&](const char *n) { return op == QLatin1String(n); })) {
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
