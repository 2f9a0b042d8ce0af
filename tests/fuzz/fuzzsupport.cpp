#include "fuzzsupport.h"

#include "interpreter/runtime/runtime.h"

#include <cstdio>
#include <cstdlib>

namespace fuzzing {

void fail(const char *file, int line, const char *condition, const QString &detail)
{
    std::fprintf(stderr, "%s:%d: FUZZ_CHECK(%s) failed\n%s\n", file, line, condition, qPrintable(detail.left(4000)));
    std::abort();
}

QString text(const std::uint8_t *data, std::size_t size)
{
    return QString::fromUtf8(reinterpret_cast<const char *>(data), qsizetype(std::min(size, kMaxInput)));
}

void runBothWays(const std::shared_ptr<const iec::interp::Module> &module)
{
    using iec::interp::Runtime;
    constexpr int kCycles = 3;
    constexpr std::uint64_t kBudget = 20'000;
    Runtime jit(module);
    qputenv("IEC_JIT", "0");
    Runtime interpreted(module);
    qunsetenv("IEC_JIT");
    jit.vm().budgetPerRun = interpreted.vm().budgetPerRun = kBudget;
    for (int cycle = 1; cycle <= kCycles; ++cycle) {
        const bool a = jit.runCycle();
        const bool b = interpreted.runCycle();
        FUZZ_CHECK(a == b, QStringLiteral("cycle %1: the JIT %2, the interpreter %3").arg(cycle).arg(a).arg(b));
        FUZZ_CHECK(jit.vm().memory() == interpreted.vm().memory(), QStringLiteral("memory differs after cycle %1").arg(cycle));
        FUZZ_CHECK(jit.fault().has_value() == interpreted.fault().has_value(), QStringLiteral("fault in cycle %1").arg(cycle));
        if (jit.fault()) {
            FUZZ_CHECK(jit.fault()->toString() == interpreted.fault()->toString(),
                jit.fault()->toString() + QStringLiteral(" vs ") + interpreted.fault()->toString());
            return;
        }
    }
}

} // namespace fuzzing
