#pragma once

#include "interpreter/compiler/types.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <memory>
#include <vector>

namespace iec::interp {

// ---- operands -------------------------------------------------------------------------------
// An operand is a byte offset into the memory image. With kInstanceRelative set it counts from
// the base of the instance that is running (the program or FB instance), otherwise from the
// start of the image (globals, function variables, temporaries, constants). The VM resolves it
// as bases[operand >> 31] + (operand & kOffsetMask): no branch, no lookup.
constexpr std::uint32_t kInstanceRelative = 0x80000000u;
constexpr std::uint32_t kOffsetMask = 0x7fffffffu;

// ---- opcodes --------------------------------------------------------------------------------
// Typed families occupy kVtCount consecutive opcodes, one per VT (I8 ... F64), so the compiler
// picks `family + vt` and the VM's dispatch is one switch. Operands: a = destination, b and c
// = sources, unless said otherwise.
#define IEC_TYPED_FAMILIES(X)                                                                               \
    X(Add) X(Sub) X(Mul) X(Div) X(Mod) X(Neg) X(Abs) X(Min) X(Max)                                          \
    X(Eq) X(Ne) X(Lt) X(Le) X(Gt) X(Ge)                   /* a (BOOL) = b op c */                              \
    X(And) X(Or) X(Xor) X(Not) X(Shl) X(Shr) X(Rol) X(Ror) /* unsigned VTs only */                        \
    X(GetBit)                                             /* a (BOOL) = bit d of b */                      \
    X(SetBit)                                             /* bit d of a = b (BOOL) */                       \
    X(Expt)                                               /* a = b ** c, c is LREAL (reals only) */         \
    X(Math)                                               /* a = fn[aux](b) (reals only) */                \
    X(ToStr)                                              /* a (STRING) = text of b; aux: TextFormat<<1|wide*/\
    X(FromStr)                                            /* a = value of the STRING b; aux as ToStr */    \
    X(Bcd)                                                /* a = BCD of b (aux 0) or binary of BCD b (1) */ \
    X(BrEq) X(BrNe) X(BrLt) X(BrLe) X(BrGt) X(BrGe)       /* if b op c: pc = a (fused compare and jump) */ \
    X(IncBrLe) X(IncBrGe)                                 /* FOR: a += b; if a <= c (>= c): pc = d */     \
    X(IncBrLt) X(IncBrGt)                                 /* WHILE i < n DO ... i := i + s: the same */    \
    X(MulAdd)                                             /* a = b * c + d (wraps like Mul then Add) */

#define IEC_PLAIN_OPS(X)                                                                                    \
    X(Nop)                                                                                                   \
    X(Mov1) X(Mov2) X(Mov4) X(Mov8) X(MovN)               /* a = b; MovN copies d bytes */                \
    X(BoolNot)                                            /* a = b ^ 1 */                                   \
    X(Jmp)                                                /* pc = a */                                      \
    X(Jz) X(Jnz)                                          /* if BOOL b is (not) zero: pc = a */             \
    X(CallFb)                                             /* run POU aux with the instance at operand a */ \
    X(CallFbPtr)                                          /* ... with the instance at the address in a */  \
    X(CallFn)                                             /* run function POU aux */                        \
    X(Ret)                                                                                                   \
    X(Halt)                                               /* end of a task's code */                        \
    X(Lea)                                                /* a (UDINT) = absolute address of operand b */   \
    X(Index)                                              /* a = address b + (idx c - low) * stride; idx  \
                                                              checked against descriptor aux */            \
    X(IndexPtr)                                           /* the same with the base address read from b */ \
    X(PtrAdd)                                             /* a = address in b + d */                        \
    X(Load1) X(Load2) X(Load4) X(Load8) X(LoadN)         /* a = bytes at the address in b (d bytes) */     \
    X(Store1) X(Store2) X(Store4) X(Store8) X(StoreN)    /* bytes at the address in a = b (d bytes) */     \
    X(LoadIdx1) X(LoadIdx2) X(LoadIdx4) X(LoadIdx8)       /* a = element c of the array at b (Index+Load) */\
    X(StoreIdx1) X(StoreIdx2) X(StoreIdx4) X(StoreIdx8)   /* element c of the array at a = d (Index+Store)*/\
    X(LoadIdxMA1) X(LoadIdxMA2) X(LoadIdxMA4) X(LoadIdxMA8) /* a = element c * d + e of the array at b   \
                                                              (MulAdd+Index+Load: a[i * 24 + k]) */        \
    X(BoolAndNot)                                         /* a = b AND NOT c (BOOL) */                      \
    X(BoolAndOr)                                          /* a = (b AND c) OR d (BOOL): contacts in series, \
                                                              parallel to a branch */                         \
    X(BoolOrAnd)                                          /* a = (b OR c) AND d (BOOL) */                   \
    X(NativeFb)                                           /* standard FB aux (NativeBlock) on instance a */ \
    X(NativeFbPtr)                                        /* ... with the instance at the address in a */  \
    X(NativeFbArgs)                                       /* IN := b, PT := c, then NativeFb on a; then  \
                                                              e := Q unless e is 0 */                       \
    X(BoolAndNotOrAnd)                                    /* a = (b AND NOT c) OR (d AND e) (BOOL): a rung \
                                                              with a normally closed contact and a branch */\
    X(BoolAndNotOrAndRel)                                 /* the same, all five operands instance-relative \
                                                              offsets without kInstanceRelative (rungs on \
                                                              a program's own variables: no select) */      \
    X(RungBlock)                                          /* the run of c BoolAndNotOrAndRel starting here, \
                                                              from Module::rungs[b...] (packed), then skips \
                                                              them; a jump into the run runs the rest */    \
    X(StrMov)                                             /* string a = string b (checks the capacity);     \
                                                              aux bit 0: a is wide, bit 1: b is wide */      \
    X(StrConcat)                                          /* a = b & c */                                   \
    X(StrCmp)                                             /* a (DINT) = compare(b, c): -1, 0, 1 */          \
    X(StrLen)                                             /* a (DINT) = LEN(b) */                           \
    X(StrLeft) X(StrRight)                                /* a = LEFT/RIGHT(b, DINT c) */                   \
    X(StrMid)                                             /* a = MID(b, DINT c = length, DINT d = pos) */   \
    X(StrInsert)                                          /* a = INSERT(b, c, DINT d) */                    \
    X(StrDelete)                                          /* a = DELETE(b, DINT c = length, DINT d = pos) */\
    X(StrReplace)                                         /* a = REPLACE(b, c, DINT d = L, DINT d+4 = P) */ \
    X(StrFind)                                            /* a (DINT) = FIND(b, c) */                       \
    X(Now)                                                /* a (LTIME) = the virtual clock */               \
    X(CheckRange)                                         /* fault unless b lies in descriptor aux's range \
                                                              (an assignment to a subrange type) */         \
    X(Log)                                                /* message: the STRING b at level a (Beremiz LOGGER) \
                                                              into Vm::log */                              \
    X(CheckPtr)                                           /* fault unless the address in b lies in the   \
                                                              image with d bytes after it (pointers and   \
                                                              references: 0 is NullPointer) */             \
    X(Fault)                                              /* stop with the fault kind in aux */           \
    X(JitEnter)                                           /* run machine-code entry a (jit.h); only in the \
                                                              JIT's copy of the code */                    \
    X(Break)                                              /* a place the debugger may halt at (vm.h); only \
                                                              in the debugger's copy of the code */

namespace op {
enum : std::uint16_t {
#define IEC_FAMILY(name) name, name##_Last = name + kVtCount - 1,
    IEC_TYPED_FAMILIES(IEC_FAMILY)
#undef IEC_FAMILY
    Convert,                                  // Convert + from * kVtCount + to: a = b converted
    Convert_Last = Convert + kVtCount * kVtCount - 1,
#define IEC_PLAIN(name) name,
    IEC_PLAIN_OPS(IEC_PLAIN)
#undef IEC_PLAIN
    Count
};
} // namespace op

constexpr std::uint16_t typedOp(std::uint16_t family, VT vt)
{
    return static_cast<std::uint16_t>(family + static_cast<int>(vt));
}
constexpr std::uint16_t convertOp(VT from, VT to)
{
    return static_cast<std::uint16_t>(op::Convert + static_cast<int>(from) * kVtCount + static_cast<int>(to));
}

// How op::ToStr / op::FromStr write and read values (aux >> 1).
// Bit strings print as 16#2a and integral reals as 42, as the Beremiz test suite expects.
enum class TextFormat : std::uint16_t { Number, Bool, Duration, Date, TimeOfDay, DateAndTime, Hex };

// Standard function blocks that run as C++ (op::NativeFb); they behave exactly like their ST
// versions in stdlib.cpp (tst_stdfb runs both) and are what makes 1,000 timers cheap.
enum class NativeBlock : std::uint16_t { Ton, Tof, Tp };

// Real functions for op::Math, indexed by aux.
enum class MathFn : std::uint16_t { Sqrt, Ln, Log, Exp, Sin, Cos, Tan, Asin, Acos, Atan, Trunc, Round, Count };

struct Instr {
    std::uint16_t op = op::Nop;
    std::uint16_t aux = 0;
    std::uint32_t a = 0, b = 0, c = 0, d = 0;
    std::uint32_t e = 0; // the fifth operand of a few superinstructions (24 bytes in all)
};

// One rung of op::RungBlock: out = (in[b] AND NOT in[c]) OR (in[d] AND in[e]), every byte at
// instance + a + delta. Half the size of the instruction it stands for, so long runs of rungs
// stream through the cache faster.
struct RungRecord {
    std::uint32_t a = 0;
    std::int16_t b = 0, c = 0, d = 0, e = 0;
};

// Bounds of one array dimension for op::Index.
struct IndexDescriptor {
    std::int64_t low = 0;
    std::int64_t count = 0;
    std::uint32_t stride = 0;
    VT indexType = VT::I64; // how the index operand is stored (the index expression's own type)
};

// What stops a program: the runtime reports it with the POU and line of the instruction.
enum class FaultKind : std::uint16_t {
    None,
    DivisionByZero,
    IndexOutOfRange,
    StringOverflow,
    BudgetExceeded,
    CallDepthExceeded,
    InvalidProgram,
    OutOfSubrange,
    NullPointer,    // a pointer or reference that is 0 was dereferenced
    InvalidAddress, // a pointer that points outside the program's memory was dereferenced
    Halted,         // not a fault: the debugger halted the run (Vm::resume goes on)
};
QString faultMessage(FaultKind kind);

// Where an instruction came from, for faults and breakpoints.
struct LineEntry {
    std::uint32_t pc = 0;
    int pou = -1;
    int line = 0;
    qint64 localId = -1; // graphical bodies: the element the code is for (a network's root, a step)
};

struct CompiledPou {
    QString name;
    ast::PouKind kind = ast::PouKind::Program;
    std::uint32_t entry = 0;
    const Type *instanceType = nullptr; // programs and FBs: the layout of an instance
};

struct ProgramInstance {
    QString name;      // Main, or the name given in the configuration
    int pou = -1;
    std::uint32_t base = 0;
    std::uint32_t entry = 0; // code that calls the program then halts
};

struct TaskInfo {
    QString name;
    int priority = 0;
    std::int64_t intervalNs = 0;      // 0: runs every cycle
    std::int32_t singleOffset = -1;   // SINGLE: absolute offset of the BOOL that triggers it
    std::vector<int> programs;        // indices in Module::programs
    std::uint32_t entry = 0;          // code that runs the programs in order, then halts
};

// A variable with an address in the process image (AT %QX0.1 or a %QX0.1 used in code). The
// program reads and writes the image itself; `offset` is the variable's own slot, which names
// (Main.q) resolve to and the symbol table redirects to the image.
struct LocatedVar {
    QString address;     // %QX0.1
    char area = 'I';     // I, Q, M
    std::uint32_t byte = 0;
    int bit = -1;        // -1: not a bit address
    std::uint32_t size = 1;
    std::uint32_t offset = 0; // absolute, in the memory image
};

// A named root of the symbol table: a global or a program instance.
struct Symbol {
    QString name;
    const Type *type = nullptr;
    std::uint32_t offset = 0; // absolute
};

// A named global variable list (CODESYS GVL): its variables can be named List.Variable too.
struct GlobalList {
    QString name;
    QStringList variables; // as declared
};

struct RetainRange {
    std::uint32_t offset = 0;
    std::uint32_t size = 0;
};

// Everything the VM needs to run a compiled project.
struct Module {
    std::shared_ptr<TypeTable> types;
    std::vector<Instr> code;
    std::vector<IndexDescriptor> indexDescriptors;
    std::vector<RungRecord> rungs;
    std::vector<std::uint8_t> initialImage;
    std::vector<CompiledPou> pous;
    std::vector<ProgramInstance> programs;
    std::vector<TaskInfo> tasks;
    std::vector<LocatedVar> located;
    std::vector<Symbol> symbols;
    std::vector<GlobalList> globalLists;
    std::vector<RetainRange> retain;
    std::vector<LineEntry> lines;
    std::uint32_t imageSizes[3] = {0, 0, 0}; // I, Q, M bytes
    std::uint32_t imageBase[3] = {0, 0, 0};  // where the I, Q, M areas lie in the memory image

    // The POU and line of the instruction at pc.
    LineEntry lineAt(std::uint32_t pc) const;
};

} // namespace iec::interp
