// bench_vm: three programs run by the VM and the same algorithms in plain C++ in this binary.
//   (1) an ST numeric kernel over arrays (sieve of Eratosthenes up to 20,000),
//   (2) 1,000 TON instances,
//   (3) 10,000 boolean rung-like assignments.
// Prints ns per scan for both and their ratio. Build it Release (-DIEC_BUILD_TESTS=OFF).
// IEC_JIT=0 measures the interpreter alone.
#include "interpreter/compiler/compiler.h"
#include "interpreter/runtime/runtime.h"
#include "interpreter/runtime/valueformat.h"
#include "interpreter/vm/disassembler.h"
#include "interpreter/vm/jit.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstring>
#include <cstdint>
#include <functional>
#include <vector>

using namespace iec::interp;
using Clock = std::chrono::steady_clock;

namespace {

// Keeps the optimiser from dropping results of the C++ versions.
volatile std::int64_t g_sink = 0;

// CPU time of this thread: the machine is shared, and wall time would count the time the
// scheduler gave to other processes (on a loaded machine that hit the slower VM rounds more).
double threadNs()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e9 + double(t.tv_nsec);
}

// The best of 20 short rounds: what one scan costs when nothing else disturbs it.
double nsPerScan(int scans, const std::function<void()> &scan)
{
    for (int i = 0; i < scans / 10 + 1; ++i) // warm up caches and branch predictors
        scan();
    const int perRound = std::max(1, scans / 10);
    double best = 1e300;
    for (int round = 0; round < 20; ++round) {
        const double start = threadNs();
        for (int i = 0; i < perRound; ++i)
            scan();
        best = std::min(best, (threadNs() - start) / perRound);
    }
    return best;
}

double g_lastCompileMs = 0;

std::shared_ptr<const Module> build(const QString &source)
{
    Diagnostics diagnostics;
    const auto start = Clock::now();
    auto module = compileText(source, diagnostics);
    g_lastCompileMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    for (const Diagnostic &d : diagnostics.all())
        std::fprintf(stderr, "%s\n", qPrintable(d.toString()));
    // IEC_BENCH_DISASM=1 prints the code of the smaller programs, to see what the compiler emits.
    if (module && qEnvironmentVariableIsSet("IEC_BENCH_DISASM") && module->code.size() < 1000)
        std::fprintf(stderr, "%s\n", qPrintable(disassemble(*module)));
    return module;
}

void report(const char *name, double vm, double cpp, double target, std::size_t instructions)
{
    std::printf("%-34s VM %9.0f ns/scan   C++ -O2 %9.0f ns/scan   ratio %5.2fx (target %.1fx)   %zu instructions, compiled in %.0f ms, JIT %s\n",
                name, vm, cpp, vm / cpp, target, instructions, g_lastCompileMs, jitEnabled() ? "on" : "off (IEC_JIT=0)");
}

// ---- (1) sieve ----------------------------------------------------------------------------
constexpr int kSieve = 20000;

__attribute__((noinline)) std::int32_t sieveCpp(std::vector<std::uint8_t> &flags)
{
    for (int i = 2; i <= kSieve; ++i)
        flags[size_t(i)] = 1;
    std::int32_t count = 0;
    for (int i = 2; i <= kSieve; ++i) {
        if (flags[size_t(i)]) {
            ++count;
            for (std::int32_t j = i * i; j <= kSieve; j += i)
                flags[size_t(j)] = 0;
        }
    }
    return count;
}

void benchSieve()
{
    const QString source = QStringLiteral(
        "PROGRAM Main\nVAR flags : ARRAY[0..20000] OF BOOL; i : DINT; j : DINT; count : DINT; END_VAR\n"
        "FOR i := 2 TO 20000 DO flags[i] := TRUE; END_FOR;\n"
        "count := 0;\n"
        "FOR i := 2 TO 20000 DO\n"
        "  IF flags[i] THEN\n"
        "    count := count + 1;\n"
        "    j := i * i;\n"
        "    WHILE j <= 20000 DO flags[j] := FALSE; j := j + i; END_WHILE;\n"
        "  END_IF;\n"
        "END_FOR;\nEND_PROGRAM\n");
    const auto module = build(source);
    Runtime runtime(module);
    const double vm = nsPerScan(200, [&] { runtime.runCycle(); });
    std::vector<std::uint8_t> flags(kSieve + 1);
    const double cpp = nsPerScan(200, [&] { g_sink = g_sink + sieveCpp(flags); });
    if (runtime.read(QStringLiteral("Main.count")) != QStringLiteral("2262"))
        std::printf("sieve: wrong result %s\n", qPrintable(runtime.read(QStringLiteral("Main.count")).value_or(QStringLiteral("?"))));
    report("(1) ST sieve over ARRAY[0..20000]", vm, cpp, 3.0, module->code.size());
}

