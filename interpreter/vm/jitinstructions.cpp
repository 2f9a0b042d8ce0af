#include "interpreter/vm/jittranslator.h"

#include "interpreter/vm/nativeblocks.h"

#include <cstddef>
#include <limits>

namespace iec::interp::jit {

namespace {

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

} // namespace

// ---- instructions ---------------------------------------------------------------------------

void RegionTranslator::divide(std::uint32_t pc, const Instr &in, VT vt, bool modulo)
{
    const bool wide = sizeOf(vt) == 8;
    loadInt(rax, in.b, vt);
    loadInt(rcx, in.c, vt);
    m.test(true, rcx, rcx);
    m.jcc(E, fault(pc, FaultKind::DivisionByZero));
    if (isSignedInt(vt)) {
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
    storeRaw(in.a, rax, sizeOf(vt));
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
    const auto field = [&](std::size_t offset) { return Mem{instance.base, kNoIndex, 1, instance.disp + std::int32_t(offset)}; };
    if (in.op == op::NativeFbArgs) {
        loadByte(rax, in.b);
        m.store(1, field(offsetof(nativedetail::TimerInstance, in)), rax);
        loadRaw(rax, in.c, 8);
        m.store(8, field(offsetof(nativedetail::TimerInstance, pt)), rax);
    }
    m.lea(rdi, instance);
    m.load(8, rax, kClockSlot, false);
    m.load(8, rsi, Mem{rax, kNoIndex, 1, 0}, false);
    m.movImm(rax, std::int64_t(nativeBlockFunction(in.aux)));
    m.callReg(rax);
    if (in.op == op::NativeFbArgs && in.e != 0) {
        m.load(1, rax, field(offsetof(nativedetail::TimerInstance, q)), false);
        storeByte(in.e, rax);
    }
}

void RegionTranslator::convert(const Instr &in)
{
    const int n = in.op - op::Convert;
    const VT from = static_cast<VT>(n / kVtCount), to = static_cast<VT>(n % kVtCount);
    if (!isFloat(from) && !isFloat(to)) {
        loadInt(rax, in.b, from); // the low bytes of the extended value are static_cast<To>
        storeRaw(in.a, rax, sizeOf(to));
    } else if (!isFloat(from)) {
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

bool RegionTranslator::typed(std::uint32_t pc, const Instr &in, const Typed &t)
{
    const VT vt = t.vt;
    const bool real = isFloat(vt), dbl = vt == VT::F64;
    const int n = sizeOf(vt);
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
        switch (t.family) {
        case op::Eq: case op::Ne: case op::Lt: case op::Le: case op::Gt: case op::Ge:
            aluWith(Alu::Cmp, wide, wordLeft(in.b, wide), source(in.c));
            m.setcc(intCondition(t.family, vt, true), rax);
            storeByte(in.a, rax);
            return true;
        case op::BrEq: case op::BrNe: case op::BrLt: case op::BrLe: case op::BrGt: case op::BrGe: {
            aluWith(Alu::Cmp, wide, wordLeft(in.b, wide), source(in.c));
            const Cond cond = intCondition(t.family, vt, true);
            branch(pc, &cond, in.a, in.a <= pc);
            return true;
        }
        case op::IncBrLe: case op::IncBrGe: case op::IncBrLt: case op::IncBrGt: {
            wordIncrement(in, vt);
            const Cond cond = intCondition(t.family, vt, true);
            branch(pc, &cond, in.d, true);
            return true;
        }
        default: break;
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
            m.setcc(intCondition(t.family, vt, false), rax);
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
            cond = intCondition(t.family, vt, false);
        }
        branch(pc, &cond, in.a, in.a <= pc);
        return true;
    }
    case op::IncBrLe: case op::IncBrGe: case op::IncBrLt: case op::IncBrGt: {
        loadInt(rax, in.a, vt);
        loadInt(rcx, in.b, vt);
        m.alu(Alu::Add, true, rax, rcx);
        storeRaw(in.a, rax, n);
        m.extend(n, isSignedInt(vt), rax); // compare the wrapped value, as the VM does
        loadInt(rcx, in.c, vt);
        m.alu(Alu::Cmp, true, rax, rcx);
        const Cond cond = intCondition(t.family, vt, false);
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
    if (const auto t = typedOf(in.op))
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
            m.extend(sizeOf(vt), true, rax); // wrapped like the index type (INT)
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

} // namespace iec::interp::jit
