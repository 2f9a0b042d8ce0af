#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <vector>

// A small x86-64 machine-code emitter for the JIT (jit.h): only the instructions the translation
// of VM code needs. Memory operands are always [base + index * scale + disp32].
namespace iec::interp::x64 {

enum Reg : std::uint8_t { rax, rcx, rdx, rbx, rsp, rbp, rsi, rdi, r8, r9, r10, r11, r12, r13, r14, r15 };
constexpr int kNoIndex = -1;

// Condition codes, as in Jcc / SETcc.
enum Cond : std::uint8_t { O, NO, B, AE, E, NE, BE, A, S, NS, P, NP, L, GE, LE, G };

struct Mem {
    Reg base = rax;
    int index = kNoIndex; // a Reg, or kNoIndex
    int scale = 1;        // 1, 2, 4 or 8
    std::int32_t disp = 0;
};

// A place in the code a jump goes to; bound later or earlier.
struct Label {
    int id = -1;
};

class Emitter
{
public:
    Label newLabel();
    void bind(Label label);
    std::size_t size() const { return m_code.size(); }

    // Resolves jumps; false if a label was used but never bound.
    bool finish();
    const std::vector<std::uint8_t> &code() const { return m_code; }
    // Offset of a bound label in the code.
    std::size_t offsetOf(Label label) const { return std::size_t(m_labels[std::size_t(label.id)]); }

    // ---- integer moves -------------------------------------------------------------------
    void load(int bytes, Reg dst, const Mem &m, bool signExtend); // 1/2/4/8 bytes into dst (64-bit)
    void store(int bytes, const Mem &m, Reg src);
    void movRR(bool wide, Reg dst, Reg src);
    void movImm(Reg dst, std::int64_t value);
    void movsxdRR(Reg dst, Reg src);           // dst (64) = sign-extended src (32)
    void extend(int bytes, bool sign, Reg r);  // r = r's low bytes extended to 64 bits

    // ---- integer arithmetic, dst op= src (wide: 64-bit, else 32-bit) --------------------------
    enum class Alu : std::uint8_t { Add = 0x03, Or = 0x0B, And = 0x23, Sub = 0x2B, Xor = 0x33, Cmp = 0x3B };
    void alu(Alu op, bool wide, Reg dst, Reg src);
    void aluMem(Alu op, bool wide, Reg dst, const Mem &m);
    void aluImm(Alu op, bool wide, Reg dst, std::int32_t imm);
    void aluMem8(Alu op, Reg dst8, const Mem &m); // dst's low byte op= the byte at m (al, cl, dl, bl)
    void shrImm(bool wide, Reg r, std::uint8_t count);
    void alu8(Alu op, Reg dst8, Reg src8);   // low bytes: dst op= src (al, cl, dl, bl)
    void test8(Reg a8, Reg b8);
    void imul(bool wide, Reg dst, Reg src);
    void imulMem(bool wide, Reg dst, const Mem &m);
    void imulImm(bool wide, Reg dst, Reg src, std::int32_t imm);
    void neg(bool wide, Reg r);
    void notR(bool wide, Reg r);
    void signExtendAcc(bool wide);              // cdq / cqo
    void div(bool wide, bool isSigned, Reg divisor); // rdx:rax / divisor
    void cmpMem8Imm(const Mem &m, std::uint8_t imm);
    void test(bool wide, Reg a, Reg b);
    void setcc(Cond c, Reg dst8);               // dst's low byte = condition (al, cl, dl, bl only)
    void movzx8(Reg dst, Reg src8);             // dst (32) = src's low byte

    // ---- SSE scalar floating point (xmm registers numbered 0..15) ------------------------------
    void fload(bool isDouble, int xmm, const Mem &m);
    void fstore(bool isDouble, const Mem &m, int xmm);
    void fmovRR(int dst, int src);
    enum class Fop : std::uint8_t { Add = 0x58, Mul = 0x59, Sub = 0x5C, Div = 0x5E };
    void fop(Fop op, bool isDouble, int dst, int src);
    void fcompare(bool isDouble, int a, int b); // flags from ucomis a, b
    void cvtIntToFloat(bool isDouble, bool from64, int xmm, Reg src);
    void cvtFloatToFloat(bool toDouble, int dst, int src);
    void movGprToXmm(bool wide, int xmm, Reg src);
    void movXmmToGpr(bool wide, Reg dst, int xmm);

    // ---- control ---------------------------------------------------------------------------
    void jmp(Label target);
    void jcc(Cond c, Label target);
    void jmpReg(Reg r);
    void callReg(Reg r);
    void lea(Reg dst, const Mem &m);
    void push(Reg r);
    void pop(Reg r);
    void ret();

private:
    void byte(std::uint8_t b) { m_code.push_back(b); }
    void imm32(std::int32_t v);
    // prefix (0 = none), REX.W, opcode bytes, the ModRM reg field, then the r/m operand.
    void rmMem(std::uint8_t prefix, bool w, std::initializer_list<std::uint8_t> opcode, int reg, const Mem &m, bool forceRex = false);
    void rmReg(std::uint8_t prefix, bool w, std::initializer_list<std::uint8_t> opcode, int reg, int rm, bool forceRex = false);
    void rel32To(Label target);

    std::vector<std::uint8_t> m_code;
    std::vector<std::int64_t> m_labels;              // offset, or -1 while unbound
    std::vector<std::pair<std::size_t, int>> m_fixups; // where a rel32 sits, which label
};

} // namespace iec::interp::x64
