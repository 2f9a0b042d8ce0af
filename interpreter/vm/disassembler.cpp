#include "interpreter/vm/disassembler.h"

#include <array>

namespace iec::interp {

QString opcodeName(std::uint16_t opcode)
{
    static const std::array<const char *, kVtCount> vts{"I8", "I16", "I32", "I64", "U8", "U16", "U32", "U64", "F32", "F64"};
    struct Family {
        const char *name;
        std::uint16_t first;
    };
    static const Family families[] = {
#define IEC_FAMILY_NAME(name) {#name, op::name},
        IEC_TYPED_FAMILIES(IEC_FAMILY_NAME)
#undef IEC_FAMILY_NAME
    };
    for (const Family &f : families) {
        if (opcode >= f.first && opcode < f.first + kVtCount)
            return QStringLiteral("%1.%2").arg(QLatin1String(f.name), QLatin1String(vts[size_t(opcode - f.first)]));
    }
    if (opcode >= op::Convert && opcode <= op::Convert_Last) {
        const int n = opcode - op::Convert;
        return QStringLiteral("Convert.%1.%2").arg(QLatin1String(vts[size_t(n / kVtCount)]), QLatin1String(vts[size_t(n % kVtCount)]));
    }
    static const std::pair<std::uint16_t, const char *> plain[] = {
#define IEC_PLAIN_NAME(name) {op::name, #name},
        IEC_PLAIN_OPS(IEC_PLAIN_NAME)
#undef IEC_PLAIN_NAME
    };
    for (const auto &[code, name] : plain) {
        if (code == opcode)
            return QLatin1String(name);
    }
    return QStringLiteral("?%1").arg(opcode);
}

QString disassemble(const Module &module, std::uint32_t from, std::uint32_t to)
{
    const auto operand = [](std::uint32_t x) {
        return (x & kInstanceRelative) ? QStringLiteral("i+%1").arg(x & kOffsetMask) : QStringLiteral("@%1").arg(x);
    };
    QString text;
    for (std::uint32_t pc = from; pc < module.code.size() && pc < to; ++pc) {
        const Instr &i = module.code[pc];
        text += QStringLiteral("%1  %2 a=%3 b=%4 c=%5 d=%6 aux=%7\n")
                    .arg(pc, 5)
                    .arg(opcodeName(i.op), -14)
                    .arg(operand(i.a), operand(i.b), operand(i.c))
                    .arg(i.d)
                    .arg(i.aux);
        if (i.e != 0) {
            text.chop(1);
            text += QStringLiteral(" e=%1\n").arg(operand(i.e));
        }
    }
    return text;
}

} // namespace iec::interp