// ---- (1b) matrix product -------------------------------------------------------------------
constexpr int kMatrix = 24;

__attribute__((noinline)) float matrixCpp(const float *a, const float *b, float *c)
{
    for (int i = 0; i < kMatrix; ++i) {
        for (int j = 0; j < kMatrix; ++j) {
            float sum = 0.0f;
            for (int k = 0; k < kMatrix; ++k)
                sum += a[i * kMatrix + k] * b[k * kMatrix + j];
            c[i * kMatrix + j] = sum;
        }
    }
    return c[kMatrix * kMatrix - 1];
}

void benchMatrix()
{
    const QString source = QStringLiteral(
        "PROGRAM Main\nVAR a : ARRAY[0..575] OF REAL; b : ARRAY[0..575] OF REAL; c : ARRAY[0..575] OF REAL;\n"
        "i : DINT; j : DINT; k : DINT; sum : REAL; init : BOOL; END_VAR\n"
        "IF NOT init THEN FOR i := 0 TO 575 DO a[i] := DINT_TO_REAL(i MOD 7) * 0.5; b[i] := DINT_TO_REAL(i MOD 5) - 1.0; END_FOR; init := TRUE; END_IF;\n"
        "FOR i := 0 TO 23 DO\n"
        "  FOR j := 0 TO 23 DO\n"
        "    sum := 0.0;\n"
        "    FOR k := 0 TO 23 DO sum := sum + a[i * 24 + k] * b[k * 24 + j]; END_FOR;\n"
        "    c[i * 24 + j] := sum;\n"
        "  END_FOR;\n"
        "END_FOR;\nEND_PROGRAM\n");
    const auto module = build(source);
    Runtime runtime(module);
    const double vm = nsPerScan(500, [&] { runtime.runCycle(); });
    std::vector<float> a(kMatrix * kMatrix), b(kMatrix * kMatrix), c(kMatrix * kMatrix);
    for (int i = 0; i < kMatrix * kMatrix; ++i) {
        a[size_t(i)] = float(i % 7) * 0.5f;
        b[size_t(i)] = float(i % 5) - 1.0f;
    }
    const double cpp = nsPerScan(500, [&] { g_sink = g_sink + std::int64_t(matrixCpp(a.data(), b.data(), c.data())); });
    if (runtime.read(QStringLiteral("Main.c[575]")) != formatReal(c[575]))
        std::printf("matrix: results differ: %s %s\n", qPrintable(runtime.read(QStringLiteral("Main.c[575]")).value_or(QString())), qPrintable(formatReal(c[575])));
    report("(1b) ST REAL matrix product 24x24", vm, cpp, 3.0, module->code.size());
}

// ---- (2) 1,000 TON -------------------------------------------------------------------------
constexpr int kTimers = 1000;

struct Ton {
    bool in = false, q = false, running = false;
    std::int64_t pt = 0, et = 0, start = 0;
};

// The same logic as the library's TON.
__attribute__((noinline)) void ton(Ton &t, bool in, std::int64_t pt, std::int64_t now)
{
    t.in = in;
    t.pt = pt;
    if (t.in) {
        if (!t.running) {
            t.running = true;
            t.start = now;
        }
        if (!t.q) {
            t.et = now - t.start;
            if (t.et >= t.pt) {
                t.et = t.pt;
                t.q = true;
            }
        }
    } else {
        t.running = false;
        t.q = false;
        t.et = 0;
    }
}

