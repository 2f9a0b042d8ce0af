#include "interpreter/vm/jit.h"

#include "interpreter/vm/jitregions.h"
#include "interpreter/vm/nativeblocks.h"
#include "interpreter/vm/x64emitter.h"

#include <QtGlobal>

#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <unordered_map>

#if defined(__x86_64__) && defined(__linux__)
#include <sys/mman.h>
#define IEC_JIT_X64 1
#endif

namespace iec::interp {

bool jitEnabled()
{
#ifdef IEC_JIT_X64
    return qEnvironmentVariable("IEC_JIT") != QLatin1String("0");
#else
    return false;
#endif
}

namespace {

using namespace x64;
using jit::CachedSlot;
using jit::Region;

// Fixed registers while a region runs (see jitregions.cpp cacheableGprs()).
constexpr Reg kMemory = r12;
constexpr Reg kInstance = r13;
constexpr Reg kBudget = r14;

// What a region calls for op::NativeFb: one plain function per block, so the block's switch folds.
template<NativeBlock block>
void runNativeBlockFromJit(std::uint8_t *instance, std::int64_t now)
{
    runNativeBlock(block, instance, now);
}

std::uintptr_t nativeBlockFunction(std::uint16_t block)
{
    switch (static_cast<NativeBlock>(block)) {
    case NativeBlock::Ton: return reinterpret_cast<std::uintptr_t>(&runNativeBlockFromJit<NativeBlock::Ton>);
    case NativeBlock::Tof: return reinterpret_cast<std::uintptr_t>(&runNativeBlockFromJit<NativeBlock::Tof>);
    case NativeBlock::Tp: break;
    }
    return reinterpret_cast<std::uintptr_t>(&runNativeBlockFromJit<NativeBlock::Tp>);
}

// Where the prologue leaves the pointer to the virtual clock.
const Mem kClockSlot{rsp, kNoIndex, 1, 0};

Mem memOf(std::uint32_t operand)
{
    return Mem{(operand & kInstanceRelative) ? kInstance : kMemory, kNoIndex, 1, std::int32_t(operand & kOffsetMask)};
}

bool fitsInt32(std::int64_t v)
{
    return v >= std::numeric_limits<std::int32_t>::min() && v <= std::numeric_limits<std::int32_t>::max();
}

Cond negate(Cond c)
{
    return static_cast<Cond>(c ^ 1); // x86 condition codes come in complementary pairs
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
    bool typed(std::uint32_t pc, const Instr &in, const jit::Typed &t);
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
    Cond intCondition(std::uint16_t family, VT vt) const;
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
    bool m_compareAtWidth = false; // set around a word compare, read by intCondition()
};

bool RegionTranslator::translate()
{
    m_prologue = m.newLabel();
    m_epilogue = m.newLabel();
    m_joins.assign(m_region.end - m_region.begin, false);
    for (std::uint32_t pc = m_region.begin; pc < m_region.end; ++pc)
        m_labels.push_back(m.newLabel());
    for (std::uint32_t pc : m_region.entries)
        m_joins[pc - m_region.begin] = true;
    emitPrologue();
    for (std::uint32_t pc = m_region.begin; pc < m_region.end; ++pc) {
        m.bind(labelOf(pc));
        m_carried = m_joins[pc - m_region.begin] ? std::nullopt : m_held;
        m_held.reset();
        if (!instruction(pc, m_module.code[pc]))
            return false;
    }
    m.jmp(target(m_region.end)); // falling off the end: the interpreter goes on there
    emitStubsAndEpilogue();
    return true;
}

void RegionTranslator::emitPrologue()
{
    // NativeRegion(memory = rdi, instance = rsi, budget = rdx, target = rcx, clock = r8), System V.
    // Eight pushes after the return address keep rsp 16-byte aligned for calls to C++.
    m.bind(m_prologue);
    for (Reg r : {rbx, rbp, r12, r13, r14, r15})
        m.push(r);
    m.push(rdx);
    m.push(r8);
    m.push(r8);
    m.movRR(true, kMemory, rdi);
    m.movRR(true, kInstance, rsi);
    m.load(8, kBudget, Mem{rdx, kNoIndex, 1, 0}, false);
    for (const CachedSlot &slot : m_region.cache) {
        if (slot.isFloat)
            m.fload(slot.bytes == 8, slot.reg, memOf(slot.operand));
        else
            m.load(slot.bytes, Reg(slot.reg), memOf(slot.operand), false);
    }
    m.jmpReg(rcx);
}

void RegionTranslator::emitStubsAndEpilogue()
{
    for (const auto &[result, label] : m_exits) {
        m.bind(label);
        m.movImm(rax, std::int64_t(result));
        m.jmp(m_epilogue);
    }
    m.bind(m_epilogue);
    for (const CachedSlot &slot : m_region.cache) {
        if (!slot.written)
            continue;
        if (slot.isFloat)
            m.fstore(slot.bytes == 8, memOf(slot.operand), slot.reg);
        else
            m.store(slot.bytes, memOf(slot.operand), Reg(slot.reg));
    }
    m.pop(rcx); // the clock, twice
    m.pop(rcx);
    m.pop(rcx);
    m.store(8, Mem{rcx, kNoIndex, 1, 0}, kBudget);
    for (Reg r : {r15, r14, r13, r12, rbp, rbx})
        m.pop(r);
    m.ret();
}

Label RegionTranslator::exitWith(std::uint64_t result)
{
    const auto it = m_exits.find(result);
    if (it != m_exits.end())
        return it->second;
    const Label label = m.newLabel();
    m_exits.emplace(result, label);
    return label;
}

Label RegionTranslator::target(std::uint32_t pc)
{
    if (pc >= m_region.begin && pc < m_region.end)
        return labelOf(pc);
    return exitWith(pc);
}

// ---- operands -------------------------------------------------------------------------------

// dst = the integer operand, extended to 64 bits as its type says, so that one 64-bit compare
// or add serves every integer type.
void RegionTranslator::loadInt(Reg dst, std::uint32_t operand, VT vt)
{
    const int bytes = jit::sizeOf(vt);
    const bool sign = jit::isSignedInt(vt);
    if (const CachedSlot *slot = cached(operand)) {
        if (bytes == 8)
            m.movRR(true, dst, Reg(slot->reg));
        else if (sign)
            m.movsxdRR(dst, Reg(slot->reg));
        else
            m.movRR(false, dst, Reg(slot->reg));
        return;
    }
    m.load(bytes, dst, memOf(operand), sign);
}

void RegionTranslator::loadRaw(Reg dst, std::uint32_t operand, int bytes)
{
    if (const CachedSlot *slot = cached(operand)) {
        if (slot->isFloat)
            m.movXmmToGpr(bytes == 8, dst, slot->reg);
        else
            m.movRR(bytes == 8, dst, Reg(slot->reg));
        return;
    }
    m.load(bytes, dst, memOf(operand), false);
}

void RegionTranslator::storeRaw(std::uint32_t operand, Reg src, int bytes)
{
    if (const CachedSlot *slot = cached(operand)) {
        if (slot->isFloat)
            m.movGprToXmm(bytes == 8, slot->reg, src);
        else
            m.movRR(bytes == 8, Reg(slot->reg), src);
        return;
    }
    m.store(bytes, memOf(operand), src);
}

// The xmm register holding a REAL/LREAL operand: its cache register, or `scratch` loaded.
int RegionTranslator::floatSource(std::uint32_t operand, bool isDouble, int scratch)
{
    if (const CachedSlot *slot = cached(operand))
        return slot->reg;
    m.fload(isDouble, scratch, memOf(operand));
    return scratch;
}

void RegionTranslator::storeFloat(std::uint32_t operand, int xmm, bool isDouble)
{
    if (const CachedSlot *slot = cached(operand)) {
        if (slot->reg != xmm)
            m.fmovRR(slot->reg, xmm);
        return;
    }
    m.fstore(isDouble, memOf(operand), xmm);
}

// ---- words ----------------------------------------------------------------------------------

bool isWord(VT vt)
{
    return !jit::isFloat(vt) && jit::sizeOf(vt) >= 4;
}

RegionTranslator::Source RegionTranslator::source(std::uint32_t operand) const
{
    if (const CachedSlot *slot = cached(operand); slot && !slot->isFloat)
        return Source{true, Reg(slot->reg), {}};
    return Source{false, rax, memOf(operand)};
}

void RegionTranslator::aluWith(Emitter::Alu op, bool wide, Reg dst, const Source &s)
{
    if (s.inRegister)
        m.alu(op, wide, dst, s.reg);
    else
        m.aluMem(op, wide, dst, s.mem);
}

void RegionTranslator::movFrom(bool wide, Reg dst, const Source &s)
{
    if (!s.inRegister)
        m.load(wide ? 8 : 4, dst, s.mem, false);
    else if (s.reg != dst)
        m.movRR(wide, dst, s.reg);
}

// A register holding the operand: its cache register, or rax loaded.
Reg RegionTranslator::wordLeft(std::uint32_t operand, bool wide)
{
    const Source s = source(operand);
    if (s.inRegister)
        return s.reg;
    movFrom(wide, rax, s);
    return rax;
}

// a = b op c straight into a's register when it has one.
bool RegionTranslator::wordBinary(const Instr &in, VT vt, std::uint16_t family)
{
    using Alu = Emitter::Alu;
    if (family != op::Add && family != op::Sub && family != op::And && family != op::Or && family != op::Xor && family != op::Mul)
        return false;
    const bool wide = jit::sizeOf(vt) == 8;
    const CachedSlot *dst = cached(in.a);
    const bool cIsDst = in.c == in.a && in.b != in.a;
    const Reg r = dst && !dst->isFloat && !cIsDst ? Reg(dst->reg) : rax;
    movFrom(wide, r, source(in.b));
    const Source c = source(in.c);
    switch (family) {
    case op::Add: aluWith(Alu::Add, wide, r, c); break;
    case op::Sub: aluWith(Alu::Sub, wide, r, c); break;
    case op::And: aluWith(Alu::And, wide, r, c); break;
    case op::Or: aluWith(Alu::Or, wide, r, c); break;
    case op::Xor: aluWith(Alu::Xor, wide, r, c); break;
    default: c.inRegister ? m.imul(wide, r, c.reg) : m.imulMem(wide, r, c.mem); break; // Mul
    }
    if (r == rax)
        storeRaw(in.a, rax, jit::sizeOf(vt));
    return true;
}

// a += b, then flags from comparing a with c (the IncBr family).
void RegionTranslator::wordIncrement(const Instr &in, VT vt)
{
    const bool wide = jit::sizeOf(vt) == 8;
    const Source a = source(in.a);
    const Reg r = a.inRegister ? a.reg : rax;
    movFrom(wide, r, a);
    aluWith(Emitter::Alu::Add, wide, r, source(in.b));
    if (!a.inRegister)
        m.store(wide ? 8 : 4, a.mem, rax);
    aluWith(Emitter::Alu::Cmp, wide, r, source(in.c));
}

// ---- arrays ---------------------------------------------------------------------------------

// rax holds the index as read; leaves rax = index - low, faulting unless 0 <= it < count.
void RegionTranslator::checkIndex(std::uint32_t pc, const IndexDescriptor &dsc, FaultKind kind)
{
    if (dsc.low != 0) {
        if (fitsInt32(dsc.low)) {
            m.aluImm(Emitter::Alu::Sub, true, rax, std::int32_t(dsc.low));
        } else {
            m.movImm(rdx, dsc.low);
            m.alu(Emitter::Alu::Sub, true, rax, rdx);
        }
    }
    if (fitsInt32(dsc.count)) {
        m.aluImm(Emitter::Alu::Cmp, true, rax, std::int32_t(dsc.count));
    } else {
        m.movImm(rdx, dsc.count);
        m.alu(Emitter::Alu::Cmp, true, rax, rdx);
    }
    m.jcc(AE, fault(pc, kind)); // unsigned: a negative offset is huge
}

Mem RegionTranslator::element(std::uint32_t arrayOperand, const IndexDescriptor &dsc)
{
    Mem e = memOf(arrayOperand);
    e.index = rax;
    if (dsc.stride == 1 || dsc.stride == 2 || dsc.stride == 4 || dsc.stride == 8) {
        e.scale = int(dsc.stride);
    } else {
        m.imulImm(true, rax, rax, std::int32_t(dsc.stride));
        e.scale = 1;
    }
    return e;
}

void RegionTranslator::loadElement(std::uint32_t dst, const Mem &element, int bytes)
{
    if (const CachedSlot *slot = cached(dst)) {
        if (slot->isFloat)
            m.fload(bytes == 8, slot->reg, element);
        else
            m.load(bytes, Reg(slot->reg), element, false);
        return;
    }
    m.load(bytes, rcx, element, false);
    m.store(bytes, memOf(dst), rcx);
    if (bytes == 1)
        m_held = HeldByte{dst, rcx};
}

void RegionTranslator::storeElement(const Mem &element, std::uint32_t src, int bytes)
{
    if (const CachedSlot *slot = cached(src)) {
        if (slot->isFloat)
            m.fstore(bytes == 8, element, slot->reg);
        else
            m.store(bytes, element, Reg(slot->reg));
        return;
    }
    m.load(bytes, rcx, memOf(src), false);
    m.store(bytes, element, rcx);
}

// ---- comparisons and jumps ------------------------------------------------------------------

void RegionTranslator::intCompare(std::uint32_t b, std::uint32_t c, VT vt)
{
    loadInt(rax, b, vt);
    loadInt(rcx, c, vt);
    m.alu(Emitter::Alu::Cmp, true, rax, rcx);
}

// The condition of `b op c` after intCompare. Values are extended to 64 bits by their type, so
// only ULINT/LWORD compare unsigned.
Cond RegionTranslator::intCondition(std::uint16_t family, VT vt) const
{
    // Words (isWord) are compared at their own width instead: UDINT/DWORD unsigned too.
    const bool u = vt == VT::U64 || (vt == VT::U32 && m_compareAtWidth);
    switch (family) {
    case op::Eq: case op::BrEq: return E;
    case op::Ne: case op::BrNe: return NE;
    case op::Lt: case op::BrLt: case op::IncBrLt: return u ? B : L;
    case op::Le: case op::BrLe: case op::IncBrLe: return u ? BE : LE;
    case op::Gt: case op::BrGt: case op::IncBrGt: return u ? A : G;
    default: return u ? AE : GE; // Ge, BrGe, IncBrGe
    }
}

// al (and all of rax) = b op c for reals, with C++'s answers for NaN: only <> is true.
void RegionTranslator::floatCompareToAl(std::uint16_t family, std::uint32_t b, std::uint32_t c, bool isDouble)
{
    const int x = floatSource(b, isDouble, 0);
    const int y = floatSource(c, isDouble, 1);
    switch (family) {
    case op::Eq: case op::BrEq:
        m.fcompare(isDouble, x, y);
        m.setcc(E, rax);
        m.setcc(NP, rcx);
        m.alu(Emitter::Alu::And, false, rax, rcx);
        break;
    case op::Ne: case op::BrNe:
        m.fcompare(isDouble, x, y);
        m.setcc(NE, rax);
        m.setcc(P, rcx);
        m.alu(Emitter::Alu::Or, false, rax, rcx);
        break;
    case op::Lt: case op::BrLt: m.fcompare(isDouble, y, x); m.setcc(A, rax); break;
    case op::Le: case op::BrLe: m.fcompare(isDouble, y, x); m.setcc(AE, rax); break;
    case op::Gt: case op::BrGt: m.fcompare(isDouble, x, y); m.setcc(A, rax); break;
    default: m.fcompare(isDouble, x, y); m.setcc(AE, rax); break;
    }
    m.movzx8(rax, rax);
}

// A jump to `to`, if `condition` (when given) holds. Backward jumps and loop steps count against
// the budget like the interpreter's, and fault at this pc when it runs out.
void RegionTranslator::branch(std::uint32_t pc, const Cond *condition, std::uint32_t to, bool countsBudget)
{
    if (!countsBudget) {
        if (condition)
            m.jcc(*condition, target(to));
        else
            m.jmp(target(to));
        return;
    }
    const Label skip = m.newLabel();
    if (condition)
        m.jcc(negate(*condition), skip);
    m.aluImm(Emitter::Alu::Sub, true, kBudget, 1);
    m.jcc(NE, target(to)); // the loop goes on: one taken branch per turn
    m.jmp(fault(pc, FaultKind::BudgetExceeded));
    m.bind(skip);
}

// ---- instructions ---------------------------------------------------------------------------

void RegionTranslator::divide(std::uint32_t pc, const Instr &in, VT vt, bool modulo)
{
    const bool wide = jit::sizeOf(vt) == 8;
    loadInt(rax, in.b, vt);
    loadInt(rcx, in.c, vt);
    m.test(true, rcx, rcx);
    m.jcc(E, fault(pc, FaultKind::DivisionByZero));
    if (jit::isSignedInt(vt)) {
        // MIN / -1 traps on x86; the VM wraps it (vm.cpp divide()): a / -1 is -a, a MOD -1 is 0.
        const Label normal = m.newLabel(), done = m.newLabel();
        m.aluImm(Emitter::Alu::Cmp, true, rcx, -1);
        m.jcc(NE, normal);
        if (modulo)
            m.alu(Emitter::Alu::Xor, false, rdx, rdx); // the remainder, taken from rdx below
        else
            m.neg(true, rax);
        m.jmp(done);
        m.bind(normal);
        m.signExtendAcc(wide);
        m.div(wide, true, rcx);
        m.bind(done);
    } else {
        m.alu(Emitter::Alu::Xor, false, rdx, rdx);
        m.div(wide, false, rcx);
    }
    if (modulo)
        m.movRR(true, rax, rdx);
    storeRaw(in.a, rax, jit::sizeOf(vt));
}

void RegionTranslator::rung(std::uint32_t out, std::uint32_t b, std::uint32_t c, std::uint32_t d, std::uint32_t e)
{
    // out = (b AND NOT c) OR (d AND e), as op::BoolAndNotOrAnd. The branch d AND e first: in a
    // rung list its input is often the previous rung's output, still in al.
    if (carriedIn(d, rax))
        m.movzx8(rcx, rax);
    else
        loadByte(rcx, d);
    if (carriedIn(e, rax))
        m.alu8(Emitter::Alu::And, rcx, rax);
    else
        m.aluMem8(Emitter::Alu::And, rcx, memOf(e));
    loadByte(rax, c);
    m.aluImm(Emitter::Alu::Xor, false, rax, 1);
    m.aluMem8(Emitter::Alu::And, rax, memOf(b));
    m.alu(Emitter::Alu::Or, false, rax, rcx);
    storeByte(out, rax);
}

// op::NativeFb / op::NativeFbArgs: a call to the same C++ as the interpreter's. Regions that call
// out keep values only in callee-saved registers (jitregions.cpp), so nothing needs saving here.
void RegionTranslator::nativeBlock(const Instr &in)
{
    const Mem instance = memOf(in.a);
    const auto field = [&](std::int32_t offset) { return Mem{instance.base, kNoIndex, 1, instance.disp + offset}; };
    if (in.op == op::NativeFbArgs) {
        loadByte(rax, in.b);
        m.store(1, field(0), rax); // IN
        loadRaw(rax, in.c, 8);
        m.store(8, field(8), rax); // PT
    }
    m.lea(rdi, instance);
    m.load(8, rax, kClockSlot, false);
    m.load(8, rsi, Mem{rax, kNoIndex, 1, 0}, false);
    m.movImm(rax, std::int64_t(nativeBlockFunction(in.aux)));
    m.callReg(rax);
    if (in.op == op::NativeFbArgs && in.e != 0) {
        m.load(1, rax, field(16), false); // Q
        storeByte(in.e, rax);
    }
}

void RegionTranslator::convert(const Instr &in)
{
    const int n = in.op - op::Convert;
    const VT from = static_cast<VT>(n / kVtCount), to = static_cast<VT>(n % kVtCount);
    if (!jit::isFloat(from) && !jit::isFloat(to)) {
        loadInt(rax, in.b, from); // the low bytes of the extended value are static_cast<To>
        storeRaw(in.a, rax, jit::sizeOf(to));
    } else if (!jit::isFloat(from)) {
        loadInt(rax, in.b, from);
        m.cvtIntToFloat(to == VT::F64, true, 0, rax);
        storeFloat(in.a, 0, to == VT::F64);
    } else if (from == to) {
        storeFloat(in.a, floatSource(in.b, from == VT::F64, 0), from == VT::F64);
    } else {
        const int x = floatSource(in.b, from == VT::F64, 0);
        m.cvtFloatToFloat(to == VT::F64, 0, x);
        storeFloat(in.a, 0, to == VT::F64);
    }
}

bool RegionTranslator::typed(std::uint32_t pc, const Instr &in, const jit::Typed &t)
{
    const VT vt = t.vt;
    const bool real = jit::isFloat(vt), dbl = vt == VT::F64;
    const int n = jit::sizeOf(vt);
    using Alu = Emitter::Alu;
    using Fop = Emitter::Fop;
    const auto floatBinary = [&](Fop fop) {
        const int x = floatSource(in.b, dbl, 0);
        if (x != 0)
            m.fmovRR(0, x);
        m.fop(fop, dbl, 0, floatSource(in.c, dbl, 1));
        storeFloat(in.a, 0, dbl);
    };
    const auto intBinary = [&](Alu alu) {
        loadInt(rax, in.b, vt);
        loadInt(rcx, in.c, vt);
        m.alu(alu, true, rax, rcx);
        storeRaw(in.a, rax, n);
    };
    if (isWord(vt)) {
        if (wordBinary(in, vt, t.family))
            return true;
        const bool wide = n == 8;
        m_compareAtWidth = true;
        switch (t.family) {
        case op::Eq: case op::Ne: case op::Lt: case op::Le: case op::Gt: case op::Ge:
            aluWith(Alu::Cmp, wide, wordLeft(in.b, wide), source(in.c));
            m.setcc(intCondition(t.family, vt), rax);
            storeByte(in.a, rax);
            m_compareAtWidth = false;
            return true;
        case op::BrEq: case op::BrNe: case op::BrLt: case op::BrLe: case op::BrGt: case op::BrGe: {
            aluWith(Alu::Cmp, wide, wordLeft(in.b, wide), source(in.c));
            const Cond cond = intCondition(t.family, vt);
            m_compareAtWidth = false;
            branch(pc, &cond, in.a, in.a <= pc);
            return true;
        }
        case op::IncBrLe: case op::IncBrGe: case op::IncBrLt: case op::IncBrGt: {
            wordIncrement(in, vt);
            const Cond cond = intCondition(t.family, vt);
            m_compareAtWidth = false;
            branch(pc, &cond, in.d, true);
            return true;
        }
        default: m_compareAtWidth = false; break;
        }
    }
    switch (t.family) {
    case op::Add: real ? floatBinary(Fop::Add) : intBinary(Alu::Add); return true;
    case op::Sub: real ? floatBinary(Fop::Sub) : intBinary(Alu::Sub); return true;
    case op::And: intBinary(Alu::And); return true;
    case op::Or: intBinary(Alu::Or); return true;
    case op::Xor: intBinary(Alu::Xor); return true;
    case op::Mul:
        if (real) {
            floatBinary(Fop::Mul);
        } else {
            loadInt(rax, in.b, vt);
            loadInt(rcx, in.c, vt);
            m.imul(true, rax, rcx);
            storeRaw(in.a, rax, n);
        }
        return true;
    case op::Div:
        real ? floatBinary(Fop::Div) : divide(pc, in, vt, false);
        return true;
    case op::Mod: divide(pc, in, vt, true); return true;
    case op::Neg:
        loadRaw(rax, in.b, n);
        if (!real) {
            m.neg(true, rax);
        } else if (!dbl) {
            m.aluImm(Alu::Xor, false, rax, std::numeric_limits<std::int32_t>::min()); // the sign bit
        } else {
            m.movImm(rcx, std::numeric_limits<std::int64_t>::min());
            m.alu(Alu::Xor, true, rax, rcx);
        }
        storeRaw(in.a, rax, n);
        return true;
    case op::Not:
        loadRaw(rax, in.b, n);
        m.notR(true, rax);
        storeRaw(in.a, rax, n);
        return true;
    case op::Eq: case op::Ne: case op::Lt: case op::Le: case op::Gt: case op::Ge:
        if (real) {
            floatCompareToAl(t.family, in.b, in.c, dbl);
        } else {
            intCompare(in.b, in.c, vt);
            m.setcc(intCondition(t.family, vt), rax);
        }
        storeByte(in.a, rax);
        return true;
    case op::GetBit:
        loadInt(rax, in.b, vt); // signed values extended, as static_cast<uint64_t> in the VM
        if (in.d != 0)
            m.shrImm(true, rax, std::uint8_t(in.d));
        m.aluImm(Alu::And, false, rax, 1);
        storeByte(in.a, rax);
        return true;
    case op::BrEq: case op::BrNe: case op::BrLt: case op::BrLe: case op::BrGt: case op::BrGe: {
        Cond cond = NE;
        if (real) {
            floatCompareToAl(t.family, in.b, in.c, dbl);
            m.test(false, rax, rax);
        } else {
            intCompare(in.b, in.c, vt);
            cond = intCondition(t.family, vt);
        }
        branch(pc, &cond, in.a, in.a <= pc);
        return true;
    }
    case op::IncBrLe: case op::IncBrGe: case op::IncBrLt: case op::IncBrGt: {
        loadInt(rax, in.a, vt);
        loadInt(rcx, in.b, vt);
        m.alu(Alu::Add, true, rax, rcx);
        storeRaw(in.a, rax, n);
        m.extend(n, jit::isSignedInt(vt), rax); // compare the wrapped value, as the VM does
        loadInt(rcx, in.c, vt);
        m.alu(Alu::Cmp, true, rax, rcx);
        const Cond cond = intCondition(t.family, vt);
        branch(pc, &cond, in.d, true);
        return true;
    }
    case op::MulAdd:
        if (real) {
            const int x = floatSource(in.b, dbl, 0);
            if (x != 0)
                m.fmovRR(0, x);
            m.fop(Fop::Mul, dbl, 0, floatSource(in.c, dbl, 1));
            m.fop(Fop::Add, dbl, 0, floatSource(in.d, dbl, 1));
            storeFloat(in.a, 0, dbl);
        } else {
            loadInt(rax, in.b, vt);
            loadInt(rcx, in.c, vt);
            m.imul(true, rax, rcx);
            loadInt(rcx, in.d, vt);
            m.alu(Alu::Add, true, rax, rcx);
            storeRaw(in.a, rax, n);
        }
        return true;
    default: return false;
    }
}

bool RegionTranslator::instruction(std::uint32_t pc, const Instr &in)
{
    if (const auto t = jit::typedOf(in.op))
        return typed(pc, in, *t);
    if (in.op >= op::Convert && in.op <= op::Convert_Last) {
        convert(in);
        return true;
    }
    const auto descriptor = [&]() -> const IndexDescriptor & { return m_module.indexDescriptors[in.aux]; };
    switch (in.op) {
    case op::Nop: return true;
    case op::Jmp: branch(pc, nullptr, in.a, in.a <= pc); return true;
    case op::Jz:
    case op::Jnz: {
        if (m_carried && m_carried->operand == in.b)
            m.test8(m_carried->reg, m_carried->reg);
        else
            m.cmpMem8Imm(memOf(in.b), 0);
        const Cond cond = in.op == op::Jz ? E : NE;
        branch(pc, &cond, in.a, in.a <= pc);
        return true;
    }
    case op::Mov1: case op::Mov2: case op::Mov4: case op::Mov8: {
        const int n = 1 << (in.op - op::Mov1);
        const CachedSlot *from = cached(in.b), *to = cached(in.a);
        if (from && to && from->isFloat && to->isFloat) {
            m.fmovRR(to->reg, from->reg);
        } else {
            loadRaw(rax, in.b, n);
            storeRaw(in.a, rax, n);
        }
        return true;
    }
    case op::BoolNot:
        loadByte(rax, in.b);
        m.aluImm(Emitter::Alu::Xor, false, rax, 1);
        storeByte(in.a, rax);
        return true;
    case op::LoadIdx1: case op::LoadIdx2: case op::LoadIdx4: case op::LoadIdx8:
        loadInt(rax, in.c, descriptor().indexType);
        checkIndex(pc, descriptor(), FaultKind::IndexOutOfRange);
        loadElement(in.a, element(in.b, descriptor()), 1 << (in.op - op::LoadIdx1));
        return true;
    case op::StoreIdx1: case op::StoreIdx2: case op::StoreIdx4: case op::StoreIdx8:
        loadInt(rax, in.c, descriptor().indexType);
        checkIndex(pc, descriptor(), FaultKind::IndexOutOfRange);
        storeElement(element(in.a, descriptor()), in.d, 1 << (in.op - op::StoreIdx1));
        return true;
    case op::LoadIdxMA1: case op::LoadIdxMA2: case op::LoadIdxMA4: case op::LoadIdxMA8: {
        const VT vt = descriptor().indexType;
        if (isWord(vt)) { // DINT/LINT: at the type's width, which wraps like the VM's index
            const bool wide = vt == VT::I64;
            movFrom(wide, rax, source(in.c));
            const Source d = source(in.d);
            d.inRegister ? m.imul(wide, rax, d.reg) : m.imulMem(wide, rax, d.mem);
            aluWith(Emitter::Alu::Add, wide, rax, source(in.e));
            if (!wide)
                m.movsxdRR(rax, rax);
        } else {
            loadInt(rax, in.c, vt);
            loadInt(rcx, in.d, vt);
            m.imul(true, rax, rcx);
            loadInt(rcx, in.e, vt);
            m.alu(Emitter::Alu::Add, true, rax, rcx);
            m.extend(jit::sizeOf(vt), true, rax); // wrapped like the index type (INT)
        }
        checkIndex(pc, descriptor(), FaultKind::IndexOutOfRange);
        loadElement(in.a, element(in.b, descriptor()), 1 << (in.op - op::LoadIdxMA1));
        return true;
    }
    case op::BoolAndNot:
        loadByte(rax, in.c);
        m.aluImm(Emitter::Alu::Xor, false, rax, 1);
        m.aluMem8(Emitter::Alu::And, rax, memOf(in.b));
        storeByte(in.a, rax);
        return true;
    case op::BoolAndOr:
    case op::BoolOrAnd: {
        const bool andFirst = in.op == op::BoolAndOr;
        loadByte(rax, in.b);
        m.aluMem8(andFirst ? Emitter::Alu::And : Emitter::Alu::Or, rax, memOf(in.c));
        m.aluMem8(andFirst ? Emitter::Alu::Or : Emitter::Alu::And, rax, memOf(in.d));
        storeByte(in.a, rax);
        return true;
    }
    case op::BoolAndNotOrAnd: rung(in.a, in.b, in.c, in.d, in.e); return true;
    case op::BoolAndNotOrAndRel:
        rung(in.a | kInstanceRelative, in.b | kInstanceRelative, in.c | kInstanceRelative, in.d | kInstanceRelative,
             in.e | kInstanceRelative);
        return true;
    case op::RungBlock: {
        const RungRecord &r = m_module.rungs[in.b];
        const auto at = [&](std::int64_t delta) { return std::uint32_t(std::int64_t(r.a) + delta) | kInstanceRelative; };
        rung(at(0), at(r.b), at(r.c), at(r.d), at(r.e));
        return true;
    }
    case op::NativeFb:
    case op::NativeFbArgs: nativeBlock(in); return true;
    case op::Now:
        m.load(8, rax, kClockSlot, false);
        m.load(8, rax, Mem{rax, kNoIndex, 1, 0}, false);
        storeRaw(in.a, rax, 8);
        return true;
    case op::CheckRange:
        loadInt(rax, in.b, descriptor().indexType);
        checkIndex(pc, descriptor(), FaultKind::OutOfSubrange);
        return true;
    default: return false;
    }
}

// IEC_JIT_DUMP=FILE writes the machine code, for `objdump -D -b binary -m i386:x86-64 FILE`.
void dumpIfAsked(const std::vector<std::uint8_t> &code)
{
    const QByteArray path = qgetenv("IEC_JIT_DUMP");
    if (path.isEmpty())
        return;
    if (FILE *f = std::fopen(path.constData(), "wb")) {
        std::fwrite(code.data(), 1, code.size(), f);
        std::fclose(f);
    }
}

#ifdef IEC_JIT_X64
void *mapExecutable(const std::vector<std::uint8_t> &code)
{
    void *p = mmap(nullptr, code.size(), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED)
        return nullptr;
    std::memcpy(p, code.data(), code.size());
    if (mprotect(p, code.size(), PROT_READ | PROT_EXEC) != 0) {
        munmap(p, code.size());
        return nullptr;
    }
    return p;
}
#endif

} // namespace

JitProgram::~JitProgram()
{
#ifdef IEC_JIT_X64
    if (m_machineCode)
        munmap(m_machineCode, m_machineCodeSize);
#endif
}

std::unique_ptr<JitProgram> JitProgram::compile(const Module &module)
{
#ifdef IEC_JIT_X64
    if (!jitEnabled())
        return nullptr;
    const std::vector<Region> regions = jit::findRegions(module);
    if (regions.empty())
        return nullptr;
    Emitter emitter;
    struct Translated {
        Label prologue;
        std::vector<std::pair<std::uint32_t, Label>> entries;
    };
    std::vector<Translated> translated;
    std::unique_ptr<JitProgram> program(new JitProgram);
    for (const Region &region : regions) {
        RegionTranslator translator(module, emitter, region);
        if (!translator.translate())
            return nullptr; // describe() promised more than the translator does: run interpreted
        Translated t{translator.prologue(), {}};
        for (std::uint32_t pc : region.entries)
            t.entries.emplace_back(pc, translator.labelOf(pc));
        translated.push_back(std::move(t));
        ++program->m_stats.regions;
        program->m_stats.instructions += region.end - region.begin;
    }
    if (!emitter.finish() || emitter.size() == 0)
        return nullptr;
    dumpIfAsked(emitter.code());
    void *machineCode = mapExecutable(emitter.code());
    if (!machineCode)
        return nullptr;
    program->m_machineCode = machineCode;
    program->m_machineCodeSize = emitter.size();
    program->m_stats.bytes = emitter.size();
    program->m_code = module.code;
    auto *base = static_cast<std::uint8_t *>(machineCode);
    for (const Translated &t : translated) {
        const auto region = reinterpret_cast<NativeRegion>(base + emitter.offsetOf(t.prologue));
        for (const auto &[pc, label] : t.entries) {
            Instr enter;
            enter.op = op::JitEnter;
            enter.a = std::uint32_t(program->m_entries.size());
            program->m_code[pc] = enter;
            program->m_entries.push_back({region, base + emitter.offsetOf(label)});
        }
    }
    return program;
#else
    Q_UNUSED(module);
    return nullptr;
#endif
}

} // namespace iec::interp
