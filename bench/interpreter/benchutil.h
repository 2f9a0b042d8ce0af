#pragma once

// What the interpreter benches share: the timing loop, the diagnostics printout and the boolean
// rungs that bench_ld (as LD) and bench_vm (as ST) run against plain C++.
#include "interpreter/compiler/diagnostics.h"

#include <QString>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <vector>

namespace iec::bench {

using Clock = std::chrono::steady_clock;

inline double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The best of 5 rounds of `scans` calls of `scan`, after a warm-up of a tenth of them.
inline double nsPerScan(int scans, const std::function<void()> &scan)
{
    for (int i = 0; i < scans / 10 + 1; ++i)
        scan();
    double best = 1e300;
    for (int round = 0; round < 5; ++round) {
        const auto start = Clock::now();
        for (int i = 0; i < scans; ++i)
            scan();
        best = std::min(best, std::chrono::duration<double, std::nano>(Clock::now() - start).count() / scans);
    }
    return best;
}

inline void printDiagnostics(const interp::Diagnostics &diagnostics)
{
    for (const interp::Diagnostic &d : diagnostics.all())
        std::fprintf(stderr, "%s\n", qPrintable(d.toString()));
}

// Rung k: O_k := (A_k AND NOT B_k) OR (C_k AND O_k-1) (rung 0 without O_-1), with
// A_k = k mod 3 = 0, B_k = k mod 5 = 0, C_k = k mod 2 = 0.
inline QString rungDeclarations(int rungs)
{
    const auto flag = [](bool value) { return value ? QStringLiteral("TRUE") : QStringLiteral("FALSE"); };
    QString text;
    for (int k = 0; k < rungs; ++k) {
        text += QStringLiteral("A%1 : BOOL := %2; B%1 : BOOL := %3; C%1 : BOOL := %4; O%1 : BOOL;\n")
                    .arg(k)
                    .arg(flag(k % 3 == 0), flag(k % 5 == 0), flag(k % 2 == 0));
    }
    return text;
}

inline QString rungStatements(int rungs)
{
    QString text;
    for (int k = 0; k < rungs; ++k) {
        text += k == 0 ? QStringLiteral("O0 := (A0 AND NOT B0) OR C0;\n")
                       : QStringLiteral("O%1 := (A%1 AND NOT B%1) OR (C%1 AND O%2);\n").arg(k).arg(k - 1);
    }
    return text;
}

// The same rungs in plain C++, the baseline.
class CppRungs
{
public:
    explicit CppRungs(int rungs)
        : m_a(std::size_t(rungs)), m_b(std::size_t(rungs)), m_c(std::size_t(rungs)), m_o(std::size_t(rungs))
    {
        for (int k = 0; k < rungs; ++k) {
            m_a[std::size_t(k)] = k % 3 == 0;
            m_b[std::size_t(k)] = k % 5 == 0;
            m_c[std::size_t(k)] = k % 2 == 0;
        }
    }

    __attribute__((noinline)) void scan()
    {
        const std::uint8_t *a = m_a.data(), *b = m_b.data(), *c = m_c.data();
        std::uint8_t *o = m_o.data();
        const int rungs = int(m_o.size());
        o[0] = (a[0] & !b[0]) | c[0];
        for (int k = 1; k < rungs; ++k)
            o[k] = (a[k] & !b[k]) | (c[k] & o[k - 1]);
    }

    bool output(int k) const { return m_o[std::size_t(k)] != 0; }

private:
    std::vector<std::uint8_t> m_a, m_b, m_c, m_o;
};

} // namespace iec::bench
