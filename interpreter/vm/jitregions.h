#pragma once

#include "interpreter/vm/bytecode.h"

#include <cstdint>
#include <optional>
#include <vector>

// What the JIT (jit.h) knows about bytecode: which instructions it translates, which memory each
// one touches, and how the code splits into regions with their register-cached variables.
namespace iec::interp::jit {

// How an operand's bytes are used, which decides whether a register may hold them.
enum class Use : std::uint8_t {
    Int,   // an integer of the operand's size
    Float, // REAL or LREAL
    Raw,   // copied as bytes (Mov, array element), whatever they mean
    Byte,  // BOOL and other single bytes: never kept in a register
};

struct Access {
    std::uint32_t operand = 0; // as in Instr: offset, with kInstanceRelative for the instance
    std::uint8_t bytes = 0;
    Use use = Use::Int;
    bool write = false;
};

// The bytes an indexed access may touch: the whole array at `operand`.
struct ArrayAccess {
    std::uint32_t operand = 0;
    std::uint64_t bytes = 0;
};

struct Footprint {
    std::vector<Access> accesses;
    std::vector<ArrayAccess> arrays;
    bool callsOut = false; // calls C++ (a native block), which may change caller-saved registers
};

// True if the JIT translates `instr`; then `out` receives what it reads and writes.
bool describe(const Module &module, const Instr &instr, Footprint &out);

// Where an instruction may jump (any instruction, translated or not).
std::optional<std::uint32_t> jumpTarget(const Instr &instr);

// The typed family (op::Add, ...) and VT of a typed opcode.
struct Typed {
    std::uint16_t family = 0;
    VT vt = VT::I8;
};
std::optional<Typed> typedOf(std::uint16_t opcode);
std::uint8_t sizeOf(VT vt);
bool isFloat(VT vt);
bool isSignedInt(VT vt);

// A variable a region keeps in a register while it runs.
struct CachedSlot {
    std::uint32_t operand = 0;
    std::uint8_t bytes = 0;
    bool isFloat = false;
    bool written = false; // stored back when the region exits
    int reg = 0;          // a general register (x64::Reg) or an xmm number
};

struct Region {
    std::uint32_t begin = 0, end = 0;  // [begin, end) of the code
    std::vector<std::uint32_t> entries; // pcs where control may come in, begin first
    std::vector<CachedSlot> cache;
    bool callsOut = false;
};

// Registers the translation may use for cached slots; the rest are its scratch and fixed state.
// The first kCalleeSavedGprs survive calls to C++; regions that call out use only those.
constexpr std::size_t kCalleeSavedGprs = 3;
const std::vector<int> &cacheableGprs();
const std::vector<int> &cacheableXmms();

// The regions worth translating: runs of translatable instructions that hold a loop or are long
// enough to beat the cost of entering native code.
std::vector<Region> findRegions(const Module &module);

} // namespace iec::interp::jit
