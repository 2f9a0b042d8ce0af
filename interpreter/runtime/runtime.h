#pragma once

#include "interpreter/runtime/debugging.h"
#include "interpreter/runtime/symbols.h"
#include "interpreter/vm/bytecode.h"
#include "interpreter/vm/vm.h"

#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace iec::interp {

struct RuntimeFault {
    FaultKind kind = FaultKind::None;
    QString pou;
    int line = 0;
    int cycle = 0;
    QString message;
    QString toString() const; // "Main:12: Integer division by zero. (cycle 3)"
};

// Everything a cycle leaves behind for the next: the memory image (variables, timers, SFC steps),
// the process image, the clock and the tasks' schedule. Restoring it goes back to that scan.
struct RuntimeState {
    std::vector<std::uint8_t> memory;
    std::vector<std::uint8_t> images[3];
    std::int64_t timeNs = 0;
    int cycle = 0;
    std::vector<std::int64_t> nextDue;
    std::vector<bool> singleBefore;
};

// Runs a compiled module scan by scan on a virtual clock:
//   inputs image -> variables, tasks that are due (in priority order), variables -> outputs image.
// Cycle n runs at time (n - 1) * cycle time. A fault stops the program; the host goes on.
class Runtime
{
public:
    explicit Runtime(std::shared_ptr<const Module> module, std::int64_t cycleNs = 10'000'000);

    // Cold restart: every variable back to its initial value, the clock to zero.
    void coldRestart();
    // Warm restart: like cold, but RETAIN variables keep their values.
    void warmRestart();

    // Runs one cycle; false (and nothing happens) once a fault stopped the program, and false
    // when a breakpoint halted it mid-cycle. Called while halted, it finishes the halted cycle
    // (resume(Continue)).
    bool runCycle();
    bool runCycles(int count);

    int cycle() const { return m_cycle; }              // cycles run so far
    std::int64_t timeNs() const { return m_timeNs; }   // time of the next cycle
    std::int64_t cycleNs() const { return m_cycleNs; }
    const std::optional<RuntimeFault> &fault() const { return m_fault; }

    // Variables by name: Main.Counter, Main.Timer1.ET, Main.A[2], GlobalVar, %QX0.1.
    std::optional<VariableRef> find(const QString &name) const { return resolveSymbol(*m_module, name); }
    std::optional<QString> read(const QString &name) const; // nullopt: no such variable
    QString read(const VariableRef &ref) const;
    // Writes a literal; returns an explanation on failure.
    std::optional<QString> write(const QString &name, const QString &literal);
    // A forced variable keeps its value: written before the inputs are read and after the tasks ran.
    std::optional<QString> force(const QString &name, const QString &literal);
    void unforce(const QString &name);

    std::vector<std::uint8_t> &image(char area); // 'I', 'Q', 'M'
    const std::vector<std::uint8_t> &image(char area) const;

    // The state between two cycles, and going back to one (ScanHistory keeps them). Restoring
    // drops a halt and a fault: the program goes on from that scan. Forces stay.
    RuntimeState state() const;
    void copyStateTo(RuntimeState &into) const; // reuses `into`'s buffers (once per scan, online)
    void restore(const RuntimeState &state);

    // Messages the program logged (Beremiz LOGGER) since they were last taken.
    struct LogEntry {
        int cycle = 0;
        int level = 2; // 0 critical, 1 warning, 2 info, 3 debug
        QString text;
        QString toString() const; // "INFO: text (cycle 3)"
    };
    std::vector<LogEntry> takeLog();

    // Debugging (debugging.h). Breakpoints whose place has no code are kept but never halt.
    // Without breakpoints and steps the program runs as fast as without a debugger.
    void setBreakpoints(std::vector<Breakpoint> breakpoints);
    const std::vector<Breakpoint> &breakpoints() const { return m_breakpoints; }
    const std::optional<HaltInfo> &halt() const { return m_halt; }
    bool isHalted() const { return m_halt.has_value(); }
    // Goes on from the halt (or, when not halted, starts a cycle that halts at its first line
    // for a step); true once the cycle finished, false when it halted again or faulted.
    bool resume(ResumeKind kind);
    // Where the code of a place starts: every pc whose line-table entry names it.
    std::vector<std::uint32_t> codeAt(const CodeLocation &at) const;
    // How often each breakpoint was reached since it was set.
    const std::vector<int> &hitCounts() const { return m_hits; }

    Vm &vm() { return m_vm; }
    const Vm &vm() const { return m_vm; }
    const Module &module() const { return *m_module; }

private:
    void beginCycle();
    bool taskIsDue(size_t task);
    bool runTasksFrom(size_t first);
    bool finishTaskRun(FaultKind kind);
    void endCycle();
    FaultKind passUnwantedHalts(FaultKind kind);
    bool breakpointHolds(int index, int hits);
    void updateStops(bool stepping);
    HaltInfo describeHalt(int breakpoint) const;
    QString instanceAt(std::uint32_t offset, int pou) const;
    void copyInputs();
    void copyOutputs();
    void applyForces();

    std::shared_ptr<const Module> m_module;
    Vm m_vm;
    std::int64_t m_cycleNs;
    std::int64_t m_timeNs = 0;
    int m_cycle = 0;
    std::vector<std::int64_t> m_nextDue;
    std::vector<bool> m_singleBefore;
    std::vector<std::uint8_t> m_images[3];
    struct Force {
        QString name;
        VariableRef ref;
        QString literal;
    };
    std::vector<Force> m_forces;
    std::optional<RuntimeFault> m_fault;
    std::vector<LogEntry> m_log;

    std::vector<Breakpoint> m_breakpoints;
    std::vector<int> m_hits;                               // per breakpoint
    std::vector<std::vector<int>> m_breakpointsAtPc;       // pc -> breakpoints there (debugging only)
    std::optional<HaltInfo> m_halt;
    size_t m_haltedTask = 0;
    QString m_conditionProblem; // of the breakpoint last checked
};

} // namespace iec::interp
