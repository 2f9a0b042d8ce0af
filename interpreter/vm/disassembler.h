#pragma once

#include "interpreter/vm/bytecode.h"

#include <QString>

namespace iec::interp {

// "Add.I16 a=i+4 b=@120 c=t+0" per instruction: i+ is instance relative, @ absolute.
QString opcodeName(std::uint16_t opcode);
QString disassemble(const Module &module, std::uint32_t from = 0, std::uint32_t to = UINT32_MAX);

} // namespace iec::interp
