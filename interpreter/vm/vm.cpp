#include "interpreter/vm/vm.h"

#include "interpreter/vm/jit.h"
#include "interpreter/vm/vmoperations.h"

#include <array>
#include <cmath>
#include <cstring>
#include <limits>

namespace iec::interp {

using namespace vmops;

Vm::Vm(const Module &module)
    : m_module(module)
    , m_jit(JitProgram::compile(module))
    , m_memory(module.initialImage)
{
    m_scratch.resize(2 * 65536);
}

Vm::~Vm() = default;

std::size_t Vm::nativeInstructions() const
{
    return m_jit ? m_jit->stats().instructions : 0;
}


FaultKind Vm::execute(std::uint32_t entry, bool resuming)
{
    struct Frame {
        const Instr *ip; // where to go on
        std::uint8_t *base;
    };
    std::array<Frame, 256> frames;
    size_t depth = 0;
    // The hot state lives in plain locals whose addresses are never taken, so the compiler keeps
    // them in registers although every store goes through a byte pointer that may alias anything.
    std::uint8_t *const mem = m_memory.data();
    const std::uint8_t *const memEnd = mem + m_memory.size();
    std::uint8_t *inst = mem;
    // With the JIT, its copy of the code, where op::JitEnter marks the way into machine code; with
    // stops, the debugger's copy (op::Break at each stop), run without the JIT. Resuming without
    // stops runs the plain code: a halt may have been inside what the JIT translated.
    const Instr *const code = !m_debugCode.empty() ? m_debugCode.data()
        : m_jit && !resuming                       ? m_jit->code().data()
                                                   : m_module.code.data();
    const IndexDescriptor *const descriptors = m_module.indexDescriptors.data();
    const RungRecord *const rungs = m_module.rungs.data();
    if (entry >= m_module.code.size()) {
        m_faultPc = entry;
        return FaultKind::InvalidProgram;
    }
    std::uint64_t budget = budgetPerRun;
    // The stop a resumed run starts at is passed once: its instruction runs, then the run goes on.
    std::uint32_t passStopAt = std::numeric_limits<std::uint32_t>::max();
    if (resuming) {
        for (const HaltedFrame &caller : m_halt->callers)
            frames[depth++] = {code + caller.pc, mem + caller.instance};
        inst = mem + m_halt->instance;
        budget = m_halt->budget;
        passStopAt = entry;
        m_halt.reset();
    }

#define P(operand) (((operand) & kInstanceRelative ? inst : mem) + ((operand) & kOffsetMask))
#define FAULT(kind)                                                                                                \
    do {                                                                                                           \
        m_faultPc = static_cast<std::uint32_t>(ip - code);                                                         \
        return (kind);                                                                                             \
    } while (false)
    // Macros, not lambdas: a lambda would capture `inst` as it was, or take its address.
#define absolute(operand) static_cast<std::uint32_t>(P(operand) - mem)
#define readInt(operand) static_cast<std::int64_t>(load<std::int32_t>(P(operand)))
#define str(operand, wide) StringRef{P(operand), (wide), memEnd}
    // Writes m_scratch[0, n) into a string; false when it does not fit.
    const auto writeString = [this](StringRef dst, int n) {
        if (!dst.fits() || n > dst.capacity())
            return false;
        store<std::uint16_t>(dst.p + 2, static_cast<std::uint16_t>(n));
        for (int i = 0; i < n; ++i) {
            if (dst.wide)
                store<char16_t>(dst.p + 4 + 2 * i, m_scratch[size_t(i)]);
            else
                dst.p[4 + i] = static_cast<std::uint8_t>(m_scratch[size_t(i)]);
        }
        // The NUL that ends it (StringRef); a full string has room for it too, unless its header lies.
        if (dst.p + 4 + (n + 1) * (dst.wide ? 2 : 1) <= dst.end) {
            if (dst.wide)
                store<char16_t>(dst.p + 4 + 2 * n, 0);
            else
                dst.p[4 + n] = 0;
        }
        return true;
    };
    const auto copyInto = [this](StringRef s, int from, int count, int at) {
        for (int i = 0; i < count; ++i)
            m_scratch[size_t(at + i)] = s.at(from + i);
        return at + count;
    };
    const auto clampInt = [](std::int64_t v, std::int64_t lo, std::int64_t hi) { return v < lo ? lo : v > hi ? hi : v; };

    // Threaded dispatch: each handler ends with its own indirect jump to the next one, which the
    // branch predictor learns per handler (GCC/Clang labels as values).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
    static const void *const dispatch[op::Count] = {
#define IEC_LABELS_OF_FAMILY(name) &&L_##name##_I8, &&L_##name##_I16, &&L_##name##_I32, &&L_##name##_I64, &&L_##name##_U8, \
                                   &&L_##name##_U16, &&L_##name##_U32, &&L_##name##_U64, &&L_##name##_F32, &&L_##name##_F64,
        IEC_TYPED_FAMILIES(IEC_LABELS_OF_FAMILY)
#undef IEC_LABELS_OF_FAMILY
#define IEC_CONVERT_LABELS(from) &&L_Convert_##from##_I8, &&L_Convert_##from##_I16, &&L_Convert_##from##_I32, \
                                 &&L_Convert_##from##_I64, &&L_Convert_##from##_U8, &&L_Convert_##from##_U16, \
                                 &&L_Convert_##from##_U32, &&L_Convert_##from##_U64, &&L_Convert_##from##_F32, &&L_Convert_##from##_F64,
        IEC_CONVERT_LABELS(I8) IEC_CONVERT_LABELS(I16) IEC_CONVERT_LABELS(I32) IEC_CONVERT_LABELS(I64)
        IEC_CONVERT_LABELS(U8) IEC_CONVERT_LABELS(U16) IEC_CONVERT_LABELS(U32) IEC_CONVERT_LABELS(U64)
        IEC_CONVERT_LABELS(F32) IEC_CONVERT_LABELS(F64)
#undef IEC_CONVERT_LABELS
#define IEC_PLAIN_LABEL(name) &&L_##name,
        IEC_PLAIN_OPS(IEC_PLAIN_LABEL)
#undef IEC_PLAIN_LABEL
    };
    // The instruction pointer is the one piece of state: the next instruction is ip + 1, a jump
    // sets it from the target's index, and the pc of a fault is ip - code.
    const Instr *ip = code + entry;
#define DISPATCH() goto *dispatch[ip->op]
#define NEXT()                                                                                                     \
    do {                                                                                                           \
        ++ip;                                                                                                      \
        DISPATCH();                                                                                                \
    } while (false)
    // A jump to `target`; backward jumps count against the budget, so an endless loop stops.
#define JUMP(target)                                                                                               \
    do {                                                                                                           \
        const Instr *const to = code + (target);                                                                   \
        if (to <= ip && --budget == 0)                                                                             \
            FAULT(FaultKind::BudgetExceeded);                                                                      \
        ip = to;                                                                                                   \
        DISPATCH();                                                                                                \
    } while (false)
    if (ip->op >= op::Count)
        FAULT(FaultKind::InvalidProgram);
    DISPATCH();
    {
#define IEC_CASE(family, vtName, T, ...)                                                                           \
    L_##family##_##vtName : {                                                                                      \
        using Ty = T;                                                                                              \
        __VA_ARGS__                                                                                                \
        NEXT();                                                                                                    \
    }
#define IEC_ALL_VT(family, ...)                                                                                    \
    IEC_CASE(family, I8, std::int8_t, __VA_ARGS__)                                                                 \
    IEC_CASE(family, I16, std::int16_t, __VA_ARGS__)                                                               \
    IEC_CASE(family, I32, std::int32_t, __VA_ARGS__)                                                               \
    IEC_CASE(family, I64, std::int64_t, __VA_ARGS__)                                                               \
    IEC_CASE(family, U8, std::uint8_t, __VA_ARGS__)                                                                \
    IEC_CASE(family, U16, std::uint16_t, __VA_ARGS__)                                                              \
    IEC_CASE(family, U32, std::uint32_t, __VA_ARGS__)                                                              \
    IEC_CASE(family, U64, std::uint64_t, __VA_ARGS__)                                                              \
    IEC_CASE(family, F32, float, __VA_ARGS__)                                                                      \
    IEC_CASE(family, F64, double, __VA_ARGS__)
#define B load<Ty>(P(ip->b))
#define C load<Ty>(P(ip->c))
#define SET(value) store<Ty>(P(ip->a), static_cast<Ty>(value))
#define SETBOOL(value) store<std::uint8_t>(P(ip->a), (value) ? 1 : 0)

            IEC_ALL_VT(Add, SET(wrapAdd<Ty>(B, C));)
            IEC_ALL_VT(Sub, SET(wrapSub<Ty>(B, C));)
            IEC_ALL_VT(Mul, SET(wrapMul<Ty>(B, C));)
            IEC_ALL_VT(Div, {
                Ty out{};
                if (!divide<Ty>(B, C, out))
                    FAULT(FaultKind::DivisionByZero);
                SET(out);
            })
            IEC_ALL_VT(Mod, {
                Ty out{};
                if (!modulo<Ty>(B, C, out))
                    FAULT(FaultKind::DivisionByZero);
                SET(out);
            })
            IEC_ALL_VT(Neg, SET(negate<Ty>(B));)
            IEC_ALL_VT(Abs, SET(absValue<Ty>(B));)
            IEC_ALL_VT(Min, { const Ty b = B, c = C; SET(c < b ? c : b); })
            IEC_ALL_VT(Max, { const Ty b = B, c = C; SET(c > b ? c : b); })
#define IEC_BRANCH(family, cmp)                                                                                    \
    IEC_ALL_VT(family, {                                                                                           \
        if (B cmp C)                                                                                               \
            JUMP(ip->a);                                                                                           \
    })
            IEC_BRANCH(BrEq, ==)
            IEC_BRANCH(BrNe, !=)
            IEC_BRANCH(BrLt, <)
            IEC_BRANCH(BrLe, <=)
            IEC_BRANCH(BrGt, >)
            IEC_BRANCH(BrGe, >=)
#undef IEC_BRANCH
#define IEC_STEP(family, cmp)                                                                                      \
    IEC_ALL_VT(family, {                                                                                           \
        const Ty next = wrapAdd<Ty>(load<Ty>(P(ip->a)), B);                                                        \
        store<Ty>(P(ip->a), next);                                                                                 \
        if (next cmp C) {                                                                                          \
            if (--budget == 0)                                                                                     \
                FAULT(FaultKind::BudgetExceeded);                                                                  \
            ip = code + ip->d;                                                                                     \
            DISPATCH();                                                                                            \
        }                                                                                                          \
    })
            IEC_STEP(IncBrLe, <=)
            IEC_STEP(IncBrGe, >=)
            IEC_STEP(IncBrLt, <)
            IEC_STEP(IncBrGt, >)
            IEC_ALL_VT(MulAdd, SET(wrapAdd<Ty>(wrapMul<Ty>(B, C), load<Ty>(P(ip->d))));)
#undef IEC_STEP
            IEC_ALL_VT(Eq, SETBOOL(B == C);)
            IEC_ALL_VT(Ne, SETBOOL(B != C);)
            IEC_ALL_VT(Lt, SETBOOL(B < C);)
            IEC_ALL_VT(Le, SETBOOL(B <= C);)
            IEC_ALL_VT(Gt, SETBOOL(B > C);)
            IEC_ALL_VT(Ge, SETBOOL(B >= C);)
            IEC_ALL_VT(And, SET(bitAnd<Ty>(B, C));)
            IEC_ALL_VT(Or, SET(bitOr<Ty>(B, C));)
            IEC_ALL_VT(Xor, SET(bitXor<Ty>(B, C));)
            IEC_ALL_VT(Not, SET(bitNot<Ty>(B));)
            IEC_ALL_VT(Shl, SET(shiftLeft<Ty>(B, load<std::uint64_t>(P(ip->c))));)
            IEC_ALL_VT(Shr, SET(shiftRight<Ty>(B, load<std::uint64_t>(P(ip->c))));)
            IEC_ALL_VT(Rol, SET(rotateLeft<Ty>(B, load<std::uint64_t>(P(ip->c))));)
            IEC_ALL_VT(Ror, SET(rotateRight<Ty>(B, load<std::uint64_t>(P(ip->c))));)
            IEC_ALL_VT(GetBit, SETBOOL(getBit<Ty>(B, ip->d));)
            IEC_ALL_VT(SetBit, SET(setBit<Ty>(load<Ty>(P(ip->a)), ip->d, load<std::uint8_t>(P(ip->b)) != 0));)
            IEC_ALL_VT(Expt, SET(std::pow(static_cast<double>(B), load<double>(P(ip->c))));)
            IEC_ALL_VT(Math, SET(applyMath(static_cast<MathFn>(ip->aux), static_cast<double>(B)));)
            IEC_ALL_VT(ToStr, {
                // A number's text is short; *_TO_STRING is the one operation that allocates.
                const QString text = toText<Ty>(B, static_cast<TextFormat>(ip->aux >> 1));
                const int n = static_cast<int>(text.size());
                for (int k = 0; k < n; ++k)
                    m_scratch[size_t(k)] = text[k].unicode();
                if (!writeString(str(ip->a, (ip->aux & 1) != 0), n))
                    FAULT(FaultKind::StringOverflow);
            })
            IEC_ALL_VT(FromStr, {
                const StringRef s = str(ip->b, (ip->aux & 1) != 0);
                const int length = s.length(); // a scan for the NUL: once
                QString text(length, Qt::Uninitialized);
                for (int k = 0; k < length; ++k)
                    text[k] = QChar(s.at(k));
                SET(fromText<Ty>(text.trimmed(), static_cast<TextFormat>(ip->aux >> 1)));
            })
            IEC_ALL_VT(Bcd, SET(bcd<Ty>(B, ip->aux != 0));)
#undef B
#undef C
#undef SET
#undef SETBOOL

#define IEC_CONVERT_TO(fromVt, From, toVt, To)                                                                     \
    L_Convert_##fromVt##_##toVt:                                                                                   \
        store<To>(P(ip->a), convert<To, From>(load<From>(P(ip->b))));                                                  \
        NEXT();
#define IEC_CONVERT_FROM(fromVt, From)                                                                             \
    IEC_CONVERT_TO(fromVt, From, I8, std::int8_t)                                                                  \
    IEC_CONVERT_TO(fromVt, From, I16, std::int16_t)                                                                \
    IEC_CONVERT_TO(fromVt, From, I32, std::int32_t)                                                                \
    IEC_CONVERT_TO(fromVt, From, I64, std::int64_t)                                                                \
    IEC_CONVERT_TO(fromVt, From, U8, std::uint8_t)                                                                 \
    IEC_CONVERT_TO(fromVt, From, U16, std::uint16_t)                                                               \
    IEC_CONVERT_TO(fromVt, From, U32, std::uint32_t)                                                               \
    IEC_CONVERT_TO(fromVt, From, U64, std::uint64_t)                                                               \
    IEC_CONVERT_TO(fromVt, From, F32, float)                                                                       \
    IEC_CONVERT_TO(fromVt, From, F64, double)
            IEC_CONVERT_FROM(I8, std::int8_t)
            IEC_CONVERT_FROM(I16, std::int16_t)
            IEC_CONVERT_FROM(I32, std::int32_t)
            IEC_CONVERT_FROM(I64, std::int64_t)
            IEC_CONVERT_FROM(U8, std::uint8_t)
            IEC_CONVERT_FROM(U16, std::uint16_t)
            IEC_CONVERT_FROM(U32, std::uint32_t)
            IEC_CONVERT_FROM(U64, std::uint64_t)
            IEC_CONVERT_FROM(F32, float)
            IEC_CONVERT_FROM(F64, double)
#undef IEC_CONVERT_FROM
#undef IEC_CONVERT_TO
#undef IEC_ALL_VT
#undef IEC_CASE

        L_Nop:
            NEXT();
        L_Mov1: *P(ip->a) = *P(ip->b); NEXT();
        L_Mov2: std::memcpy(P(ip->a), P(ip->b), 2); NEXT();
        L_Mov4: std::memcpy(P(ip->a), P(ip->b), 4); NEXT();
        L_Mov8: std::memcpy(P(ip->a), P(ip->b), 8); NEXT();
        L_MovN: std::memmove(P(ip->a), P(ip->b), ip->d); NEXT();
        L_BoolNot: *P(ip->a) = *P(ip->b) ^ 1u; NEXT();
        L_Jmp:
            JUMP(ip->a);
        L_Jz:
            if (*P(ip->b) == 0)
                JUMP(ip->a);
            NEXT();
        L_Jnz:
            if (*P(ip->b) != 0)
                JUMP(ip->a);
            NEXT();
        L_CallFb:
        L_CallFbPtr:
        L_CallFn: {
            if (depth == frames.size())
                FAULT(FaultKind::CallDepthExceeded);
            if (--budget == 0)
                FAULT(FaultKind::BudgetExceeded);
            frames[depth++] = {ip + 1, inst};
            if (ip->op == op::CallFb)
                inst = P(ip->a);
            else if (ip->op == op::CallFbPtr)
                inst = mem + load<std::uint32_t>(P(ip->a));
            ip = code + m_module.pous[ip->aux].entry;
            DISPATCH();
        }
        L_Ret:
            if (depth == 0)
                return FaultKind::None;
            --depth;
            ip = frames[depth].ip;
            inst = frames[depth].base;
            DISPATCH();
        L_Halt:
            return FaultKind::None;
        L_Lea:
            store<std::uint32_t>(P(ip->a), absolute(ip->b));
            NEXT();
        L_Index:
        L_IndexPtr: {
            const IndexDescriptor &dsc = descriptors[ip->aux];
            const std::int64_t index = readIndex(dsc, P(ip->c)) - dsc.low;
            if (index < 0 || index >= dsc.count)
                FAULT(FaultKind::IndexOutOfRange);
            const std::uint32_t base = ip->op == op::Index ? absolute(ip->b) : load<std::uint32_t>(P(ip->b));
            store<std::uint32_t>(P(ip->a), base + static_cast<std::uint32_t>(index) * dsc.stride);
            NEXT();
        }
        L_PtrAdd:
            store<std::uint32_t>(P(ip->a), load<std::uint32_t>(P(ip->b)) + ip->d);
            NEXT();
#define IEC_INDEXED(size)                                                                                         \
    L_LoadIdx##size: {                                                                                      \
        const IndexDescriptor &dsc = descriptors[ip->aux];                                                          \
        const std::int64_t index = readIndex(dsc, P(ip->c)) - dsc.low;                                               \
        if (index < 0 || index >= dsc.count)                                                                       \
            FAULT(FaultKind::IndexOutOfRange);                                                                     \
        std::memcpy(P(ip->a), P(ip->b) + static_cast<std::uint32_t>(index) * dsc.stride, size);                        \
        NEXT();                                                                                                     \
    }                                                                                                              \
    L_StoreIdx##size: {                                                                                     \
        const IndexDescriptor &dsc = descriptors[ip->aux];                                                          \
        const std::int64_t index = readIndex(dsc, P(ip->c)) - dsc.low;                                               \
        if (index < 0 || index >= dsc.count)                                                                       \
            FAULT(FaultKind::IndexOutOfRange);                                                                     \
        std::memcpy(P(ip->a) + static_cast<std::uint32_t>(index) * dsc.stride, P(ip->d), size);                        \
        NEXT();                                                                                                     \
    }
            IEC_INDEXED(1)
            IEC_INDEXED(2)
            IEC_INDEXED(4)
            IEC_INDEXED(8)
