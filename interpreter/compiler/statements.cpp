// ST statements.
#include "interpreter/compiler/codegen.h"
#include "interpreter/compiler/typeutil.h"

#include <QCoreApplication>

namespace iec::interp::detail {

using namespace ast;

Value Codegen::condition(const Expr &expr)
{
    const Value v = compileExpr(expr);
    if (!v.valid())
        return {};
    if (v.type->kind != TypeKind::Elementary || v.type->elem != Elem::Bool) {
        error(expr.location, QCoreApplication::translate("iec::interp::Compiler", "A condition must be BOOL, not %1.").arg(typeName(v.type)),
              expr.kind == ExprKind::Binary ? QString() : QCoreApplication::translate("iec::interp::Compiler", "compare it, e.g. x <> 0"));
        return {};
    }
    return v;
}

// Room for a FOR counter's value one step past a 64-bit end (__extension__: no -Wpedantic warning).
__extension__ typedef __int128 Wide128;

void Codegen::warnForLoopEnd(const Stmt &s, const Place &counter, const Value &start, const ConstValue &end, const ConstValue &step, bool up)
{
    if (end.kind != ConstValue::Kind::Int || step.kind != ConstValue::Kind::Int || end.bigUnsigned || step.bigUnsigned || step.i == 0)
        return;
    // The loop ends when the counter passes the end value. The value that passes it: exact when
    // the start is known, else at least one beyond the end.
    Wide128 passing = static_cast<Wide128>(end.i) + (up ? 1 : -1);
    bool exact = step.i == 1 || step.i == -1;
    if (start.kind == Value::Kind::Constant && start.constant.kind == ConstValue::Kind::Int && !start.constant.bigUnsigned) {
        const Wide128 first = start.constant.i;
        if (up ? first > end.i : first < end.i)
            return; // never runs
        passing = first + ((static_cast<Wide128>(end.i) - first) / step.i + 1) * step.i;
        exact = true;
    }
    const Type *type = counter.type;
    if (type->subrange) {
        const auto [low, high] = *type->subrange;
        if (passing > high || passing < low)
            warning(s.location, (exact ? QCoreApplication::translate("iec::interp::Compiler",
                                                                     "This FOR loop ends by setting %1 to %2, outside its range %3..%4, which stops the program.")
                                       : QCoreApplication::translate("iec::interp::Compiler",
                                                                     "This FOR loop ends by setting %1 beyond %2, outside its range %3..%4, which stops the program."))
                                    .arg(counter.text).arg(static_cast<qlonglong>(exact ? passing : end.i)).arg(low).arg(high),
                    QCoreApplication::translate("iec::interp::Compiler", "give %1 a type with room for the value that ends the loop").arg(counter.text));
        return;
    }
    const IntRange r = rangeOf(type->elem);
    if (passing > static_cast<Wide128>(r.high) || passing < static_cast<Wide128>(r.low))
        warning(s.location, QCoreApplication::translate("iec::interp::Compiler",
                                                        "This FOR loop never ends: %1 wraps around before it can pass %2.")
                                .arg(counter.text).arg(end.i),
                QCoreApplication::translate("iec::interp::Compiler", "use a larger type than %1 for %2").arg(typeName(type), counter.text));
}

// JMP label; in ST goes to its label anywhere in the body (CODESYS).
void Codegen::resolveStJumps()
{
    for (const auto &[at, jump] : m_stJumps) {
        const auto it = m_stLabels.constFind(key(jump->target.text));
        if (it == m_stLabels.constEnd())
            error(jump->location, QCoreApplication::translate("iec::interp::Compiler", "There is no label %1 to jump to.").arg(jump->target.text));
        else
            patchJump(at, *it);
    }
    m_stJumps.clear();
    m_stLabels.clear();
}

void Codegen::compileStatements(const std::vector<Stmt> &list)
{
    for (const Stmt &s : list)
        compileStatement(s);
}

void Codegen::compileStatement(const Stmt &s)
{
    if (stackExhausted(s.location))
        return;
    markLine(s.location);
    // Temporaries live for one statement; nested statements get their own above.
    const std::uint32_t tempMark = m_tempTop;
    switch (s.kind) {
    case StmtKind::Empty:
        break;
    case StmtKind::Assign: {
        if ((s.target.kind == ExprKind::Member || (s.target.kind == ExprKind::Name && currentClass() >= 0))
            && propertyWrite(s.target, s.value, s.location))
            break; // obj.P := value, through P's setter
        if (s.target.kind == ExprKind::Index) {
            // An element: the value first, so that the element's address and the store can
            // become one instruction.
            const Value value = compileExpr(s.value);
            const Place target = resolvePlace(s.target);
            if (target.kind != Place::Kind::Invalid)
                store(target, value, s.location);
            break;
        }
        const Place target = resolvePlace(s.target);
        if (target.kind == Place::Kind::Invalid)
            break;
        // The last operation of the expression may write straight into the variable.
        // Not for a subrange: the value is checked before it is stored. Otherwise the target
        // still gives literals and generic functions their type (a place that is never written).
        Place typeOnly;
        typeOnly.type = target.kind == Place::Kind::Bit || target.kind == Place::Kind::IndirectBit ? boolType() : target.type;
        const Place *destination = target.kind == Place::Kind::Direct && !target.readOnly && !target.type->subrange ? &target : &typeOnly;
        const Value value = compileExpr(s.value, destination);
        store(target, value, s.location);
        break;
    }
    case StmtKind::Call:
        compileCall(s.target, true);
        break;
    case StmtKind::If: {
        std::vector<std::uint32_t> toEnd;
        for (const ConditionalBlock &branch : s.branches) {
            markLine(branch.location);
            const Value c = condition(branch.condition);
            std::optional<std::uint32_t> skip;
            if (c.kind == Value::Kind::Operand)
                skip = branchIf(c, false);
            else if (c.kind == Value::Kind::Constant && c.constant.i == 0)
                skip = instr(op::Jmp); // IF FALSE: still compiled, never run
            m_tempTop = tempMark;
            compileStatements(branch.body);
            if (&branch != &s.branches.back() || s.hasElse)
                toEnd.push_back(instr(op::Jmp));
            if (skip)
                patchJump(*skip, here());
        }
        if (s.hasElse)
            compileStatements(s.body);
        for (const std::uint32_t j : toEnd)
            patchJump(j, here());
        break;
    }
    case StmtKind::Case: {
        Value selector = compileExpr(s.target);
        if (!selector.valid())
            break;
        if (selector.type->kind != TypeKind::Enum && !(selector.type->kind == TypeKind::Elementary && (info(selector.type->elem).isInt || info(selector.type->elem).isBit))) {
            error(s.target.location, QCoreApplication::translate("iec::interp::Compiler", "CASE needs an integer or an enumeration, not %1.").arg(typeName(selector.type)));
            break;
        }
        std::vector<std::uint32_t> toEnd;
        struct Seen {
            std::int64_t low, high;
            int line;
        };
        std::vector<Seen> seen; // constant labels so far: a value handled twice runs the first branch only
        for (const CaseBranch &branch : s.cases) {
            std::vector<std::uint32_t> toBody;
            for (const CaseLabel &label : branch.labels) {
                const Value low = compileExpr(label.low);
                const Value high = label.high ? compileExpr(*label.high) : low;
                if (low.kind == Value::Kind::Constant && high.kind == Value::Kind::Constant && low.constant.kind == ConstValue::Kind::Int
                    && high.constant.kind == ConstValue::Kind::Int) {
                    for (const Seen &earlier : seen) {
                        if (low.constant.i <= earlier.high && high.constant.i >= earlier.low) {
                            const std::int64_t value = std::max(low.constant.i, earlier.low);
                            QString shown = QString::number(value);
                            for (size_t e = 0; selector.type->kind == TypeKind::Enum && e < selector.type->enumValues.size(); ++e) {
                                if (selector.type->enumValues[e] == value)
                                    shown = selector.type->enumNames[qsizetype(e)];
                            }
                            warning(label.low.location, QCoreApplication::translate("iec::interp::Compiler", "The case value %1 is already handled on line %2; only the first branch runs for it.")
                                                            .arg(shown).arg(earlier.line));
                            break;
                        }
                    }
                    seen.push_back({low.constant.i, high.constant.i, label.low.location.line});
                }
                Value matches;
                if (!label.high) {
                    matches = binary(QStringLiteral("="), selector, low, label.low.location);
                } else {
                    const Value ge = binary(QStringLiteral(">="), selector, low, label.low.location);
                    const Value le = binary(QStringLiteral("<="), selector, high, label.high->location);
                    matches = binary(QStringLiteral("AND"), ge, le, label.low.location);
                }
                // A constant selector (CASE 2 OF, CASE INT#-2 OF) matches or not at compile time.
                if (matches.kind == Value::Kind::Operand)
                    toBody.push_back(branchIf(matches, true));
                else if (matches.kind == Value::Kind::Constant && matches.constant.i != 0)
                    toBody.push_back(instr(op::Jmp));
            }
            const std::uint32_t skip = instr(op::Jmp);
            for (const std::uint32_t j : toBody)
                patchJump(j, here());
            compileStatements(branch.body);
            toEnd.push_back(instr(op::Jmp));
            patchJump(skip, here());
        }
        if (s.hasElse)
            compileStatements(s.body);
        for (const std::uint32_t j : toEnd)
            patchJump(j, here());
        break;
    }
    case StmtKind::For: {
        const Place counter = resolvePlace(s.target);
        if (counter.kind == Place::Kind::Invalid)
            break;
        if (counter.kind != Place::Kind::Direct || counter.type->kind != TypeKind::Elementary || !info(counter.type->elem).isInt) {
            error(s.target.location, QCoreApplication::translate("iec::interp::Compiler", "The FOR loop needs an integer variable as its counter."));
            break;
        }
        const Value start = compileExpr(s.value);
        store(counter, start, s.value.location);
        const Type *type = counter.type;
        // The end and the step are evaluated once, before the loop.
        Value end = coerce(compileExpr(*s.to), type, s.to->location, QCoreApplication::translate("iec::interp::Compiler", "(the end value)"));
        Value step = s.by ? coerce(compileExpr(*s.by), type, s.by->location, QCoreApplication::translate("iec::interp::Compiler", "(the step)")) : Value{};
        if (!end.valid() || (s.by && !step.valid()))
            break;
        if (end.kind == Value::Kind::Operand) {
            const std::uint32_t copy = temp(type);
            emitMove(copy, end.operand, type);
            end = operandValue(copy, type);
        }
        if (!s.by) {
            ConstValue one;
            one.kind = ConstValue::Kind::Int;
            one.i = 1;
            step = constantValue(type, one);
        } else if (step.kind == Value::Kind::Operand) {
            const std::uint32_t copy = temp(type);
            emitMove(copy, step.operand, type);
            step = operandValue(copy, type);
        }
        if (step.kind == Value::Kind::Constant && step.constant.i == 0) {
            error(s.by->location, QCoreApplication::translate("iec::interp::Compiler", "A FOR loop with step 0 never ends."));
            break;
        }
        if (step.kind == Value::Kind::Constant) {
            // The direction is known. A guard skips the loop when it does not start; each round
            // then ends in one instruction that steps the counter and jumps back while it holds.
            const bool up = step.constant.i > 0 && !step.constant.bigUnsigned;
            if (end.kind == Value::Kind::Constant)
                warnForLoopEnd(s, counter, start, end.constant, step.constant, up);
            const std::uint32_t guard = branchIf(binary(up ? QStringLiteral(">") : QStringLiteral("<"), read(counter), end, s.location), true);
            const std::uint32_t top = here();
            markTarget(top);
            m_loops.emplace_back();
            compileStatements(s.body);
            const std::uint32_t continueTarget = here();
            markLine(s.location);
            if (type->subrange) {
                // Every value the counter takes is checked, the one past the end value too (as
                // CODESYS calls its range check on each step): one fused step cannot check.
                store(counter, binary(QStringLiteral("+"), read(counter), step, s.location), s.location);
                branchIf(binary(up ? QStringLiteral("<=") : QStringLiteral(">="), read(counter), end, s.location), true, top);
            } else {
                instr(typedOp(up ? op::IncBrLe : op::IncBrGe, vtOf(*type)), counter.operand, materialize(step), materialize(end), top);
            }
            patchJump(guard, here());
            for (const std::uint32_t j : m_loops.back().exits)
                patchJump(j, here());
            for (const std::uint32_t j : m_loops.back().continues)
                patchJump(j, continueTarget);
            m_loops.pop_back();
            break;
        }
        // A step known only at run time: rotated loop, the test after the body decides by its sign.
        const std::uint32_t toTest = instr(op::Jmp);
        const std::uint32_t top = here();
        m_loops.emplace_back();
        compileStatements(s.body);
        const std::uint32_t continueTarget = here();
        markLine(s.location);
        if (type->subrange)
            store(counter, binary(QStringLiteral("+"), read(counter), step, s.location), s.location);
        else
            binary(QStringLiteral("+"), read(counter), step, s.location, &counter);
        patchJump(toTest, here());
        const Value counterValue = read(counter);
        ConstValue zero;
        zero.kind = ConstValue::Kind::Int;
        const Value up = binary(QStringLiteral(">="), step, constantValue(type, zero), s.location);
        const Value above = binary(QStringLiteral(">"), counterValue, end, s.location);
        const Value below = binary(QStringLiteral("<"), counterValue, end, s.location);
        const Value doneUp = binary(QStringLiteral("AND"), up, above, s.location);
        const Value doneDown = binary(QStringLiteral("AND"), unary(QStringLiteral("NOT"), up, s.location), below, s.location);
        branchIf(binary(QStringLiteral("OR"), doneUp, doneDown, s.location), false, top);
        for (const std::uint32_t j : m_loops.back().exits)
            patchJump(j, here());
        for (const std::uint32_t j : m_loops.back().continues)
            patchJump(j, continueTarget);
        m_loops.pop_back();
        break;
    }
    case StmtKind::While: {
        // Rotated: a guard skips the loop when the condition does not hold at first, then the
        // body, then the test jumps back while it holds (one jump per round). The test is no jump
        // target, so `i := i + s` at the end of the body and a test `i <= n` become one IncBr.
        markLine(s.location);
        const Value first = condition(s.value);
        std::uint32_t guard = UINT32_MAX;
        if (first.kind == Value::Kind::Operand)
            guard = branchIf(first, false);
        else if (first.kind == Value::Kind::Constant && first.constant.i == 0)
            guard = instr(op::Jmp);
        m_tempTop = tempMark;
        const std::uint32_t top = here();
        markTarget(top);
        m_loops.emplace_back();
        compileStatements(s.body);
        const std::uint32_t test = here();
        markLine(s.location); // an endless loop is reported at its WHILE
        m_tempTop = tempMark;
        const Value c = condition(s.value);
        if (c.kind == Value::Kind::Operand) {
            const std::uint32_t back = branchIf(c, true, top);
            if (m_loops.back().continues.empty())
                fuseStepIntoBranch(top, back);
        } else if (c.kind == Value::Kind::Constant && c.constant.i != 0) {
            instr(op::Jmp, top);
        }
        if (guard != UINT32_MAX)
            patchJump(guard, here());
        for (const std::uint32_t j : m_loops.back().exits)
            patchJump(j, here());
        for (const std::uint32_t j : m_loops.back().continues)
            patchJump(j, test);
        m_loops.pop_back();
        break;
    }
    case StmtKind::Repeat: {
        const std::uint32_t top = here();
        m_loops.emplace_back();
        compileStatements(s.body);
        const std::uint32_t continueTarget = here();
        markLine(s.value.location);
        m_tempTop = tempMark;
        const Value c = condition(s.value);
        if (c.kind == Value::Kind::Operand)
            branchIf(c, false, top);
        else if (c.kind == Value::Kind::Constant && c.constant.i == 0)
            instr(op::Jmp, top);
        for (const std::uint32_t j : m_loops.back().exits)
            patchJump(j, here());
        for (const std::uint32_t j : m_loops.back().continues)
            patchJump(j, continueTarget);
        m_loops.pop_back();
        break;
    }
    case StmtKind::Exit:
    case StmtKind::Continue:
        if (m_loops.empty()) {
            error(s.location, QCoreApplication::translate("iec::interp::Compiler", "%1 is only allowed inside a FOR, WHILE or REPEAT loop.").arg(s.kind == StmtKind::Exit ? QStringLiteral("EXIT") : QStringLiteral("CONTINUE")));
            break;
        }
        (s.kind == StmtKind::Exit ? m_loops.back().exits : m_loops.back().continues).push_back(instr(op::Jmp));
        break;
    case StmtKind::Return:
        instr(op::Ret);
        break;
    case StmtKind::RefAssign:
        referenceAssignment(s);
        break;
    case StmtKind::Label:
        if (m_stLabels.contains(key(s.target.text)))
            error(s.location, QCoreApplication::translate("iec::interp::Compiler", "The label %1 is defined twice.").arg(s.target.text));
        m_stLabels.insert(key(s.target.text), here());
        markTarget(here());
        break;
    case StmtKind::Jump:
        m_stJumps.push_back({instr(op::Jmp), &s});
        break;
    }
    m_tempTop = tempMark;
}

} // namespace iec::interp::detail
