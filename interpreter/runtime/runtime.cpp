#include "interpreter/runtime/runtime.h"

#include <QCoreApplication>

#include <algorithm>
#include <cstring>
#include <limits>

namespace iec::interp {

QString RuntimeFault::toString() const
{
    return QStringLiteral("%1:%2: %3 (cycle %4)").arg(pou).arg(line).arg(message).arg(cycle);
}

Runtime::Runtime(std::shared_ptr<const Module> module, std::int64_t cycleNs)
    : m_module(std::move(module))
    , m_vm(*m_module)
    , m_cycleNs(cycleNs)
{
    for (int area = 0; area < 3; ++area)
        m_images[area].assign(m_module->imageSizes[area] + 1, 0);
    coldRestart();
}

void Runtime::coldRestart()
{
    m_vm.memory() = m_module->initialImage;
    m_timeNs = 0;
    m_cycle = 0;
    m_fault.reset();
    m_halt.reset();
    m_vm.stepMaxDepth = -1;
    m_nextDue.assign(m_module->tasks.size(), 0);
    m_singleBefore.assign(m_module->tasks.size(), false);
}

void Runtime::warmRestart()
{
    std::vector<std::uint8_t> kept = m_vm.memory();
    coldRestart();
    for (const RetainRange &r : m_module->retain)
        std::memcpy(m_vm.memory().data() + r.offset, kept.data() + r.offset, r.size);
}

std::vector<std::uint8_t> &Runtime::image(char area)
{
    return m_images[area == 'I' ? 0 : area == 'Q' ? 1 : 2];
}

const std::vector<std::uint8_t> &Runtime::image(char area) const
{
    return m_images[area == 'I' ? 0 : area == 'Q' ? 1 : 2];
}

RuntimeState Runtime::state() const
{
    RuntimeState state;
    copyStateTo(state);
    return state;
}

void Runtime::copyStateTo(RuntimeState &into) const
{
    into.memory.assign(m_vm.memory().begin(), m_vm.memory().end());
    for (int area = 0; area < 3; ++area)
        into.images[area].assign(m_images[area].begin(), m_images[area].end());
    into.timeNs = m_timeNs;
    into.cycle = m_cycle;
    into.nextDue = m_nextDue;
    into.singleBefore = m_singleBefore;
}

void Runtime::restore(const RuntimeState &state)
{
    m_vm.dropHalt();
    m_halt.reset();
    m_fault.reset();
    m_vm.stepMaxDepth = -1;
    m_vm.memory() = state.memory;
    for (int area = 0; area < 3; ++area)
        m_images[area] = state.images[area];
    m_timeNs = state.timeNs;
    m_cycle = state.cycle;
    m_nextDue = state.nextDue;
    m_singleBefore = state.singleBefore;
}

// The process image is part of the memory image (Module::imageBase): the input area is copied
// in before the tasks run, the output and marker areas out after them.
void Runtime::copyInputs()
{
    const std::vector<std::uint8_t> &inputs = image('I');
    std::memcpy(m_vm.memory().data() + m_module->imageBase[0], inputs.data(), m_module->imageSizes[0]);
}

void Runtime::copyOutputs()
{
    const std::uint8_t *memory = m_vm.memory().data();
    for (const int area : {1, 2})
        std::memcpy(m_images[area].data(), memory + m_module->imageBase[area], m_module->imageSizes[area]);
}

void Runtime::applyForces()
{
    for (const Force &f : m_forces)
        writeLiteral(f.ref, f.literal, m_vm.memory().data(), image(f.ref.imageArea ? f.ref.imageArea : 'M').data());
}

bool Runtime::runCycle()
{
    if (m_fault)
        return false;
    if (m_halt)
        return resume(ResumeKind::Continue);
    // A cycle of its own is no step: a step that ended the last cycle does not halt this one.
    m_vm.stepMaxDepth = -1;
    beginCycle();
    return runTasksFrom(0);
}

void Runtime::beginCycle()
{
    ++m_cycle;
    applyForces();
    copyInputs();
    applyForces();
    m_vm.clockNs = m_timeNs;
}

bool Runtime::taskIsDue(size_t t)
{
    const TaskInfo &task = m_module->tasks[t];
    if (task.singleOffset >= 0) {
        const bool now = m_vm.memory()[size_t(task.singleOffset)] != 0;
        const bool due = now && !m_singleBefore[t];
        m_singleBefore[t] = now;
        return due;
    }
    if (task.intervalNs > 0) {
        if (m_timeNs < m_nextDue[t])
            return false;
        m_nextDue[t] += task.intervalNs * std::max<std::int64_t>(1, (m_timeNs - m_nextDue[t]) / task.intervalNs + 1);
    }
    return true;
}

// Runs the due tasks from `first` on and ends the cycle; false when a task halted or faulted.
bool Runtime::runTasksFrom(size_t first)
{
    for (size_t t = first; t < m_module->tasks.size(); ++t) {
        if (!taskIsDue(t))
            continue;
        m_haltedTask = t;
        if (!finishTaskRun(m_vm.run(m_module->tasks[t].entry)))
            return false;
    }
    endCycle();
    return true;
}

// What a task run ended with: a halt the debugger keeps (false), a fault (false), or the end.
bool Runtime::finishTaskRun(FaultKind kind)
{
    kind = passUnwantedHalts(kind);
    if (kind == FaultKind::Halted)
        return false;
    if (kind != FaultKind::None) {
        const LineEntry line = m_module->lineAt(m_vm.faultPc());
        RuntimeFault fault;
        fault.kind = kind;
        fault.pou = line.pou >= 0 ? m_module->pous[size_t(line.pou)].name : QString();
        fault.line = line.line;
        fault.cycle = m_cycle;
        fault.message = faultMessage(kind);
        m_fault = fault;
        return false;
    }
    // A step that left the program's body halts at the next line run, wherever it is.
    if (m_vm.stepMaxDepth >= 0)
        m_vm.stepMaxDepth = std::numeric_limits<std::int64_t>::max();
    return true;
}

void Runtime::endCycle()
{
    for (Vm::LogMessage &message : m_vm.log) {
        if (m_log.size() < Vm::kMaxLog)
            m_log.push_back({m_cycle, message.level, std::move(message.text)});
    }
    m_vm.log.clear();
    applyForces();
    copyOutputs();
    applyForces(); // a forced %Q address wins over the variable mapped to it
    m_timeNs += m_cycleNs;
}

std::vector<Runtime::LogEntry> Runtime::takeLog()
{
    std::vector<LogEntry> taken;
    taken.swap(m_log);
    return taken;
}

QString Runtime::LogEntry::toString() const
{
    static const char *const levels[] = {"CRITICAL", "WARNING", "INFO", "DEBUG"};
    return QStringLiteral("%1: %2 (cycle %3)").arg(QLatin1String(levels[std::clamp(level, 0, 3)]), text).arg(cycle);
}

bool Runtime::runCycles(int count)
{
    for (int i = 0; i < count; ++i) {
        if (!runCycle())
            return false;
    }
    return true;
}

std::optional<QString> Runtime::read(const QString &name) const
{
    const auto ref = find(name);
    if (!ref)
        return std::nullopt;
    return read(*ref);
}

QString Runtime::read(const VariableRef &ref) const
{
    const int area = ref.imageArea == 'I' ? 0 : ref.imageArea == 'Q' ? 1 : 2;
    return formatValue(ref, m_vm.memory().data(), m_images[area].data());
}

std::optional<QString> Runtime::write(const QString &name, const QString &literal)
{
    const auto ref = find(name);
    if (!ref)
        return QCoreApplication::translate("iec::interp::Runtime", "There is no variable called %1.").arg(name);
    return writeLiteral(*ref, literal, m_vm.memory().data(), image(ref->imageArea ? ref->imageArea : 'M').data());
}

std::optional<QString> Runtime::force(const QString &name, const QString &literal)
{
    if (auto problem = write(name, literal))
        return problem;
    unforce(name);
    m_forces.push_back({name, *find(name), literal});
    return std::nullopt;
}

void Runtime::unforce(const QString &name)
{
    std::erase_if(m_forces, [&](const Force &f) { return f.name.compare(name, Qt::CaseInsensitive) == 0; });
}

} // namespace iec::interp