#undef IEC_INDEXED
#define IEC_INDEXED_MA(size)                                                                                       \
    L_LoadIdxMA##size: {                                                                                           \
        const IndexDescriptor &dsc = descriptors[ip->aux];                                                          \
        const std::int64_t index = mulAddIndex(dsc.indexType, P(ip->c), P(ip->d), P(ip->e)) - dsc.low;              \
        if (index < 0 || index >= dsc.count)                                                                       \
            FAULT(FaultKind::IndexOutOfRange);                                                                     \
        std::memcpy(P(ip->a), P(ip->b) + static_cast<std::uint32_t>(index) * dsc.stride, size);                    \
        NEXT();                                                                                                     \
    }
            IEC_INDEXED_MA(1)
            IEC_INDEXED_MA(2)
            IEC_INDEXED_MA(4)
            IEC_INDEXED_MA(8)
#undef IEC_INDEXED_MA
        L_BoolAndNot:
            *P(ip->a) = static_cast<std::uint8_t>(*P(ip->b) & (*P(ip->c) ^ 1u));
            NEXT();
        L_BoolAndOr:
            *P(ip->a) = static_cast<std::uint8_t>((*P(ip->b) & *P(ip->c)) | *P(ip->d));
            NEXT();
        L_BoolOrAnd:
            *P(ip->a) = static_cast<std::uint8_t>((*P(ip->b) | *P(ip->c)) & *P(ip->d));
            NEXT();
        L_NativeFb:
            runNativeBlock(static_cast<NativeBlock>(ip->aux), P(ip->a), clockNs);
            NEXT();
        L_NativeFbArgs: {
            std::uint8_t *instance = P(ip->a);
            instance[offsetof(nativedetail::TimerInstance, in)] = *P(ip->b);
            std::memcpy(instance + offsetof(nativedetail::TimerInstance, pt), P(ip->c), 8);
            runNativeBlock(static_cast<NativeBlock>(ip->aux), instance, clockNs);
            if (ip->e != 0)
                *P(ip->e) = instance[offsetof(nativedetail::TimerInstance, q)];
            NEXT();
        }
        L_BoolAndNotOrAnd:
            *P(ip->a) = static_cast<std::uint8_t>((*P(ip->b) & (*P(ip->c) ^ 1u)) | (*P(ip->d) & *P(ip->e)));
            NEXT();
        L_BoolAndNotOrAndRel:
            // Rungs come in runs: a local loop over them replaces an indirect jump per rung by a
            // well-predicted branch.
            do {
                inst[ip->a] = static_cast<std::uint8_t>((inst[ip->b] & (inst[ip->c] ^ 1u)) | (inst[ip->d] & inst[ip->e]));
                ++ip;
            } while (ip->op == op::BoolAndNotOrAndRel);
            DISPATCH();
        L_RungBlock: {
            const RungRecord *r = rungs + ip->b;
            const RungRecord *const end = r + ip->c;
            for (; r != end; ++r) {
                std::uint8_t *const out = inst + r->a;
                *out = static_cast<std::uint8_t>((out[r->b] & (out[r->c] ^ 1u)) | (out[r->d] & out[r->e]));
            }
            ip += ip->c;
            DISPATCH();
        }
        L_NativeFbPtr:
            runNativeBlock(static_cast<NativeBlock>(ip->aux), mem + load<std::uint32_t>(P(ip->a)), clockNs);
            NEXT();
        L_Load1: *P(ip->a) = mem[load<std::uint32_t>(P(ip->b))]; NEXT();
        L_Load2: std::memcpy(P(ip->a), mem + load<std::uint32_t>(P(ip->b)), 2); NEXT();
        L_Load4: std::memcpy(P(ip->a), mem + load<std::uint32_t>(P(ip->b)), 4); NEXT();
        L_Load8: std::memcpy(P(ip->a), mem + load<std::uint32_t>(P(ip->b)), 8); NEXT();
        L_LoadN: std::memmove(P(ip->a), mem + load<std::uint32_t>(P(ip->b)), ip->d); NEXT();
        L_Store1: mem[load<std::uint32_t>(P(ip->a))] = *P(ip->b); NEXT();
        L_Store2: std::memcpy(mem + load<std::uint32_t>(P(ip->a)), P(ip->b), 2); NEXT();
        L_Store4: std::memcpy(mem + load<std::uint32_t>(P(ip->a)), P(ip->b), 4); NEXT();
        L_Store8: std::memcpy(mem + load<std::uint32_t>(P(ip->a)), P(ip->b), 8); NEXT();
        L_StoreN: std::memmove(mem + load<std::uint32_t>(P(ip->a)), P(ip->b), ip->d); NEXT();
        L_StrMov: {
            const StringRef src = str(ip->b, (ip->aux & 2) != 0);
            const int n = copyInto(src, 0, src.length(), 0);
            if (!writeString(str(ip->a, (ip->aux & 1) != 0), n))
                FAULT(FaultKind::StringOverflow);
            NEXT();
        }
        L_StrConcat: {
            const bool wide = ip->aux != 0;
            const StringRef b = str(ip->b, wide), c = str(ip->c, wide);
            int n = copyInto(b, 0, b.length(), 0);
            n = copyInto(c, 0, c.length(), n);
            if (!writeString(str(ip->a, wide), n))
                FAULT(FaultKind::StringOverflow);
            NEXT();
        }
        L_StrCmp: {
            const bool wide = ip->aux != 0;
            const StringRef b = str(ip->b, wide), c = str(ip->c, wide);
            const int bLength = b.length(), cLength = c.length();
            const int n = std::min(bLength, cLength);
            int result = 0;
            for (int k = 0; k < n && result == 0; ++k)
                result = b.at(k) < c.at(k) ? -1 : b.at(k) > c.at(k) ? 1 : 0;
            if (result == 0)
                result = bLength < cLength ? -1 : bLength > cLength ? 1 : 0;
            store<std::int32_t>(P(ip->a), result);
            NEXT();
        }
        L_StrLen:
            store<std::int32_t>(P(ip->a), str(ip->b, ip->aux != 0).length());
            NEXT();
        L_StrLeft:
        L_StrRight: {
            const bool wide = ip->aux != 0;
            const StringRef s = str(ip->b, wide);
            const int len = static_cast<int>(clampInt(readInt(ip->c), 0, s.length()));
            const int n = copyInto(s, ip->op == op::StrLeft ? 0 : s.length() - len, len, 0);
            if (!writeString(str(ip->a, wide), n))
                FAULT(FaultKind::StringOverflow);
            NEXT();
        }
        L_StrMid: {
            const bool wide = ip->aux != 0;
            const StringRef s = str(ip->b, wide);
            const int from = static_cast<int>(clampInt(readInt(ip->d) - 1, 0, s.length()));
            const int len = static_cast<int>(clampInt(readInt(ip->c), 0, s.length() - from));
            if (!writeString(str(ip->a, wide), copyInto(s, from, len, 0)))
                FAULT(FaultKind::StringOverflow);
            NEXT();
        }
        L_StrInsert: {
            const bool wide = ip->aux != 0;
            const StringRef s = str(ip->b, wide), ins = str(ip->c, wide);
            const int at = static_cast<int>(clampInt(readInt(ip->d), 0, s.length()));
            int n = copyInto(s, 0, at, 0);
            n = copyInto(ins, 0, ins.length(), n);
            n = copyInto(s, at, s.length() - at, n);
            if (!writeString(str(ip->a, wide), n))
                FAULT(FaultKind::StringOverflow);
            NEXT();
        }
        L_StrDelete: {
            const bool wide = ip->aux != 0;
            const StringRef s = str(ip->b, wide);
            const int from = static_cast<int>(clampInt(readInt(ip->d) - 1, 0, s.length()));
            const int len = static_cast<int>(clampInt(readInt(ip->c), 0, s.length() - from));
            int n = copyInto(s, 0, from, 0);
            n = copyInto(s, from + len, s.length() - from - len, n);
            if (!writeString(str(ip->a, wide), n))
                FAULT(FaultKind::StringOverflow);
            NEXT();
        }
        L_StrReplace: {
            const bool wide = ip->aux != 0;
            const StringRef s = str(ip->b, wide), with = str(ip->c, wide);
            const int length = s.length();
            const int from = static_cast<int>(clampInt(readInt(ip->d + 4) - 1, 0, length));
            const int len = static_cast<int>(clampInt(readInt(ip->d), 0, length - from));
            int n = copyInto(s, 0, from, 0);
            n = copyInto(with, 0, with.length(), n);
            n = copyInto(s, from + len, length - from - len, n);
            if (!writeString(str(ip->a, wide), n))
                FAULT(FaultKind::StringOverflow);
            NEXT();
        }
        L_StrFind: {
            const bool wide = ip->aux != 0;
            const StringRef s = str(ip->b, wide), what = str(ip->c, wide);
            const int length = s.length(), whatLength = what.length(); // scans for the NUL: once
            int found = 0;
            for (int k = 0; whatLength > 0 && k + whatLength <= length && found == 0; ++k) {
                int m = 0;
                while (m < whatLength && s.at(k + m) == what.at(m))
                    ++m;
                if (m == whatLength)
                    found = k + 1;
            }
            store<std::int32_t>(P(ip->a), found);
            NEXT();
        }
        L_Now:
            store<std::int64_t>(P(ip->a), clockNs);
            NEXT();
        L_Log: {
            if (log.size() < kMaxLog) {
                const StringRef text = str(ip->b, false);
                const int length = text.length();
                QString message;
                for (int i = 0; i < length; ++i)
                    message += QChar(text.at(i));
                log.push_back({load<std::int16_t>(P(ip->a)), message});
            }
            NEXT();
        }
        L_CheckRange: {
            const IndexDescriptor &dsc = descriptors[ip->aux];
            const std::int64_t offset = readIndex(dsc, P(ip->b)) - dsc.low;
            if (offset < 0 || offset >= dsc.count)
                FAULT(FaultKind::OutOfSubrange);
            NEXT();
        }
        L_CheckPtr: {
            // Offsets below 8 are never a variable (offset 0 is the null pointer).
            const std::uint64_t address = load<std::uint32_t>(P(ip->b));
            if (address < 8)
                FAULT(FaultKind::NullPointer);
            if (address + ip->d > m_memory.size())
                FAULT(FaultKind::InvalidAddress);
            NEXT();
        }
        L_Fault:
            FAULT(static_cast<FaultKind>(ip->aux));
        L_JitEnter: {
            const JitEntry &entry = m_jit->entry(ip->a);
            std::uint64_t left = budget; // a copy: the local itself stays in a register
            const std::uint64_t result = entry.region(mem, inst, &left, entry.target, &clockNs);
            budget = left;
            const auto next = static_cast<std::uint32_t>(result);
            if (const auto kind = static_cast<FaultKind>(result >> 32); kind != FaultKind::None) {
                m_faultPc = next;
                return kind;
            }
            ip = code + next;
            DISPATCH();
        }
        L_Break: {
            const auto pc = static_cast<std::uint32_t>(ip - code);
            const std::uint8_t stop = m_stops[pc];
            const bool halt = pc != passStopAt
                && ((stop & BreakpointStop) || ((stop & LineStop) && std::int64_t(depth) <= stepMaxDepth));
            passStopAt = std::numeric_limits<std::uint32_t>::max();
            if (!halt)
                goto *dispatch[m_originalOps[pc]];
            Halt saved;
            saved.pc = pc;
            saved.instance = static_cast<std::uint32_t>(inst - mem);
            saved.budget = budget;
            for (size_t i = 0; i < depth; ++i)
                saved.callers.push_back({static_cast<std::uint32_t>(frames[i].ip - code), static_cast<std::uint32_t>(frames[i].base - mem)});
            m_halt = std::move(saved);
            m_faultPc = pc;
            return FaultKind::Halted;
        }
    }
#undef DISPATCH
#undef NEXT
#pragma GCC diagnostic pop
#undef P
#undef FAULT
#undef absolute
#undef readInt
#undef str
}

} // namespace iec::interp
