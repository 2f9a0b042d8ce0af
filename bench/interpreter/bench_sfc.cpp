// bench_sfc: a chart of 1,000 steps in 10 parallel branches of 100 steps (plus Init), every
// transition TRUE so the tokens move every scan, each branch driving a Boolean action with N
// from all its steps. The chart is written in textual SFC, read into the model and lowered
// (interpreter/sfc) like a project would be; the same semantics hand-written in C++ give the
// baseline. Prints ns per scan and the ratio. Build it Release (-DIEC_BUILD_TESTS=OFF).
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"

#include "benchutil.h"

#include <array>
#include <cstdio>
#include <cstdint>
#include <vector>

using namespace iec::interp;
using namespace iec::bench;

namespace {

constexpr int kBranches = 10;
constexpr int kLength = 100;

volatile std::int64_t g_sink = 0;

QString chartSource()
{
    QString text = QStringLiteral("PROGRAM Main\nVAR\n");
    for (int b = 0; b < kBranches; ++b)
        text += QStringLiteral("Out%1 : BOOL;\n").arg(b);
    text += QStringLiteral("END_VAR\nINITIAL_STEP Init: END_STEP\n");
    QStringList firsts, lasts;
    for (int b = 0; b < kBranches; ++b) {
        firsts << QStringLiteral("B%1_0").arg(b);
        lasts << QStringLiteral("B%1_%2").arg(b).arg(kLength - 1);
    }
    text += QStringLiteral("TRANSITION FROM Init TO (%1) := TRUE; END_TRANSITION\n").arg(firsts.join(QStringLiteral(", ")));
    for (int b = 0; b < kBranches; ++b) {
        for (int s = 0; s < kLength; ++s) {
            text += QStringLiteral("STEP B%1_%2: Out%1(N); END_STEP\n").arg(b).arg(s);
            if (s + 1 < kLength)
                text += QStringLiteral("TRANSITION FROM B%1_%2 TO B%1_%3 := TRUE; END_TRANSITION\n").arg(b).arg(s).arg(s + 1);
        }
    }
    text += QStringLiteral("TRANSITION FROM (%1) TO Init := TRUE; END_TRANSITION\nEND_PROGRAM\n").arg(lasts.join(QStringLiteral(", ")));
    return text;
}

// The same chart by hand: x/_x per step, start times, Q and last Q per action, transitions.
struct CppChart {
    static constexpr int kSteps = 1 + kBranches * kLength;
    std::array<bool, kSteps> x {}, next {}, entered {};
    std::array<std::int64_t, kSteps> start {}, t {};
    std::array<bool, kBranches> q {}, qm {}, out {};
    std::int64_t now = 0;

    CppChart() { next[0] = true; }
    static int step(int b, int s) { return 1 + b * kLength + s; }

    void scan()
    {
        for (int i = 0; i < kSteps; ++i) {
            entered[i] = next[i] && !x[i];
            x[i] = next[i];
        }
        for (int i = 0; i < kSteps; ++i) {
            if (entered[i])
                start[i] = now;
            if (x[i])
                t[i] = now - start[i];
        }
        for (int b = 0; b < kBranches; ++b) {
            bool any = false;
            for (int s = 0; s < kLength; ++s)
                any = any || x[size_t(step(b, s))];
            q[size_t(b)] = any;
            out[size_t(b)] = any;
            qm[size_t(b)] = any;
        }
        if (x[0] && next[0]) {
            next[0] = false;
            for (int b = 0; b < kBranches; ++b)
                next[size_t(step(b, 0))] = true;
        }
        for (int b = 0; b < kBranches; ++b) {
            for (int s = 0; s + 1 < kLength; ++s) {
                const int i = step(b, s);
                if (x[size_t(i)] && next[size_t(i)]) {
                    next[size_t(i)] = false;
                    next[size_t(i + 1)] = true;
                }
            }
        }
        bool all = true;
        for (int b = 0; b < kBranches; ++b)
            all = all && x[size_t(step(b, kLength - 1))] && next[size_t(step(b, kLength - 1))];
        if (all) {
            for (int b = 0; b < kBranches; ++b)
                next[size_t(step(b, kLength - 1))] = false;
            next[0] = true;
        }
        now += 10'000'000;
        g_sink = g_sink + out[0];
    }
};

} // namespace

int main()
{
    const auto start = Clock::now();
    const auto read = frontend::readIecText(chartSource(), QStringLiteral("bench"));
    Diagnostics diagnostics;
    const auto module = frontend::compileProject(read.project, diagnostics);
    const double compileMs = msSince(start);
    printDiagnostics(diagnostics);
    if (!module)
        return 1;
    Runtime runtime(module);
    const int scans = 2000;
    const double vm = nsPerScan(scans, [&] { runtime.runCycle(); });
    CppChart chart;
    const double cpp = nsPerScan(scans, [&] { chart.scan(); });
    std::printf("SFC 1,000 steps, 10 parallel branches   VM %9.0f ns/scan   C++ %9.0f ns/scan   ratio %5.1fx   "
                "read+lowered+compiled in %.0f ms\n",
        vm, cpp, vm / cpp, compileMs);
    return runtime.fault() ? 1 : 0;
}
