// iecstudio-cli run FILE [options]: run scan cycles on the virtual clock and print the watched
// values. Options and formats: docs/cli.md.

#include "app/cli/commands.h"
#include "app/cli/diagnostics.h"
#include "app/cli/projectinput.h"
#include "app/cli/runoptions.h"
#include "app/cli/trace.h"

#include "interpreter/runtime/runtime.h"

namespace iec::cli {

namespace {

constexpr std::int64_t kDefaultCycleNs = 10'000'000;

// The shortest task interval, else 10 ms (a project without configuration has no interval).
std::int64_t defaultCycleNs(const interp::Module &module)
{
    std::int64_t shortest = 0;
    for (const interp::TaskInfo &task : module.tasks) {
        if (task.intervalNs > 0 && (shortest == 0 || task.intervalNs < shortest))
            shortest = task.intervalNs;
    }
    return shortest > 0 ? shortest : kDefaultCycleNs;
}

// Compiles FILE for running; nullptr after printing why not. --program runs one PROGRAM alone,
// so the configuration's tasks are set aside (its globals stay).
std::shared_ptr<const interp::Module> compileForRun(const RunOptions &options, Io io, int &status)
{
    interp::Diagnostics diagnostics;
    LoadedUnit loaded = loadUnit(options.file, diagnostics, io.err);
    status = loaded.status;
    if (status != ExitOk) {
        printDiagnostics(options.file, diagnostics, io.err);
        return nullptr;
    }
    interp::CompileOptions compileOptions;
    if (!options.program.isEmpty()) {
        interp::frontend::dropConfigurations(loaded.unit.unit);
        compileOptions.program = options.program;
    }
    auto module = interp::frontend::compileUnit(loaded.unit, diagnostics, compileOptions);
    printDiagnostics(options.file, diagnostics, io.err);
    if (!module)
        status = ExitFailed;
    return module;
}

// Every name of --watch and --set must exist before the first cycle runs.
bool resolveNames(
    const RunOptions &options, const interp::Runtime &runtime, std::vector<TracedVariable> &watched, Io io)
{
    QStringList unknown;
    for (const QString &name : options.watches) {
        if (const auto ref = runtime.find(name))
            watched.push_back({name, *ref});
        else
            unknown << name;
    }
    for (const ScheduledWrite &write : options.writes) {
        if (!runtime.find(write.name))
            unknown << write.name;
    }
    for (const QString &name : unknown) {
        io.err << "iecstudio-cli: " << options.file << ": there is no variable called " << name
               << " (write it as Program.Variable, Global or %QX0.1).\n";
    }
    return unknown.isEmpty();
}

bool applyWrites(const RunOptions &options, int cycle, interp::Runtime &runtime, Io io)
{
    for (const ScheduledWrite &write : options.writes) {
        if (write.cycle != cycle)
            continue;
        if (const auto problem = runtime.write(write.name, write.value)) {
            io.err << "iecstudio-cli: --set " << write.name << "=" << write.value << ": " << *problem << "\n";
            return false;
        }
    }
    return true;
}

void reportFault(const QString &file, const interp::RuntimeFault &fault, QTextStream &err)
{
    err << file << ":" << fault.pou << ":" << fault.line << ": runtime error in cycle " << fault.cycle << ": "
        << fault.message << "\n";
}

// What the program logged (Beremiz LOGGER): "FILE: INFO: text (cycle 3)" on stderr.
void reportLog(const QString &file, interp::Runtime &runtime, QTextStream &err)
{
    for (const interp::Runtime::LogEntry &entry : runtime.takeLog())
        err << file << ": " << entry.toString() << "\n";
}

// Runs the cycles; the exit status.
int runCycles(const RunOptions &options, interp::Runtime &runtime, Trace *trace, Io io)
{
    if (trace)
        trace->begin(runtime);
    for (int cycle = 1; cycle <= options.cycles; ++cycle) {
        if (!applyWrites(options, cycle, runtime, io))
            return ExitUsage;
        const bool ran = runtime.runCycle();
        reportLog(options.file, runtime, io.err);
        if (!ran) {
            reportFault(options.file, *runtime.fault(), io.err);
            return ExitFailed;
        }
        if (trace)
            trace->sample(cycle, runtime);
    }
    return ExitOk;
}

} // namespace

int runRun(const QStringList &arguments, Io io)
{
    QString error;
    const std::optional<RunOptions> options = parseRunOptions(arguments, error);
    if (!options) {
        io.err << "iecstudio-cli: " << error << "\nUsage: iecstudio-cli run FILE [--program P] [--cycles N] "
               << "[--cycle-time 10ms] [--set NAME=VALUE[@CYCLE]]... [--watch NAME]... [--trace OUT.csv|OUT.vcd]\n";
        return ExitUsage;
    }
    int status = ExitOk;
    const auto module = compileForRun(*options, io, status);
    if (!module)
        return status;
    interp::Runtime runtime(module, options->cycleNs.value_or(defaultCycleNs(*module)));
    std::vector<TracedVariable> watched;
    if (!resolveNames(*options, runtime, watched, io))
        return ExitUsage;
    std::unique_ptr<Trace> trace;
    if (!options->trace.isEmpty()) {
        OpenedTrace opened = openTrace(options->trace, watched);
        if (!opened.trace) {
            io.err << "iecstudio-cli: " << opened.error << "\n";
            return opened.fileError ? ExitIoError : ExitUsage;
        }
        trace = std::move(opened.trace);
    }
    status = runCycles(*options, runtime, trace.get(), io);
    // The values are printed even after a fault: they show the state the program stopped in.
    for (const TracedVariable &variable : watched)
        io.out << variable.name << " = " << runtime.read(variable.ref) << "\n";
    if (trace && !trace->finish(error)) {
        io.err << "iecstudio-cli: " << error << "\n";
        return status == ExitOk ? ExitIoError : status;
    }
    return status;
}

} // namespace iec::cli
