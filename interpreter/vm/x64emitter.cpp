#include "interpreter/vm/x64emitter.h"

#include <cstring>

namespace iec::interp::x64 {

namespace {

bool isByteRegNeedingRex(int r)
{
    // spl, bpl, sil, dil exist only with a REX prefix; without one 4..7 mean ah, ch, dh, bh.
    return r >= 4 && r <= 7;
}

std::uint8_t scaleBits(int scale)
{
    switch (scale) {
    case 2: return 1;
    case 4: return 2;
    case 8: return 3;
    default: return 0;
    }
}

std::uint8_t aluDigit(Emitter::Alu op)
{
    switch (op) {
    case Emitter::Alu::Add: return 0;
    case Emitter::Alu::Or: return 1;
    case Emitter::Alu::And: return 4;
    case Emitter::Alu::Sub: return 5;
    case Emitter::Alu::Xor: return 6;
    case Emitter::Alu::Cmp: return 7;
    }
    return 0;
}

} // namespace

Label Emitter::newLabel()
{
    m_labels.push_back(-1);
    return Label{int(m_labels.size()) - 1};
}

void Emitter::bind(Label label)
{
    m_labels[size_t(label.id)] = std::int64_t(m_code.size());
}

bool Emitter::finish()
{
    for (const auto &[at, id] : m_fixups) {
        const std::int64_t target = m_labels[size_t(id)];
        if (target < 0)
            return false;
        const std::int32_t rel = std::int32_t(target - std::int64_t(at + 4));
        std::memcpy(m_code.data() + at, &rel, 4);
    }
    m_fixups.clear();
    return true;
}

void Emitter::imm32(std::int32_t v)
{
    std::uint8_t bytes[4];
    std::memcpy(bytes, &v, 4);
    m_code.insert(m_code.end(), bytes, bytes + 4);
}

void Emitter::rmMem(std::uint8_t prefix, bool w, std::initializer_list<std::uint8_t> opcode, int reg, const Mem &m, bool forceRex)
{
    if (prefix)
        byte(prefix);
    const int index = m.index == kNoIndex ? 0 : m.index;
    const std::uint8_t rex = std::uint8_t(0x40 | (w ? 8 : 0) | ((reg >> 3) & 1) << 2 | ((index >> 3) & 1) << 1 | ((m.base >> 3) & 1));
    if (rex != 0x40 || forceRex)
        byte(rex);
    for (std::uint8_t b : opcode)
        byte(b);
    // Always mod = 10 (disp32): one encoding for every base, r13 included.
    if (m.index == kNoIndex && (m.base & 7) != 4) {
        byte(std::uint8_t(0x80 | (reg & 7) << 3 | (m.base & 7)));
    } else {
        byte(std::uint8_t(0x80 | (reg & 7) << 3 | 4));
        const std::uint8_t indexBits = m.index == kNoIndex ? 4 : std::uint8_t(m.index & 7); // 100: no index
        byte(std::uint8_t(scaleBits(m.scale) << 6 | indexBits << 3 | (m.base & 7)));
    }
    imm32(m.disp);
}

void Emitter::rmReg(std::uint8_t prefix, bool w, std::initializer_list<std::uint8_t> opcode, int reg, int rm, bool forceRex)
{
    if (prefix)
        byte(prefix);
    const std::uint8_t rex = std::uint8_t(0x40 | (w ? 8 : 0) | ((reg >> 3) & 1) << 2 | ((rm >> 3) & 1));
    if (rex != 0x40 || forceRex)
        byte(rex);
    for (std::uint8_t b : opcode)
        byte(b);
    byte(std::uint8_t(0xC0 | (reg & 7) << 3 | (rm & 7)));
}

void Emitter::load(int bytes, Reg dst, const Mem &m, bool signExtend)
{
    switch (bytes) {
    case 1: signExtend ? rmMem(0, true, {0x0F, 0xBE}, dst, m) : rmMem(0, false, {0x0F, 0xB6}, dst, m); break;
    case 2: signExtend ? rmMem(0, true, {0x0F, 0xBF}, dst, m) : rmMem(0, false, {0x0F, 0xB7}, dst, m); break;
    case 4: signExtend ? rmMem(0, true, {0x63}, dst, m) : rmMem(0, false, {0x8B}, dst, m); break;
    default: rmMem(0, true, {0x8B}, dst, m); break;
    }
}

void Emitter::store(int bytes, const Mem &m, Reg src)
{
    switch (bytes) {
    case 1: rmMem(0, false, {0x88}, src, m, isByteRegNeedingRex(src)); break;
    case 2: rmMem(0x66, false, {0x89}, src, m); break;
    case 4: rmMem(0, false, {0x89}, src, m); break;
    default: rmMem(0, true, {0x89}, src, m); break;
    }
}

void Emitter::movRR(bool wide, Reg dst, Reg src)
{
    rmReg(0, wide, {0x8B}, dst, src);
}

void Emitter::movImm(Reg dst, std::int64_t value)
{
    if (value >= 0 && value <= 0xffffffffLL) {
        if (dst >= 8)
            byte(0x41);
        byte(std::uint8_t(0xB8 + (dst & 7)));
        imm32(std::int32_t(std::uint32_t(value)));
    } else if (value >= INT32_MIN && value <= INT32_MAX) {
        rmReg(0, true, {0xC7}, 0, dst);
        imm32(std::int32_t(value));
    } else {
        byte(std::uint8_t(0x48 | (dst >> 3)));
        byte(std::uint8_t(0xB8 + (dst & 7)));
        std::uint8_t bytes[8];
        std::memcpy(bytes, &value, 8);
        m_code.insert(m_code.end(), bytes, bytes + 8);
    }
}

void Emitter::movsxdRR(Reg dst, Reg src)
{
    rmReg(0, true, {0x63}, dst, src);
}

void Emitter::extend(int bytes, bool sign, Reg r)
{
    switch (bytes) {
    case 1: sign ? rmReg(0, true, {0x0F, 0xBE}, r, r) : rmReg(0, false, {0x0F, 0xB6}, r, r, isByteRegNeedingRex(r)); break;
    case 2: sign ? rmReg(0, true, {0x0F, 0xBF}, r, r) : rmReg(0, false, {0x0F, 0xB7}, r, r); break;
    case 4: sign ? movsxdRR(r, r) : movRR(false, r, r); break;
    default: break;
    }
}

void Emitter::alu(Alu op, bool wide, Reg dst, Reg src)
{
    rmReg(0, wide, {std::uint8_t(op)}, dst, src);
}

void Emitter::aluMem(Alu op, bool wide, Reg dst, const Mem &m)
{
    rmMem(0, wide, {std::uint8_t(op)}, dst, m);
}

void Emitter::aluImm(Alu op, bool wide, Reg dst, std::int32_t imm)
{
    if (imm >= -128 && imm <= 127) { // the short form with a sign-extended byte
        rmReg(0, wide, {0x83}, aluDigit(op), dst);
        byte(std::uint8_t(std::int8_t(imm)));
        return;
    }
    rmReg(0, wide, {0x81}, aluDigit(op), dst);
    imm32(imm);
}

void Emitter::aluMem8(Alu op, Reg dst8, const Mem &m)
{
    // The 8-bit forms are one below the 32-bit ones (22 AND r8, r/m8; 23 AND r32, r/m32; ...).
    rmMem(0, false, {std::uint8_t(std::uint8_t(op) - 1)}, dst8, m, isByteRegNeedingRex(dst8));
}

void Emitter::alu8(Alu op, Reg dst8, Reg src8)
{
    rmReg(0, false, {std::uint8_t(std::uint8_t(op) - 1)}, dst8, src8, isByteRegNeedingRex(dst8) || isByteRegNeedingRex(src8));
}

void Emitter::test8(Reg a8, Reg b8)
{
    rmReg(0, false, {0x84}, b8, a8, isByteRegNeedingRex(a8) || isByteRegNeedingRex(b8));
}

void Emitter::shrImm(bool wide, Reg r, std::uint8_t count)
{
    rmReg(0, wide, {0xC1}, 5, r);
    byte(count);
}

void Emitter::imul(bool wide, Reg dst, Reg src)
{
    rmReg(0, wide, {0x0F, 0xAF}, dst, src);
}

void Emitter::imulMem(bool wide, Reg dst, const Mem &m)
{
    rmMem(0, wide, {0x0F, 0xAF}, dst, m);
}

void Emitter::imulImm(bool wide, Reg dst, Reg src, std::int32_t imm)
{
    rmReg(0, wide, {0x69}, dst, src);
    imm32(imm);
}

void Emitter::neg(bool wide, Reg r)
{
    rmReg(0, wide, {0xF7}, 3, r);
}

void Emitter::notR(bool wide, Reg r)
{
    rmReg(0, wide, {0xF7}, 2, r);
}

void Emitter::signExtendAcc(bool wide)
{
    if (wide)
        byte(0x48);
    byte(0x99);
}

void Emitter::div(bool wide, bool isSigned, Reg divisor)
{
    rmReg(0, wide, {0xF7}, isSigned ? 7 : 6, divisor);
}

void Emitter::cmpMem8Imm(const Mem &m, std::uint8_t imm)
{
    rmMem(0, false, {0x80}, 7, m);
    byte(imm);
}

void Emitter::test(bool wide, Reg a, Reg b)
{
    rmReg(0, wide, {0x85}, b, a);
}

void Emitter::setcc(Cond c, Reg dst8)
{
    rmReg(0, false, {0x0F, std::uint8_t(0x90 + c)}, 0, dst8, isByteRegNeedingRex(dst8));
}

void Emitter::movzx8(Reg dst, Reg src8)
{
    rmReg(0, false, {0x0F, 0xB6}, dst, src8, isByteRegNeedingRex(src8));
}

void Emitter::fload(bool isDouble, int xmm, const Mem &m)
{
    rmMem(isDouble ? 0xF2 : 0xF3, false, {0x0F, 0x10}, xmm, m);
}

void Emitter::fstore(bool isDouble, const Mem &m, int xmm)
{
    rmMem(isDouble ? 0xF2 : 0xF3, false, {0x0F, 0x11}, xmm, m);
}

void Emitter::fmovRR(int dst, int src)
{
    rmReg(0, false, {0x0F, 0x28}, dst, src);
}

void Emitter::fop(Fop op, bool isDouble, int dst, int src)
{
    rmReg(isDouble ? 0xF2 : 0xF3, false, {0x0F, std::uint8_t(op)}, dst, src);
}

void Emitter::fcompare(bool isDouble, int a, int b)
{
    rmReg(isDouble ? 0x66 : 0, false, {0x0F, 0x2E}, a, b);
}

void Emitter::cvtIntToFloat(bool isDouble, bool from64, int xmm, Reg src)
{
    rmReg(isDouble ? 0xF2 : 0xF3, from64, {0x0F, 0x2A}, xmm, src);
}

void Emitter::cvtFloatToFloat(bool toDouble, int dst, int src)
{
    rmReg(toDouble ? 0xF3 : 0xF2, false, {0x0F, 0x5A}, dst, src);
}

void Emitter::movGprToXmm(bool wide, int xmm, Reg src)
{
    rmReg(0x66, wide, {0x0F, 0x6E}, xmm, src);
}

void Emitter::movXmmToGpr(bool wide, Reg dst, int xmm)
{
    rmReg(0x66, wide, {0x0F, 0x7E}, xmm, dst);
}

void Emitter::rel32To(Label target)
{
    m_fixups.emplace_back(m_code.size(), target.id);
    imm32(0);
}

void Emitter::jmp(Label target)
{
    byte(0xE9);
    rel32To(target);
}

void Emitter::jcc(Cond c, Label target)
{
    byte(0x0F);
    byte(std::uint8_t(0x80 + c));
    rel32To(target);
}

void Emitter::jmpReg(Reg r)
{
    rmReg(0, false, {0xFF}, 4, r);
}

void Emitter::callReg(Reg r)
{
    rmReg(0, false, {0xFF}, 2, r);
}

void Emitter::lea(Reg dst, const Mem &m)
{
    rmMem(0, true, {0x8D}, dst, m);
}

void Emitter::push(Reg r)
{
    if (r >= 8)
        byte(0x41);
    byte(std::uint8_t(0x50 + (r & 7)));
}

void Emitter::pop(Reg r)
{
    if (r >= 8)
        byte(0x41);
    byte(std::uint8_t(0x58 + (r & 7)));
}

void Emitter::ret()
{
    byte(0xC3);
}

} // namespace iec::interp::x64
