#pragma once

// Shared by the fuzz targets (each one file with LLVMFuzzerTestOneInput): the check that turns a
// broken promise into a crash libFuzzer reports, and the runs that compare the JIT with the
// interpreter.
#include "interpreter/compiler/compiler.h"

#include <QString>

#include <cstddef>
#include <cstdint>
#include <memory>

namespace fuzzing {

// Inputs beyond this are cut: longer ones find nothing new and slow every execution down.
inline constexpr std::size_t kMaxInput = 64 * 1024;

[[noreturn]] void fail(const char *file, int line, const char *condition, const QString &detail);

QString text(const std::uint8_t *data, std::size_t size);

// Runs the module a few cycles with the JIT and without it (IEC_JIT=0), a small instruction budget
// each, and fails unless both give the same memory after every cycle and the same fault.
void runBothWays(const std::shared_ptr<const iec::interp::Module> &module);

} // namespace fuzzing

#define FUZZ_CHECK(condition, detail)                                                                     \
    do {                                                                                                  \
        if (!(condition))                                                                                 \
            ::fuzzing::fail(__FILE__, __LINE__, #condition, (detail));                                    \
    } while (false)
