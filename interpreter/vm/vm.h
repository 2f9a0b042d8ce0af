#pragma once

#include "interpreter/vm/bytecode.h"

#include <QString>

#include <memory>
#include <optional>

#include <cstdint>
#include <vector>

namespace iec::interp {

// Runs bytecode over one memory image. It allocates nothing while running: the image, the call
// stack and the string scratch buffer are sized when it is created.
class JitProgram;

class Vm
{
public:
    // Translates the module's hot code to machine code unless the JIT is off (jit.h).
    explicit Vm(const Module &module);
    ~Vm();
    Vm(const Vm &) = delete;
    Vm &operator=(const Vm &) = delete;

    // Instructions of the module that run as machine code (0 without the JIT).
    std::size_t nativeInstructions() const;

    std::vector<std::uint8_t> &memory() { return m_memory; }
    const std::vector<std::uint8_t> &memory() const { return m_memory; }

    // The virtual clock, read by op::Now (timers).
    std::int64_t clockNs = 0;
    // How many backward jumps and calls one run() may make before it stops with BudgetExceeded:
    // an endless loop stops the program instead of the host.
    std::uint64_t budgetPerRun = 50'000'000;

    // Messages of op::Log (Beremiz LOGGER) since the runtime last took them: level (0 critical,
    // 1 warning, 2 info, 3 debug) and text. Bounded: a program logging every cycle cannot fill memory.
    struct LogMessage {
        int level = 2;
        QString text;
    };
    std::vector<LogMessage> log;
    static constexpr std::size_t kMaxLog = 1000;

    // Runs from `entry` until Halt (or the outermost Ret). Returns FaultKind::None, or the fault
    // with faultPc() telling where, or FaultKind::Halted when a stop halted it (below).
    FaultKind run(std::uint32_t entry);
    std::uint32_t faultPc() const { return m_faultPc; }

    // Debugging. Stops are pcs the run may halt at: a breakpoint always halts there, a line start
    // only while stepping and at a call depth of at most stepMaxDepth. With stops, runs use a
    // copy of the code holding op::Break at each stop and no JIT; without any, nothing is slower.
    enum StopKind : std::uint8_t { NoStop = 0, BreakpointStop = 1, LineStop = 2 };
    void setStops(std::vector<std::uint8_t> stops); // one per pc (shorter is padded); empty: none
    bool hasStops() const { return !m_debugCode.empty(); }
    std::uint8_t stopAt(std::uint32_t pc) const { return pc < m_stops.size() ? m_stops[pc] : std::uint8_t(NoStop); }
    std::int64_t stepMaxDepth = -1;                 // -1: not stepping
    // After FaultKind::Halted: goes on from the halt, running the halted instruction first.
    FaultKind resume();
    bool isHalted() const { return m_halt.has_value(); }
    void dropHalt() { m_halt.reset(); } // the halted run is abandoned (the runtime went back in time)
    struct HaltedFrame {
        std::uint32_t pc = 0;       // the caller: where it goes on; the innermost: the halt
        std::uint32_t instance = 0; // offset of the instance it runs on
    };
    std::vector<HaltedFrame> haltedFrames() const; // outermost first, the halted one last
    // Without copying the frames: how many callers the halted body has, and where it halted.
    std::size_t haltedDepth() const { return m_halt ? m_halt->callers.size() : 0; }
    HaltedFrame haltedFrame() const { return m_halt ? HaltedFrame{m_halt->pc, m_halt->instance} : HaltedFrame{}; }

private:
    FaultKind execute(std::uint32_t entry, bool resuming);

    const Module &m_module;
    std::unique_ptr<const JitProgram> m_jit;
    std::vector<std::uint8_t> m_memory;
    std::vector<char16_t> m_scratch;
    std::uint32_t m_faultPc = 0;

    std::vector<std::uint8_t> m_stops;
    std::vector<Instr> m_debugCode;
    std::vector<std::uint16_t> m_originalOps; // the debug copy's ops before op::Break went in
    struct Halt {
        std::uint32_t pc = 0;
        std::uint32_t instance = 0;
        std::uint64_t budget = 0;
        std::vector<HaltedFrame> callers;
    };
    std::optional<Halt> m_halt;
};

} // namespace iec::interp
