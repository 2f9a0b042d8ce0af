// The runtime's debugger: breakpoints, halting mid-scan and going on (debugging.h).
//
// The VM halts at every stop it is given (vm.h); the policy lives here: whether a breakpoint's
// hit count and condition hold, which halts a step wants, and where the halted program stands.
#include "interpreter/runtime/conditionexpression.h"
#include "interpreter/runtime/runtime.h"

#include "interpreter/compiler/types.h"

#include <algorithm>
#include <limits>

namespace iec::interp {

void Runtime::setBreakpoints(std::vector<Breakpoint> breakpoints)
{
    m_breakpoints = std::move(breakpoints);
    m_hits.assign(m_breakpoints.size(), 0);
    if (m_halt && m_halt->breakpoint >= int(m_breakpoints.size()))
        m_halt->breakpoint = -1;
    updateStops(m_vm.stepMaxDepth >= 0 || m_halt.has_value());
}

std::vector<std::uint32_t> Runtime::codeAt(const CodeLocation &at) const
{
    std::vector<std::uint32_t> pcs;
    const bool graphical = at.localId >= 0 || !at.elements.empty();
    bool previousMatched = false;
    for (const LineEntry &entry : m_module->lines) {
        if (entry.line <= 0 && entry.localId < 0)
            continue; // code that is no place (a chart's bookkeeping)
        bool matches = entry.pou >= 0 && m_module->pous[size_t(entry.pou)].name.compare(at.pou, Qt::CaseInsensitive) == 0;
        if (matches && graphical)
            matches = ((at.localId >= 0 && entry.localId == at.localId) || std::ranges::find(at.elements, entry.localId) != at.elements.end());
        else if (matches)
            matches = entry.line == at.line && at.line > 0;
        // A place whose code is interrupted by no other place's (a network of several coils) is
        // reached once: where it starts.
        if (matches && !previousMatched)
            pcs.push_back(entry.pc);
        previousMatched = matches;
    }
    return pcs;
}

// The VM gets stops only while they are wanted: breakpoints, or a halt or step in progress (every
// line start then, so a step can halt at the next one). Otherwise it runs its fast code.
void Runtime::updateStops(bool stepping)
{
    m_breakpointsAtPc.clear();
    bool any = false;
    for (size_t i = 0; i < m_breakpoints.size(); ++i) {
        if (!m_breakpoints[i].enabled)
            continue;
        for (const std::uint32_t pc : codeAt(m_breakpoints[i].at)) {
            if (m_breakpointsAtPc.size() <= pc)
                m_breakpointsAtPc.resize(size_t(pc) + 1);
            m_breakpointsAtPc[pc].push_back(int(i));
            any = true;
        }
    }
    if (!any && !stepping) {
        if (m_vm.hasStops())
            m_vm.setStops({});
        return;
    }
    std::vector<std::uint8_t> stops(m_module->code.size(), Vm::NoStop);
    // Every line start that names a place (a line, an element): the chart's bookkeeping is none.
    for (const LineEntry &entry : m_module->lines)
        if (entry.pc < stops.size() && (entry.line > 0 || entry.localId >= 0))
            stops[entry.pc] |= Vm::LineStop;
    for (size_t pc = 0; pc < m_breakpointsAtPc.size() && pc < stops.size(); ++pc)
        if (!m_breakpointsAtPc[pc].empty())
            stops[pc] |= Vm::BreakpointStop;
    m_vm.setStops(std::move(stops));
}

bool Runtime::resume(ResumeKind kind)
{
    if (m_fault)
        return false;
    const bool stepping = kind != ResumeKind::Continue;
    if (stepping && !m_vm.hasStops())
        updateStops(true);
    const auto depth = std::int64_t(m_vm.haltedDepth());
    switch (kind) {
    case ResumeKind::Continue: m_vm.stepMaxDepth = -1; break;
    case ResumeKind::StepInto: m_vm.stepMaxDepth = std::numeric_limits<std::int64_t>::max(); break;
    case ResumeKind::StepOver: m_vm.stepMaxDepth = m_halt ? depth : std::numeric_limits<std::int64_t>::max(); break;
    case ResumeKind::StepOut: m_vm.stepMaxDepth = m_halt ? depth - 1 : std::numeric_limits<std::int64_t>::max(); break;
    }
    if (!m_halt) {
        beginCycle();
        return runTasksFrom(0);
    }
    m_halt.reset();
    if (!stepping && m_breakpointsAtPc.empty())
        updateStops(false); // without breakpoints the rest runs at full speed
    if (!finishTaskRun(m_vm.resume()))
        return false;
    return runTasksFrom(m_haltedTask + 1);
}

// Goes on past halts the debugger does not want: a breakpoint whose hit count or condition does
// not hold. Returns the kind the run finally ended with.
FaultKind Runtime::passUnwantedHalts(FaultKind kind)
{
    while (kind == FaultKind::Halted) {
        const std::uint32_t pc = m_vm.faultPc();
        const bool stepHalts = m_vm.stepMaxDepth >= 0 && (m_vm.stopAt(pc) & Vm::LineStop)
            && std::int64_t(m_vm.haltedDepth()) <= m_vm.stepMaxDepth;
        // Every breakpoint here counts the hit; the first whose rule and condition hold halts.
        int hit = -1;
        m_conditionProblem.clear();
        if (pc < m_breakpointsAtPc.size())
            for (const int index : m_breakpointsAtPc[pc]) {
                const int hits = ++m_hits[size_t(index)];
                if (hit < 0 && breakpointHolds(index, hits))
                    hit = index;
            }
        if (stepHalts || hit >= 0) {
            m_vm.stepMaxDepth = -1;
            m_halt = describeHalt(hit);
            if (hit >= 0)
                m_halt->conditionProblem = m_conditionProblem;
            return kind;
        }
        kind = m_vm.resume();
    }
    return kind;
}

// Whether the hit rule (for `hits` hits) and the condition hold (an expression that cannot be
// evaluated halts, with the reason in the halt, so a typo does not hide the place).
bool Runtime::breakpointHolds(int index, int hits)
{
    const Breakpoint &b = m_breakpoints[size_t(index)];
    const int target = std::max(1, b.hitTarget);
    bool counted = true;
    switch (b.hitRule) {
    case HitRule::Always: break;
    case HitRule::Equal: counted = hits == target; break;
    case HitRule::MultipleOf: counted = hits % target == 0; break;
    case HitRule::AtLeast: counted = hits >= target; break;
    }
    if (!counted || b.condition.trimmed().isEmpty())
        return counted;
    const Vm::HaltedFrame halted = m_vm.haltedFrame();
    const LineEntry line = m_module->lineAt(halted.pc);
    ConditionScope scope{*m_module, m_vm.memory().data(), {m_images[0].data(), m_images[1].data(), m_images[2].data()},
                         instanceAt(halted.instance, line.pou)};
    const ConditionResult result = evaluateCondition(b.condition, scope);
    m_conditionProblem = result.error;
    return !result.value || *result.value;
}

HaltInfo Runtime::describeHalt(int breakpoint) const
{
    HaltInfo info;
    info.cycle = m_cycle;
    info.breakpoint = breakpoint;
    info.hits = breakpoint >= 0 ? m_hits[size_t(breakpoint)] : 0;
    const std::vector<Vm::HaltedFrame> frames = m_vm.haltedFrames();
    // The outermost frame is the task's own code, which calls the programs: not a body.
    for (size_t i = frames.size() > 1 ? 1 : 0; i < frames.size(); ++i) {
        const Vm::HaltedFrame &frame = frames[i];
        // A caller's pc is where it goes on: the call is the instruction before it.
        const bool halted = i + 1 == frames.size();
        const LineEntry line = m_module->lineAt(halted || frame.pc == 0 ? frame.pc : frame.pc - 1);
        if (line.pou < 0)
            continue;
        StackFrame f;
        f.pou = m_module->pous[size_t(line.pou)].name;
        f.instance = instanceAt(frame.instance, line.pou);
        f.line = line.line;
        f.localId = line.localId;
        info.stack.push_back(f);
    }
    if (!info.stack.empty())
        info.at = {info.stack.back().pou, info.stack.back().line, info.stack.back().localId};
    return info;
}

namespace {

// The path of the function block instance at `offset` below `type` (found: true).
bool findInstance(const Type *type, std::uint32_t base, std::uint32_t offset, const Type *wanted, QString &path, int depth)
{
    if (!type || depth > 16)
        return false;
    for (const Member &m : type->members) {
        if (!m.type || m.byReference || (m.type->kind != TypeKind::FunctionBlock && m.type->kind != TypeKind::Struct))
            continue;
        const std::uint32_t at = base + m.offset;
        if (offset < at || offset >= at + m.type->size)
            continue;
        if (at == offset && m.type == wanted) {
            path += QLatin1Char('.') + m.name;
            return true;
        }
        const int before = int(path.size());
        path += QLatin1Char('.') + m.name;
        if (findInstance(m.type, at, offset, wanted, path, depth + 1))
            return true;
        path.truncate(before);
    }
    return false;
}

} // namespace

// The name of the instance a body runs on: a program, a global or nested function block
// instance (Main.Counter1); empty for functions and when it cannot be told.
QString Runtime::instanceAt(std::uint32_t offset, int pou) const
{
    if (pou < 0)
        return {};
    const CompiledPou &compiled = m_module->pous[size_t(pou)];
    if (compiled.kind == ast::PouKind::Function || !compiled.instanceType)
        return {};
    for (const ProgramInstance &program : m_module->programs)
        if (program.base == offset && m_module->pous[size_t(program.pou)].instanceType == compiled.instanceType)
            return program.name;
    for (const Symbol &symbol : m_module->symbols) {
        if (!symbol.type)
            continue;
        if (symbol.offset == offset && symbol.type == compiled.instanceType)
            return symbol.name;
        QString path = symbol.name;
        if (findInstance(symbol.type, symbol.offset, offset, compiled.instanceType, path, 0))
            return path;
    }
    return {};
}

} // namespace iec::interp
