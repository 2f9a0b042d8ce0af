// The VM's side of the debugger (vm.h): stops, halting and going on. The halt itself is
// op::Break in Vm::execute (vm.cpp).
#include "interpreter/vm/vm.h"


namespace iec::interp {

FaultKind Vm::run(std::uint32_t entry)
{
    m_halt.reset();
    return execute(entry, false);
}

FaultKind Vm::resume()
{
    if (!m_halt)
        return FaultKind::None;
    return execute(m_halt->pc, true);
}

void Vm::setStops(std::vector<std::uint8_t> stops)
{
    m_stops = std::move(stops);
    m_debugCode.clear();
    m_originalOps.clear();
    if (m_stops.empty())
        return;
    m_stops.resize(m_module.code.size(), NoStop);
    m_debugCode = m_module.code;
    m_originalOps.resize(m_debugCode.size());
    for (size_t pc = 0; pc < m_debugCode.size(); ++pc) {
        Instr &instruction = m_debugCode[pc];
        // A packed rung run would skip a stop inside it: the rungs run one by one instead, the
        // first from its packed record (RungBlock took its instruction's place).
        if (instruction.op == op::RungBlock) {
            const RungRecord &r = m_module.rungs[instruction.b];
            const auto at = [&r](std::int16_t delta) { return static_cast<std::uint32_t>(std::int64_t(r.a) + delta); };
            instruction = {op::BoolAndNotOrAndRel, 0, r.a, at(r.b), at(r.c), at(r.d), at(r.e)};
        }
        m_originalOps[pc] = instruction.op;
        if (m_stops[pc] != NoStop)
            instruction.op = op::Break;
    }
}

std::vector<Vm::HaltedFrame> Vm::haltedFrames() const
{
    if (!m_halt)
        return {};
    std::vector<HaltedFrame> frames = m_halt->callers;
    frames.push_back({m_halt->pc, m_halt->instance});
    return frames;
}


} // namespace iec::interp
