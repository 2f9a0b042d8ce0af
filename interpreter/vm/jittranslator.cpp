#include "interpreter/vm/jittranslator.h"

namespace iec::interp::jit {

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
    // Nine pushes after the return address keep rsp 16-byte aligned for calls to C++.
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
    const int bytes = sizeOf(vt);
    const bool sign = isSignedInt(vt);
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
    const bool wide = sizeOf(vt) == 8;
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
        storeRaw(in.a, rax, sizeOf(vt));
    return true;
}

// a += b, then flags from comparing a with c (the IncBr family).
void RegionTranslator::wordIncrement(const Instr &in, VT vt)
{
    const bool wide = sizeOf(vt) == 8;
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
Cond RegionTranslator::intCondition(std::uint16_t family, VT vt, bool atWidth)
{
    // Words (isWord) are compared at their own width instead: UDINT/DWORD unsigned too.
    const bool u = vt == VT::U64 || (vt == VT::U32 && atWidth);
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

} // namespace iec::interp::jit
