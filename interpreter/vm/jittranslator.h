#pragma once

#include "interpreter/vm/jitregions.h"
#include "interpreter/vm/x64emitter.h"

#include <map>
#include <optional>
#include <unordered_map>
#include <vector>

// The translation of one JIT region into machine code (see jit.h for the idea). The class is split
// over two files: jittranslator.cpp has the frame (prologue, exits, epilogue), operands, array
// accesses and jumps; jitinstructions.cpp has what each VM instruction becomes.
namespace iec::interp::jit {

using namespace x64;

// Fixed registers while a region runs (see jitregions.cpp cacheableGprs()).
constexpr Reg kMemory = r12;
constexpr Reg kInstance = r13;
constexpr Reg kBudget = r14;
// Where the prologue leaves the pointer to the virtual clock.
inline const Mem kClockSlot{rsp, kNoIndex, 1, 0};

inline Mem memOf(std::uint32_t operand)
{
    return Mem{(operand & kInstanceRelative) ? kInstance : kMemory, kNoIndex, 1, std::int32_t(operand & kOffsetMask)};
}

inline bool fitsInt32(std::int64_t v)
{
    return v >= std::numeric_limits<std::int32_t>::min() && v <= std::numeric_limits<std::int32_t>::max();
}

inline Cond negate(Cond c)
{
    return static_cast<Cond>(c ^ 1); // x86 condition codes come in complementary pairs
}

// 4- and 8-byte integers, which the translation computes at their own width.
inline bool isWord(VT vt)
{
    return !isFloat(vt) && sizeOf(vt) >= 4;
}

// Emits the machine code of one region: a prologue that every entry goes through, one label per
// instruction, out-of-line stubs for exits and faults, and the epilogue that writes the cached
// variables back.
class RegionTranslator
{
public:
    RegionTranslator(const Module &module, Emitter &emitter, const Region &region)
        : m_module(module)
        , m(emitter)
        , m_region(region)
    {
        for (const CachedSlot &slot : region.cache)
            m_cache.emplace(slot.operand, slot);
    }

    bool translate();
    Label prologue() const { return m_prologue; }
    Label labelOf(std::uint32_t pc) const { return m_labels[pc - m_region.begin]; }

private:
    bool instruction(std::uint32_t pc, const Instr &in);
    bool typed(std::uint32_t pc, const Instr &in, const Typed &t);
    void convert(const Instr &in);
    void emitPrologue();
    void emitStubsAndEpilogue();

    // ---- operands ----
    const CachedSlot *cached(std::uint32_t operand) const
    {
        const auto it = m_cache.find(operand);
        return it == m_cache.end() ? nullptr : &it->second;
    }
    void loadInt(Reg dst, std::uint32_t operand, VT vt);
    void loadRaw(Reg dst, std::uint32_t operand, int bytes);
    void storeRaw(std::uint32_t operand, Reg src, int bytes);
    int floatSource(std::uint32_t operand, bool isDouble, int scratch);
    void storeFloat(std::uint32_t operand, int xmm, bool isDouble);
    void loadByte(Reg dst, std::uint32_t operand) { m.load(1, dst, memOf(operand), false); }
    void storeByte(std::uint32_t operand, Reg src)
    {
        m.store(1, memOf(operand), src);
        m_held = HeldByte{operand, src};
    }
    bool carriedIn(std::uint32_t operand, Reg reg) const { return m_carried && m_carried->operand == operand && m_carried->reg == reg; }

    // ---- 4- and 8-byte integers at their own width: the CPU wraps them like the VM ----
    struct Source {
        bool inRegister = false;
        Reg reg = rax;
        Mem mem;
    };
    Source source(std::uint32_t operand) const;
    void aluWith(Emitter::Alu op, bool wide, Reg dst, const Source &s);
    void movFrom(bool wide, Reg dst, const Source &s);
    Reg wordLeft(std::uint32_t operand, bool wide);
    bool wordBinary(const Instr &in, VT vt, std::uint16_t family);
    void wordIncrement(const Instr &in, VT vt);

    // ---- pieces of instructions ----
    void checkIndex(std::uint32_t pc, const IndexDescriptor &dsc, FaultKind kind);
    Mem element(std::uint32_t arrayOperand, const IndexDescriptor &dsc);
    void loadElement(std::uint32_t dst, const Mem &element, int bytes);
    void storeElement(const Mem &element, std::uint32_t src, int bytes);
    void intCompare(std::uint32_t b, std::uint32_t c, VT vt);
    // The condition of `b op c` after a compare; atWidth: a word compared at its own width.
    static Cond intCondition(std::uint16_t family, VT vt, bool atWidth);
    void floatCompareToAl(std::uint16_t family, std::uint32_t b, std::uint32_t c, bool isDouble);
    void divide(std::uint32_t pc, const Instr &in, VT vt, bool modulo);
    void nativeBlock(const Instr &in);
    void rung(std::uint32_t out, std::uint32_t b, std::uint32_t c, std::uint32_t d, std::uint32_t e);
    void branch(std::uint32_t pc, const Cond *condition, std::uint32_t to, bool countsBudget);

    // ---- where control leaves ----
    Label target(std::uint32_t pc);
    Label exitWith(std::uint64_t result);
    Label fault(std::uint32_t pc, FaultKind kind) { return exitWith(std::uint64_t(kind) << 32 | pc); }

    const Module &m_module;
    Emitter &m;
    const Region &m_region;
    std::unordered_map<std::uint32_t, CachedSlot> m_cache;
    std::vector<Label> m_labels;
    std::map<std::uint64_t, Label> m_exits;
    Label m_prologue, m_epilogue;
    // A BOOL the previous instruction stored, still in a register: the next one may read it from
    // there (rung after rung, a load and its test) unless control can also arrive from elsewhere.
    struct HeldByte {
        std::uint32_t operand = 0;
        Reg reg = rax;
    };
    std::optional<HeldByte> m_held, m_carried;
    std::vector<bool> m_joins; // per pc: control may also come from a jump or from outside
};

} // namespace iec::interp::jit
