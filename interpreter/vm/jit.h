#pragma once

#include "interpreter/vm/bytecode.h"

#include <cstdint>
#include <memory>
#include <vector>

// The JIT: translates the hot parts of a module's bytecode into x86-64 machine code.
//
// Why: the interpreter pays about a nanosecond of dispatch per instruction and keeps every
// variable in memory, which makes array kernels 10x slower than C++. The JIT translates each
// *region* - a run of consecutive instructions it knows, typically a whole loop or a long rung
// list - into straight machine code that keeps the region's busiest scalar variables in CPU
// registers. Everything else (calls, strings, pointers, native blocks) stays interpreted.
//
// How it meets the interpreter: the JIT hands the VM a copy of the code in which every place
// where control can enter a region holds op::JitEnter; the VM calls the region there and goes on
// at the pc the region returns. A region behaves exactly like the instructions it replaces:
// same results, same faults with the same pc, same budget of backward jumps (tst_jit compares
// both on every instruction kind and on random programs).
//
// Only on x86-64 (System V); elsewhere, or with IEC_JIT=0 in the environment, compile() returns
// nullptr and the interpreter runs everything.
namespace iec::interp {

// A translated region: runs from `target` (an entry point inside it) with the memory image, the
// running instance, the budget of backward jumps and the virtual clock; returns the pc to go on
// at in the low 32 bits and a FaultKind in the high 32 bits (the pc is then the faulting
// instruction's).
using NativeRegion = std::uint64_t (*)(std::uint8_t *memory, std::uint8_t *instance, std::uint64_t *budget, const void *target,
                                       const std::int64_t *clock);

struct JitEntry {
    NativeRegion region = nullptr;
    const void *target = nullptr;
};

struct JitStats {
    int regions = 0;
    std::size_t instructions = 0; // bytecode instructions translated
    std::size_t bytes = 0;        // machine code
};

class JitProgram
{
public:
    ~JitProgram();
    JitProgram(const JitProgram &) = delete;
    JitProgram &operator=(const JitProgram &) = delete;

    // Translates what it can of `module`; nullptr when nothing was translated or the JIT is off.
    static std::unique_ptr<JitProgram> compile(const Module &module);

    // The module's code with op::JitEnter (a = index into entries()) at every entry point.
    const std::vector<Instr> &code() const { return m_code; }
    const JitEntry &entry(std::uint32_t index) const { return m_entries[index]; }
    const JitStats &stats() const { return m_stats; }

private:
    JitProgram() = default;

    std::vector<Instr> m_code;
    std::vector<JitEntry> m_entries;
    JitStats m_stats;
    void *m_machineCode = nullptr;
    std::size_t m_machineCodeSize = 0;
};

// Whether the JIT is available here and not switched off by IEC_JIT=0.
bool jitEnabled();

} // namespace iec::interp
