#include "interpreter/vm/jitregions.h"

#include "interpreter/vm/nativeblocks.h"
#include "interpreter/vm/x64emitter.h"

#include <algorithm>
#include <map>
#include <set>

namespace iec::interp::jit {

std::optional<Typed> typedOf(std::uint16_t opcode)
{
    // The typed families come first in the opcode list, kVtCount opcodes each.
    if (opcode >= op::Convert)
        return std::nullopt;
    return Typed{std::uint16_t(opcode / kVtCount * kVtCount), static_cast<VT>(opcode % kVtCount)};
}

std::uint8_t sizeOf(VT vt)
{
    switch (vt) {
    case VT::I8: case VT::U8: return 1;
    case VT::I16: case VT::U16: return 2;
    case VT::I32: case VT::U32: case VT::F32: return 4;
    default: return 8;
    }
}

bool isFloat(VT vt)
{
    return vt == VT::F32 || vt == VT::F64;
}

bool isSignedInt(VT vt)
{
    return vt == VT::I8 || vt == VT::I16 || vt == VT::I32 || vt == VT::I64;
}

std::optional<std::uint32_t> jumpTarget(const Instr &instr)
{
    switch (instr.op) {
    case op::Jmp:
    case op::Jz:
    case op::Jnz: return instr.a;
    default: break;
    }
    if (const auto t = typedOf(instr.op)) {
        switch (t->family) {
        case op::BrEq: case op::BrNe: case op::BrLt: case op::BrLe: case op::BrGt: case op::BrGe: return instr.a;
        case op::IncBrLe: case op::IncBrGe: case op::IncBrLt: case op::IncBrGt: return instr.d;
        default: break;
        }
    }
    return std::nullopt;
}

namespace {

Use useOf(VT vt)
{
    return isFloat(vt) ? Use::Float : Use::Int;
}

void add(Footprint &out, std::uint32_t operand, std::uint8_t bytes, Use use, bool write = false)
{
    out.accesses.push_back({operand, bytes, bytes == 1 ? Use::Byte : use, write});
}

bool describeTyped(const Typed &t, const Instr &in, Footprint &out)
{
    const std::uint8_t n = sizeOf(t.vt);
    const Use use = useOf(t.vt);
    const bool real = isFloat(t.vt);
    switch (t.family) {
    case op::Add: case op::Sub: case op::Mul: case op::Div:
        add(out, in.b, n, use);
        add(out, in.c, n, use);
        add(out, in.a, n, use, true);
        return true;
    case op::Mod: case op::And: case op::Or: case op::Xor:
        if (real)
            return false; // fmod and bit operations on reals stay interpreted
        add(out, in.b, n, use);
        add(out, in.c, n, use);
        add(out, in.a, n, use, true);
        return true;
    case op::Neg:
        add(out, in.b, n, use);
        add(out, in.a, n, use, true);
        return true;
    case op::Not:
        if (real)
            return false;
        add(out, in.b, n, use);
        add(out, in.a, n, use, true);
        return true;
    case op::Eq: case op::Ne: case op::Lt: case op::Le: case op::Gt: case op::Ge:
        add(out, in.b, n, use);
        add(out, in.c, n, use);
        add(out, in.a, 1, Use::Byte, true);
        return true;
    case op::GetBit:
        if (real || in.d >= 64)
            return false;
        add(out, in.b, n, use);
        add(out, in.a, 1, Use::Byte, true);
        return true;
    case op::BrEq: case op::BrNe: case op::BrLt: case op::BrLe: case op::BrGt: case op::BrGe:
        add(out, in.b, n, use);
        add(out, in.c, n, use);
        return true;
    case op::IncBrLe: case op::IncBrGe: case op::IncBrLt: case op::IncBrGt:
        if (real)
            return false;
        add(out, in.a, n, use);
        add(out, in.b, n, use);
        add(out, in.c, n, use);
        add(out, in.a, n, use, true);
        return true;
    case op::MulAdd:
        add(out, in.b, n, use);
        add(out, in.c, n, use);
        add(out, in.d, n, use);
        add(out, in.a, n, use, true);
        return true;
    default: return false;
    }
}

bool describeConvert(const Instr &in, Footprint &out)
{
    const int n = in.op - op::Convert;
    const VT from = static_cast<VT>(n / kVtCount), to = static_cast<VT>(n % kVtCount);
    // Reals to integers round half away from zero and saturate (vm.cpp convert()): interpreted.
    if (isFloat(from) && !isFloat(to))
        return false;
    if (from == VT::U64 && isFloat(to))
        return false; // no unsigned 64-bit conversion instruction before AVX-512
    add(out, in.b, sizeOf(from), useOf(from));
    add(out, in.a, sizeOf(to), useOf(to), true);
    return true;
}

bool describeIndexed(const Module &module, const Instr &in, Footprint &out, std::uint8_t n, bool store, bool mulAdd)
{
    if (in.aux >= module.indexDescriptors.size())
        return false;
    const IndexDescriptor &dsc = module.indexDescriptors[in.aux];
    const std::uint8_t indexBytes = sizeOf(dsc.indexType);
    if (isFloat(dsc.indexType) || dsc.count <= 0)
        return false;
    if (mulAdd && dsc.indexType != VT::I16 && dsc.indexType != VT::I32 && dsc.indexType != VT::I64)
        return false; // vm.cpp mulAddIndex() knows these three
    add(out, in.c, indexBytes, Use::Int);
    if (mulAdd) {
        add(out, in.d, indexBytes, Use::Int);
        add(out, in.e, indexBytes, Use::Int);
    }
    const std::uint64_t arrayBytes = std::uint64_t(dsc.count) * dsc.stride;
    if (store) {
        add(out, in.d, n, Use::Raw);
        out.arrays.push_back({in.a, arrayBytes});
    } else {
        out.arrays.push_back({in.b, arrayBytes});
        add(out, in.a, n, Use::Raw, true);
    }
    return true;
}

void addRung(Footprint &out, std::uint32_t a, std::int64_t b, std::int64_t c, std::int64_t d, std::int64_t e)
{
    for (std::int64_t delta : {b, c, d, e})
        add(out, std::uint32_t(std::int64_t(a) + delta) | kInstanceRelative, 1, Use::Byte);
    add(out, a | kInstanceRelative, 1, Use::Byte, true);
}

} // namespace

bool describe(const Module &module, const Instr &in, Footprint &out)
{
    if (const auto t = typedOf(in.op))
        return describeTyped(*t, in, out);
    if (in.op >= op::Convert && in.op <= op::Convert_Last)
        return describeConvert(in, out);
    switch (in.op) {
    case op::Nop:
    case op::Jmp: return true;
    case op::Mov1: case op::Mov2: case op::Mov4: case op::Mov8: {
        const std::uint8_t n = std::uint8_t(1u << (in.op - op::Mov1));
        add(out, in.b, n, Use::Raw);
        add(out, in.a, n, Use::Raw, true);
        return true;
    }
    case op::BoolNot:
        add(out, in.b, 1, Use::Byte);
        add(out, in.a, 1, Use::Byte, true);
        return true;
    case op::Jz: case op::Jnz:
        add(out, in.b, 1, Use::Byte);
        return true;
    case op::LoadIdx1: case op::LoadIdx2: case op::LoadIdx4: case op::LoadIdx8:
        return describeIndexed(module, in, out, std::uint8_t(1u << (in.op - op::LoadIdx1)), false, false);
    case op::StoreIdx1: case op::StoreIdx2: case op::StoreIdx4: case op::StoreIdx8:
        return describeIndexed(module, in, out, std::uint8_t(1u << (in.op - op::StoreIdx1)), true, false);
    case op::LoadIdxMA1: case op::LoadIdxMA2: case op::LoadIdxMA4: case op::LoadIdxMA8:
        return describeIndexed(module, in, out, std::uint8_t(1u << (in.op - op::LoadIdxMA1)), false, true);
    case op::BoolAndNot:
        add(out, in.b, 1, Use::Byte);
        add(out, in.c, 1, Use::Byte);
        add(out, in.a, 1, Use::Byte, true);
        return true;
    case op::BoolAndOr: case op::BoolOrAnd:
        add(out, in.b, 1, Use::Byte);
        add(out, in.c, 1, Use::Byte);
        add(out, in.d, 1, Use::Byte);
        add(out, in.a, 1, Use::Byte, true);
        return true;
    case op::BoolAndNotOrAnd:
        for (std::uint32_t operand : {in.b, in.c, in.d, in.e})
            add(out, operand, 1, Use::Byte);
        add(out, in.a, 1, Use::Byte, true);
        return true;
    case op::BoolAndNotOrAndRel:
        addRung(out, in.a, std::int64_t(in.b) - in.a, std::int64_t(in.c) - in.a, std::int64_t(in.d) - in.a, std::int64_t(in.e) - in.a);
        return true;
    case op::RungBlock: {
        // Natively only its first rung: the rest follow as their own instructions.
        if (in.c == 0 || in.b >= module.rungs.size())
            return false;
        const RungRecord &r = module.rungs[in.b];
        addRung(out, r.a, r.b, r.c, r.d, r.e);
        return true;
    }
    case op::NativeFb:
    case op::NativeFbArgs: {
        // The block reads and writes its whole instance (nativeblocks.h TimerInstance).
        out.arrays.push_back({in.a, sizeof(nativedetail::TimerInstance)});
        if (in.op == op::NativeFbArgs) {
            add(out, in.b, 1, Use::Byte);
            add(out, in.c, 8, Use::Int);
            if (in.e != 0)
                add(out, in.e, 1, Use::Byte, true);
        }
        out.callsOut = true;
        return in.aux <= std::uint16_t(NativeBlock::Tp);
    }
    case op::Now:
        add(out, in.a, 8, Use::Int, true);
        return true;
    case op::CheckRange: {
        if (in.aux >= module.indexDescriptors.size() || isFloat(module.indexDescriptors[in.aux].indexType))
            return false;
        add(out, in.b, sizeOf(module.indexDescriptors[in.aux].indexType), Use::Int);
        return true;
    }
    default: return false;
    }
}

const std::vector<int> &cacheableGprs()
{
    // rax, rcx, rdx are scratch; rsp is the stack; r12 = memory, r13 = instance, r14 = budget.
    static const std::vector<int> regs{x64::rbx, x64::rbp, x64::r15, x64::rsi, x64::rdi, x64::r8, x64::r9, x64::r10, x64::r11};
    return regs;
}

const std::vector<int> &cacheableXmms()
{
    static const std::vector<int> regs{2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
    return regs;
}

namespace {

constexpr std::size_t kMinStraightRegion = 16; // shorter runs without a loop cost more to enter

struct ByteRange {
    bool relative = false;
    std::uint64_t begin = 0, end = 0;
    bool overlaps(const ByteRange &o) const { return relative == o.relative && begin < o.end && o.begin < end; }
};

ByteRange rangeOf(std::uint32_t operand, std::uint64_t bytes)
{
    const std::uint64_t offset = operand & kOffsetMask;
    return {(operand & kInstanceRelative) != 0, offset, offset + bytes};
}

// Absolute operands inside a program instance or a global that holds function block instances
// might be the very bytes the running instance's relative operands name (a block touching itself
// through a global path); a region mixing both keeps nothing in registers.
class CompositeGlobals
{
public:
    explicit CompositeGlobals(const Module &module)
    {
        std::set<std::uint32_t> programBases;
        for (const ProgramInstance &p : module.programs)
            programBases.insert(p.base);
        for (const Symbol &s : module.symbols) {
            if (s.type && (programBases.count(s.offset) || canHoldInstance(*s.type)))
                m_ranges.emplace_back(s.offset, std::uint64_t(s.offset) + s.type->size);
        }
        std::sort(m_ranges.begin(), m_ranges.end());
    }
    bool overlaps(const ByteRange &r) const
    {
        if (r.relative)
            return false;
        // Roots never overlap each other: only the last one starting before r ends can reach it.
        auto it = std::lower_bound(m_ranges.begin(), m_ranges.end(), std::make_pair(r.end, std::uint64_t(0)));
        return it != m_ranges.begin() && std::prev(it)->second > r.begin;
    }

private:
    // Program instances and function blocks run with their own instance-relative code; a plain
    // global array or structure never does, so the program's registers cannot alias it.
    static bool canHoldInstance(const Type &type)
    {
        switch (type.kind) {
        case TypeKind::FunctionBlock: return true;
        case TypeKind::Array: return type.element && canHoldInstance(*type.element);
        case TypeKind::Struct:
            return std::any_of(type.members.begin(), type.members.end(), [](const Member &m) { return m.type && canHoldInstance(*m.type); });
        default: return false;
        }
    }

    std::vector<std::pair<std::uint64_t, std::uint64_t>> m_ranges;
};

std::vector<CachedSlot> chooseCache(const CompositeGlobals &composites, const std::vector<Footprint> &footprints, bool callsOut)
{
    struct Candidate {
        std::uint8_t bytes = 0;  // of the first access
        std::uint8_t extent = 0; // the widest access: what overlaps other slots
        Use use = Use::Raw;
        bool conflict = false;
        bool written = false;
        int uses = 0;
    };
    std::map<std::uint32_t, Candidate> candidates;
    std::vector<ByteRange> arrays;
    bool anyRelative = false, compositeAbsolute = false;
    for (const Footprint &f : footprints) {
        for (const ArrayAccess &a : f.arrays) {
            const ByteRange r = rangeOf(a.operand, a.bytes);
            arrays.push_back(r);
            anyRelative |= r.relative;
            compositeAbsolute |= composites.overlaps(r);
        }
        for (const Access &a : f.accesses) {
            const ByteRange r = rangeOf(a.operand, a.bytes);
            anyRelative |= r.relative;
            compositeAbsolute |= composites.overlaps(r);
            Candidate &c = candidates[a.operand];
            if (c.uses == 0) {
                c.bytes = a.bytes;
                c.use = a.use;
            }
            ++c.uses;
            c.extent = std::max(c.extent, a.bytes);
            c.written |= a.write;
            const bool sameUse = c.use == a.use || a.use == Use::Raw || c.use == Use::Raw;
            if (c.bytes != a.bytes || !sameUse || (a.bytes != 4 && a.bytes != 8) || a.use == Use::Byte)
                c.conflict = true;
            if (c.use == Use::Raw)
                c.use = a.use;
        }
    }
    if (anyRelative && compositeAbsolute)
        return {};
    // A slot is safe in a register when nothing else in the region can reach its bytes: no other
    // operand overlapping it, no array it lies in.
    for (auto &[operand, c] : candidates) {
        if (c.conflict)
            continue;
        const ByteRange mine = rangeOf(operand, c.extent);
        for (const ByteRange &a : arrays)
            c.conflict |= a.overlaps(mine);
        for (const auto &[other, o] : candidates) {
            if (other != operand && rangeOf(other, o.extent).overlaps(mine))
                c.conflict = true;
        }
    }
    std::vector<std::pair<int, std::uint32_t>> order;
    for (const auto &[operand, c] : candidates) {
        if (!c.conflict)
            order.emplace_back(-c.uses, operand);
    }
    std::sort(order.begin(), order.end());
    std::vector<CachedSlot> cache;
    std::size_t gprs = 0, xmms = 0;
    const std::size_t gprLimit = callsOut ? kCalleeSavedGprs : cacheableGprs().size();
    const std::size_t xmmLimit = callsOut ? 0 : cacheableXmms().size(); // every xmm is caller-saved
    for (const auto &[negUses, operand] : order) {
        const Candidate &c = candidates[operand];
        const bool isFloatSlot = c.use == Use::Float;
        if (isFloatSlot && xmms < xmmLimit)
            cache.push_back({operand, c.bytes, true, c.written, cacheableXmms()[xmms++]});
        else if (!isFloatSlot && gprs < gprLimit)
            cache.push_back({operand, c.bytes, false, c.written, cacheableGprs()[gprs++]});
    }
    return cache;
}

bool hasLoop(const Module &module, std::uint32_t begin, std::uint32_t end)
{
    for (std::uint32_t pc = begin; pc < end; ++pc) {
        const auto target = jumpTarget(module.code[pc]);
        if (target && *target >= begin && *target <= pc)
            return true;
    }
    return false;
}

// Every pc the interpreter may reach by a jump, a call or a return; a region must be enterable
// at each of these that it contains.
std::set<std::uint32_t> entryCandidates(const Module &module)
{
    std::set<std::uint32_t> pcs;
    for (std::uint32_t pc = 0; pc < module.code.size(); ++pc) {
        const Instr &in = module.code[pc];
        if (const auto target = jumpTarget(in))
            pcs.insert(*target);
        if (in.op == op::CallFb || in.op == op::CallFbPtr || in.op == op::CallFn)
            pcs.insert(pc + 1);
    }
    for (const CompiledPou &p : module.pous)
        pcs.insert(p.entry);
    for (const ProgramInstance &p : module.programs)
        pcs.insert(p.entry);
    for (const TaskInfo &t : module.tasks)
        pcs.insert(t.entry);
    return pcs;
}

} // namespace

std::vector<Region> findRegions(const Module &module)
{
    const std::set<std::uint32_t> targets = entryCandidates(module);
    const CompositeGlobals composites(module);
    std::vector<Region> regions;
    const std::uint32_t size = std::uint32_t(module.code.size());
    std::uint32_t pc = 0;
    while (pc < size) {
        std::vector<Footprint> footprints;
        const std::uint32_t begin = pc;
        bool callsOut = false;
        for (Footprint f; pc < size && describe(module, module.code[pc], f); f = {}, ++pc) {
            callsOut |= f.callsOut;
            footprints.push_back(std::move(f));
        }
        const std::uint32_t end = pc;
        if (end == begin) {
            ++pc; // an instruction the JIT leaves to the interpreter
            continue;
        }
        if (end - begin < kMinStraightRegion && !hasLoop(module, begin, end))
            continue;
        Region region;
        region.begin = begin;
        region.end = end;
        region.entries.push_back(begin);
        for (auto it = targets.upper_bound(begin); it != targets.end() && *it < end; ++it)
            region.entries.push_back(*it);
        region.callsOut = callsOut;
        region.cache = chooseCache(composites, footprints, callsOut);
        regions.push_back(std::move(region));
    }
    return regions;
}

} // namespace iec::interp::jit
