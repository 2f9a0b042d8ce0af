// bench_history: what going back in time and the trace recorder cost per scan (issue 19). For
// the examples, the 2,500 boolean rungs of bench_vm and a program with a 200 KB array of which a
// few elements change each scan, it prints: ns per scan without them, with the scan history
// (ScanHistory::record of every scan), and with a trace of five variables as well; the bytes the
// history takes per scan after 1,000 scans; and the longest time to bring back a scan
// (stateAt, up to 63 change lists after a full copy). Build it Release.
#include "interpreter/compiler/compiler.h"
#include "interpreter/frontend/projectsource.h"
#include "interpreter/runtime/runtime.h"
#include "interpreter/runtime/scanhistory.h"
#include "interpreter/runtime/tracerecorder.h"
#include "model/plcopen/reader.h"

#include "benchutil.h"

#include <cstdio>
#include <memory>

using namespace iec;
using namespace iec::interp;
using namespace iec::bench;

namespace {

struct Program {
    QString name;
    std::shared_ptr<const Module> module;
    QStringList traced; // five variables, or fewer when the program has fewer
};

Program example(const QString &file, const QStringList &traced)
{
    const model::plcopen::ReadResult read
        = model::plcopen::readProjectFile(QStringLiteral(IEC_SOURCE_DIR "/resources/examples/") + file);
    Diagnostics diagnostics;
    auto module = frontend::compileProject(read.project, diagnostics);
    printDiagnostics(diagnostics);
    return {file, module, traced};
}

Program text(const QString &name, const QString &source, const QStringList &traced)
{
    Diagnostics diagnostics;
    auto module = compileText(source, diagnostics);
    printDiagnostics(diagnostics);
    return {name, module, traced};
}

void measure(const Program &program)
{
    if (!program.module) {
        std::printf("%-22s did not compile\n", qPrintable(program.name));
        return;
    }
    constexpr int kScans = 1000;
    Runtime plain(program.module);
    const double plainNs = nsPerScan(kScans, [&] { plain.runCycle(); });

    Runtime withHistory(program.module);
    ScanHistory history;
    RuntimeState scratch; // as the IDE's runtime worker does it
    const double historyNs = nsPerScan(kScans, [&] {
        withHistory.runCycle();
        withHistory.copyStateTo(scratch);
        history.record(scratch);
    });

    Runtime withTrace(program.module);
    ScanHistory traceHistory;
    TraceRecorder recorder;
    TraceSettings settings;
    settings.variables = program.traced;
    recorder.configure(settings, withTrace);
    const double traceNs = nsPerScan(kScans, [&] {
        withTrace.runCycle();
        withTrace.copyStateTo(scratch);
        traceHistory.record(scratch);
        recorder.sample(withTrace);
    });

    // A fresh history of exactly 1,000 scans for the memory figure and the way back.
    Runtime fresh(program.module);
    ScanHistory kept;
    for (int i = 0; i < kScans; ++i) {
        fresh.runCycle();
        kept.record(fresh.state());
    }
    double worstBackUs = 0;
    for (int cycle = kept.firstCycle(); cycle <= kept.lastCycle(); cycle += 7) {
        const auto start = Clock::now();
        const auto state = kept.stateAt(cycle);
        worstBackUs = std::max(worstBackUs, msSince(start) * 1000);
        if (!state)
            std::printf("  scan %d missing!\n", cycle);
    }
    std::printf("%-22s %8zu B  %10.0f %10.0f %10.0f  %9.0f B %9.1f us\n", qPrintable(program.name),
                fresh.vm().memory().size(), plainNs, historyNs, traceNs, double(kept.bytesUsed()) / kScans,
                worstBackUs);
}

} // namespace

int main()
{
    std::printf("%-22s %10s  %10s %10s %10s  %11s %12s\n", "program", "memory", "ns/scan", "+history",
                "+trace(5)", "history/scan", "worst back");
    measure(example(QStringLiteral("first_steps.xml"), {}));
    measure(example(QStringLiteral("mixing_tank.xml"),
                    {QStringLiteral("Tank.Y1"), QStringLiteral("Tank.Y2"), QStringLiteral("Tank.M"),
                     QStringLiteral("Tank.Y3"), QStringLiteral("Tank.Mixing.T")}));
    measure(example(QStringLiteral("star_delta.xml"), {}));
    measure(text(QStringLiteral("2,500 rungs (ST)"),
                 QStringLiteral("PROGRAM Main\nVAR\n") + rungDeclarations(2500) + QStringLiteral("END_VAR\n")
                     + rungStatements(2500) + QStringLiteral("END_PROGRAM\n"),
                 {QStringLiteral("Main.O0"), QStringLiteral("Main.O1"), QStringLiteral("Main.O2"),
                  QStringLiteral("Main.O3"), QStringLiteral("Main.O2499")}));
    measure(text(QStringLiteral("200 KB array"),
                 QStringLiteral("PROGRAM Main\nVAR a : ARRAY[0..99999] OF INT; n : DINT; i : DINT; END_VAR\n"
                                "n := n + 1;\nFOR i := 0 TO 9 DO a[(n * 37 + i * 1009) MOD 100000] := DINT_TO_INT(n); END_FOR;\n"
                                "END_PROGRAM\n"),
                 {QStringLiteral("Main.n"), QStringLiteral("Main.a[0]"), QStringLiteral("Main.a[37]"),
                  QStringLiteral("Main.i"), QStringLiteral("Main.a[99999]")}));
    return 0;
}
