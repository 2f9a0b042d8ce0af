// bench_ld: an LD program of 2,500 rungs with 4 contacts each (10,000 contacts), lowered by
// interpreter/graphical and run by the VM, against the same logic in plain C++ in this binary:
//   rung k:  --+--[ A_k ]--[/B_k ]--+--( O_k )
//              +--[ C_k ]--[ O_k-1 ]-+
// Prints the time to lower and compile, ns per scan for both, and their ratio. Build it Release.
#include "interpreter/compiler/compiler.h"
#include "interpreter/frontend/iecreader.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"

#include "model/element.h"

#include "benchutil.h"

#include <cstdint>
#include <limits>
#include <cstdio>
#include <vector>

using namespace iec;
using namespace iec::interp;
using namespace iec::bench;

namespace {

constexpr int kRungs = 2500;
volatile std::int64_t g_sink = 0;

model::ConnectionPointIn wire(std::initializer_list<quint64> sources)
{
    model::ConnectionPointIn point;
    for (const quint64 id : sources) {
        model::Connection connection;
        connection.refLocalId = id;
        point.connections.push_back(connection);
    }
    return point;
}

model::Element contact(quint64 id, const QString &variable, model::ConnectionPointIn in, double x, double y, bool negated)
{
    model::Contact c;
    c.localId = id;
    c.position = {x, y};
    c.variable = variable;
    c.negated = negated;
    c.connectionPointIn = std::move(in);
    c.connectionPointOut.emplace();
    return c;
}

// The ladder: one left rail; rung k at y = 60 k, its elements numbered from 10 k + 10.
model::Body ladder()
{
    model::Body body = model::Body::withLanguage(model::BodyLanguage::LD);
    std::vector<model::Element> &elements = *body.elements();
    model::LeftPowerRail rail;
    rail.localId = 1;
    rail.connectionPointOuts.emplace_back();
    elements.emplace_back(rail);
    for (int k = 0; k < kRungs; ++k) {
        const quint64 base = 10 * quint64(k) + 10;
        const double y = 60.0 * k;
        elements.push_back(contact(base, QStringLiteral("A%1").arg(k), wire({1}), 100, y, false));
        elements.push_back(contact(base + 1, QStringLiteral("B%1").arg(k), wire({base}), 200, y, true));
        elements.push_back(contact(base + 2, QStringLiteral("C%1").arg(k), wire({1}), 100, y + 30, false));
        const QString previous = k == 0 ? QStringLiteral("TRUE") : QStringLiteral("O%1").arg(k - 1);
        elements.push_back(contact(base + 3, previous, wire({base + 2}), 200, y + 30, false));
        model::Coil coil;
        coil.localId = base + 4;
        coil.position = {400, y};
        coil.variable = QStringLiteral("O%1").arg(k);
        coil.connectionPointIn = wire({base + 1, base + 3});
        coil.connectionPointOut.emplace();
        elements.emplace_back(coil);
    }
    return body;
}

} // namespace

int main()
{
    const QString declarations = QStringLiteral("PROGRAM Main\nVAR\n") + rungDeclarations(kRungs) + QStringLiteral("END_VAR\n");
    auto read = frontend::readIecText(QString(declarations + QStringLiteral("END_PROGRAM\n")), QStringLiteral("bench"));
    read.project.types.pous.front().bodies = {ladder()};

    Diagnostics diagnostics;
    const auto start = Clock::now();
    const frontend::ProjectUnit unit = frontend::buildUnit(read.project, diagnostics);
    const auto lowered = Clock::now();
    const auto module = frontend::compileUnit(unit, diagnostics);
    const double lowerMs = std::chrono::duration<double, std::milli>(lowered - start).count();
    const double compileMs = msSince(lowered);
    printDiagnostics(diagnostics);
    if (!module)
        return 1;
    Runtime runtime(module);
    const double vm = nsPerScan(2000, [&] { runtime.runCycle(); });

    // With the debugger armed: a breakpoint on the last rung that never halts (on its
    // 2,147,483,647th hit), so every scan runs the debugger's code (op::Break at each rung, no JIT).
    Runtime debugged(module);
    Breakpoint never;
    const qint64 last = 10 * qint64(kRungs - 1) + 10;
    never.at = {QStringLiteral("Main"), 0, last + 4, {last, last + 1, last + 2, last + 3, last + 4}};
    never.hitRule = HitRule::Equal;
    never.hitTarget = std::numeric_limits<int>::max();
    debugged.setBreakpoints({never});
    const double armed = nsPerScan(2000, [&] { debugged.runCycle(); });
    const bool armedHits = debugged.hitCounts().front() > 0;

    CppRungs rungs(kRungs);
    const double cpp = nsPerScan(2000, [&] {
        rungs.scan();
        g_sink = g_sink + rungs.output(kRungs - 1);
    });
    // The same rungs written in ST, to tell the lowering's cost from the VM's.
    const QString text = declarations + rungStatements(kRungs) + QStringLiteral("END_PROGRAM\n");
    Diagnostics stDiagnostics;
    const auto stModule = compileText(text, stDiagnostics);
    double st = 0;
    if (stModule) {
        Runtime stRuntime(stModule);
        st = nsPerScan(2000, [&] { stRuntime.runCycle(); });
    }

    int differences = 0;
    for (int k = 0; k < kRungs; ++k) {
        const QString expected = rungs.output(k) ? QStringLiteral("TRUE") : QStringLiteral("FALSE");
        differences += runtime.read(QStringLiteral("Main.O%1").arg(k)) != expected;
    }
    std::printf("LD, %d rungs, %d contacts: declarations parsed and body lowered in %.0f ms, compiled in %.0f ms, "
                "%zu instructions\n",
        kRungs, 4 * kRungs, lowerMs, compileMs, module->code.size());
    std::printf("VM %9.0f ns/scan   C++ -O2 %9.0f ns/scan   ratio %5.2fx   %s\n", vm, cpp, vm / cpp,
        differences == 0 ? "same results" : "RESULTS DIFFER");
    std::printf("the same rungs in ST: VM %9.0f ns/scan, %zu instructions\n", st, stModule ? stModule->code.size() : 0);
    std::printf("with a breakpoint that never halts: %9.0f ns/scan (%.2fx; the breakpoint was %s)\n", armed, armed / vm,
        armedHits ? "reached every scan" : "NEVER REACHED");
    return differences == 0 ? 0 : 1;
}
