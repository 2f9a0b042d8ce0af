#pragma once

#include "interpreter/vm/bytecode.h"

#include <cstdint>

namespace iec::interp {

// TON, TOF and TP in C++, for op::NativeFb. They read and write the instance with the layout of
// their ST declarations in compiler/stdlib.cpp (IN, PT, Q, ET, START, RUNNING/TRIGGERED), which the
// compiler checks before it emits op::NativeFb, and behave exactly like that ST (tst_stdfb runs
// every trace both ways).
void runNativeBlock(NativeBlock block, std::uint8_t *instance, std::int64_t now);

} // namespace iec::interp
