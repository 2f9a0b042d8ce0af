#pragma once

#include "interpreter/runtime/runtime.h"
#include "interpreter/runtime/scanhistory.h"
#include "interpreter/runtime/snapshot.h"
#include "interpreter/runtime/tracerecorder.h"
#include "model/pou.h"

#include <QElapsedTimer>
#include <QObject>
#include <QStringList>

#include <memory>
#include <optional>
#include <vector>

class QTimer;

namespace iec::app {

// How fast Run goes: cycles paced to the wall clock, ten times faster, or back to back.
enum class RunSpeed { RealTime, Times10, AsFastAsPossible };

// A chart an open SFC editor shows: the POU (as it was at login; online mode never changes the
// model), the instance whose state it wants, and the action when the chart is an action's body.
struct ChartRequest {
    QString instance;
    model::Pou pou;
    QString action;
};

// What the open views want in each snapshot.
struct WatchRequest {
    QStringList names;
    std::vector<ChartRequest> charts;
};

// Owns the Runtime of an online session and runs it (DESIGN.md). In the IDE it lives on its
// own QThread and every call reaches it as a queued call, so the thread's event queue is the
// command queue: Run executes cycles in slices of a few milliseconds and goes back to the event
// loop between slices, so a Stop or a write is taken within one slice even at full speed.
// Tests call the methods directly on one thread; single cycles are deterministic.
//
// Snapshots are published at most every kPublishIntervalMs while running, and after every
// command that changes what is shown (a single cycle, stop, reset, force).
class RuntimeWorker : public QObject
{
    Q_OBJECT

public:
    static constexpr int kPublishIntervalMs = 50; // about 20 Hz
    static constexpr int kSliceMs = 8;           // longest stretch of cycles between commands

    RuntimeWorker(std::shared_ptr<const interp::Module> module, quint64 modelRevision, std::int64_t cycleNs,
                  QObject *parent = nullptr);
    ~RuntimeWorker() override;

    // Runs cycles until stop() or a fault; `cycles` > 0 stops by itself after that many.
    void run(int cycles = 0);
    void stop();
    void singleCycle();
    void warmReset();
    void coldReset();
    // Applied once, at the start of the next cycle (a variable mapped to an input address
    // writes the input, so the program reads the value).
    void write(const QString &name, const QString &literal);
    // Held every cycle until released; takes effect at once.
    void force(const QString &name, const QString &literal);
    void release(const QString &name);
    void releaseAll();
    void setWatch(const WatchRequest &request);
    // Takes effect with the next reset (the runtime's clock is built with it).
    void setCycleTime(std::int64_t cycleNs);
    void setSpeed(RunSpeed speed);
    // The instruction budget per task run (an endless loop faults when it is used up).
    void setBudget(std::uint64_t backwardJumps);
    void publish();
    // Debugging: the breakpoints (kept across resets), and going on from a halt: Continue, or a
    // step (which, when not halted, starts a cycle and halts at its first line).
    void setBreakpoints(const std::vector<interp::Breakpoint> &breakpoints);
    void resume(interp::ResumeKind kind);

    // Going back in time (runtimeworkerhistory.cpp): after every cycle the state is kept in a
    // ScanHistory. showScan publishes an earlier scan's values (the program stays where it is;
    // a Run stops); showPresent goes back to the present; resumeFrom makes that scan the
    // present, dropping the scans after it, so the program goes on from there.
    void showScan(int cycle);
    void showPresent();
    void resumeFrom(int cycle);
    void setHistoryLimit(int scans);
    // The trace recorder: what it records (starts it again), pausing, and starting again.
    void setTrace(const interp::TraceSettings &settings);
    void setTracePaused(bool paused);
    void restartTrace();

    [[nodiscard]] bool isRunning() const { return m_running; }
    [[nodiscard]] const interp::ScanHistory &history() const { return m_history; }
    [[nodiscard]] const interp::TraceRecorder &traceRecorder() const { return m_trace; }
    [[nodiscard]] const interp::Runtime &runtime() const { return *m_runtime; }

Q_SIGNALS:
    void snapshotReady(std::shared_ptr<const iec::interp::RuntimeSnapshot> snapshot);
    // The program stopped with a fault (it is also in the snapshot published right after).
    void faulted(const iec::interp::RuntimeFault &fault);
    // A write or force that could not be done, with the reason.
    void commandFailed(const QString &message);
    // Run ended: Stop, the N cycles are done, or a fault.
    void stopped();
    // What the program logged (Beremiz's LOGGER) since the last publication: "INFO: text (cycle 3)"
    // with its level (0 critical, 1 warning, 2 info, 3 debug), in order.
    void logged(const QStringList &texts, const QList<int> &levels);
    // What the trace settings name that cannot be recorded, one sentence each.
    void traceProblems(const QStringList &problems);

private:
    void runSlice();
    bool stepOnce(); // false: a fault stopped the program, or it halted
    void applyPendingWrites();
    bool checkCycleEnd(bool finished);
    void reset(bool keepRetain); // stops a run, restarts the program, publishes
    void rebuildRuntime(bool keepRetain);
    void resolveWatch();
    void startPacing();
    [[nodiscard]] std::int64_t cyclesDue() const;
    [[nodiscard]] int speedFactor() const;
    [[nodiscard]] std::optional<QString> checkLiteral(const QString &name, const QString &literal) const;
    [[nodiscard]] QString writableName(const QString &name) const;
    void finishRun();
    void cycleFinished(); // keeps the scan in the history and samples the trace
    void startHistory();  // after login and resets: the history and the trace start afresh
    void fillValues(interp::RuntimeSnapshot &snapshot, const interp::Runtime &runtime) const;
    void fillHistory(interp::RuntimeSnapshot &snapshot);
    std::shared_ptr<const interp::TraceUpdate> traceUpdate();

    std::shared_ptr<const interp::Module> m_module;
    quint64 m_modelRevision = 0;
    std::int64_t m_cycleNs = 0;
    std::uint64_t m_budget = 0;
    std::unique_ptr<interp::Runtime> m_runtime;

    struct Watched {
        QString name;
        std::optional<interp::VariableRef> ref;
    };
    WatchRequest m_request;
    std::vector<Watched> m_watched;
    struct Forced {
        QString name;
        QString literal;
    };
    std::vector<Forced> m_forced;
    std::vector<std::pair<QString, QString>> m_pendingWrites;
    std::vector<interp::Breakpoint> m_breakpoints;

    bool m_running = false;
    int m_cyclesLeft = 0; // 0: unbounded
    RunSpeed m_speed = RunSpeed::RealTime;
    QTimer *m_tick = nullptr;
    QElapsedTimer m_paceClock;
    int m_paceStartCycle = 0;
    QElapsedTimer m_lastPublish;

    interp::ScanHistory m_history;
    interp::RuntimeState m_scanState; // the buffers each scan is copied through into the history
    std::optional<int> m_shownCycle;              // showing an earlier scan
    std::unique_ptr<interp::Runtime> m_pastViewer; // reads earlier scans, built on first use
    interp::TraceRecorder m_trace;
    quint64 m_traceSentGeneration = ~quint64(0);
    quint64 m_traceSentRows = 0;
    interp::TraceRecorder::Status m_traceSentStatus = interp::TraceRecorder::Status::NoVariables;
};

} // namespace iec::app