void benchTimers()
{
    QString declarations, body;
    for (int k = 0; k < kTimers; ++k) {
        declarations += QStringLiteral("T%1 : TON; Q%1 : BOOL;\n").arg(k);
        body += QStringLiteral("T%1(IN := run, PT := T#%2ms);\nQ%1 := T%1.Q;\n").arg(k).arg((k % 10 + 1) * 10);
    }
    const QString source = QStringLiteral("PROGRAM Main\nVAR n : DINT; run : BOOL;\n") + declarations
        + QStringLiteral("END_VAR\nn := n + 1;\nrun := n MOD 16 <> 0;\n") + body + QStringLiteral("END_PROGRAM\n");
    const auto module = build(source);
    Runtime runtime(module);
    const double vm = nsPerScan(2000, [&] { runtime.runCycle(); });

    std::vector<Ton> timers(kTimers);
    std::vector<std::uint8_t> q(kTimers);
    std::int32_t n = 0;
    std::int64_t now = 0;
    const double cpp = nsPerScan(2000, [&] {
        ++n;
        const bool run = n % 16 != 0;
        for (int k = 0; k < kTimers; ++k) {
            ton(timers[size_t(k)], run, std::int64_t(k % 10 + 1) * 10'000'000, now);
            q[size_t(k)] = timers[size_t(k)].q;
        }
        now += 10'000'000;
        g_sink = g_sink + q[size_t(n % kTimers)];
    });
    report("(2) 1,000 TON instances", vm, cpp, 1.5, module->code.size());
}

// ---- (3) 10,000 rungs ----------------------------------------------------------------------
constexpr int kRungs = 10000;

__attribute__((noinline)) void rungsCpp(const std::uint8_t *a, const std::uint8_t *b, const std::uint8_t *c, std::uint8_t *o)
{
    o[0] = (a[0] & !b[0]) | c[0];
    for (int k = 1; k < kRungs; ++k)
        o[k] = (a[k] & !b[k]) | (c[k] & o[k - 1]);
}

void benchRungs()
{
    QString declarations, body;
    for (int k = 0; k < kRungs; ++k) {
        declarations += QStringLiteral("A%1 : BOOL := %2; B%1 : BOOL := %3; C%1 : BOOL := %4; O%1 : BOOL;\n")
                            .arg(k)
                            .arg(k % 3 == 0 ? QStringLiteral("TRUE") : QStringLiteral("FALSE"))
                            .arg(k % 5 == 0 ? QStringLiteral("TRUE") : QStringLiteral("FALSE"))
                            .arg(k % 2 == 0 ? QStringLiteral("TRUE") : QStringLiteral("FALSE"));
        body += k == 0 ? QStringLiteral("O0 := (A0 AND NOT B0) OR C0;\n")
                       : QStringLiteral("O%1 := (A%1 AND NOT B%1) OR (C%1 AND O%2);\n").arg(k).arg(k - 1);
    }
    const auto module = build(QStringLiteral("PROGRAM Main\nVAR\n") + declarations + QStringLiteral("END_VAR\n") + body + QStringLiteral("END_PROGRAM\n"));
    Runtime runtime(module);
    const double vm = nsPerScan(2000, [&] { runtime.runCycle(); });
    std::vector<std::uint8_t> a(kRungs), b(kRungs), c(kRungs), o(kRungs);
    for (int k = 0; k < kRungs; ++k) {
        a[size_t(k)] = k % 3 == 0;
        b[size_t(k)] = k % 5 == 0;
        c[size_t(k)] = k % 2 == 0;
    }
    const double cpp = nsPerScan(2000, [&] {
        rungsCpp(a.data(), b.data(), c.data(), o.data());
        g_sink = g_sink + o[kRungs - 1];
    });
    if (runtime.read(QStringLiteral("Main.O9999")) != (o[kRungs - 1] ? QStringLiteral("TRUE") : QStringLiteral("FALSE")))
        std::printf("rungs: results differ\n");
    report("(3) 10,000 boolean rungs", vm, cpp, 1.5, module->code.size());
}

} // namespace

// bench_vm [sieve|matrix|timers|rungs]...: all four without arguments.
int main(int argc, char **argv)
{
    const std::pair<const char *, void (*)()> benches[] = {
        {"sieve", benchSieve}, {"matrix", benchMatrix}, {"timers", benchTimers}, {"rungs", benchRungs}};
    for (const auto &[name, run] : benches) {
        bool wanted = argc == 1;
        for (int i = 1; i < argc; ++i)
            wanted |= std::strcmp(argv[i], name) == 0;
        if (wanted)
            run();
    }
    return 0;
}
