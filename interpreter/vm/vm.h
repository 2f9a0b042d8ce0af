#pragma once

#include "interpreter/vm/bytecode.h"

#include <QString>

#include <memory>

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
    // with faultPc() telling where.
    FaultKind run(std::uint32_t entry);
    std::uint32_t faultPc() const { return m_faultPc; }

private:
    const Module &m_module;
    std::unique_ptr<const JitProgram> m_jit;
    std::vector<std::uint8_t> m_memory;
    std::vector<char16_t> m_scratch;
    std::uint32_t m_faultPc = 0;
};

} // namespace iec::interp
