#pragma once

#include "app/documentarea.h"
#include "app/messagespane.h"
#include "app/online/runtimeworker.h"
#include "model/ids.h"

#include <QObject>
#include <QPointer>

#include <functional>
#include <memory>

class QAction;
class QActionGroup;
class QLabel;
class QMenu;
class QStatusBar;
class QThread;

namespace iec::model {
class ProjectModel;
}

namespace iec::app {

class BuildController;
class WatchPane;

// Online mode in the window: Login compiles the project (errors block it and stay in the
// messages pane), starts a RuntimeWorker on its own thread, and from then on hands every
// snapshot to each open editor (OnlineView), the watch pane and the status bar. Writes and
// forces go to the worker's queue, never into the model or an undo stack. Logout stops the
// worker and gives the editors back (setOnlineSnapshot(nullptr)).
class OnlineController : public QObject
{
    Q_OBJECT

public:
    struct Actions {
        QAction *login = nullptr;       // Login and Run (F5)
        QAction *stop = nullptr;        // Stop (Shift+F5)
        QAction *singleCycle = nullptr; // Single Cycle (Ctrl+F5)
    };

    OnlineController(model::ProjectModel &projectModel, DocumentArea &documents, MessagesPane &messages,
                     BuildController &build, WatchPane &watch, QStatusBar &statusBar, Actions actions,
                     QObject *parent = nullptr);
    ~OnlineController() override;

    // Tests run the worker on the calling thread: every command completes before it returns.
    void setThreaded(bool threaded) { m_threaded = threaded; }

    [[nodiscard]] bool isOnline() const { return m_worker != nullptr; }
    [[nodiscard]] bool isRunning() const;
    [[nodiscard]] std::shared_ptr<const interp::RuntimeSnapshot> latestSnapshot() const { return m_latest; }
    [[nodiscard]] std::shared_ptr<const interp::Module> module() const { return m_module; }
    [[nodiscard]] std::int64_t cycleNs() const { return m_cycleNs; }
    [[nodiscard]] RunSpeed speed() const { return m_speed; }
    [[nodiscard]] QLabel *statusLabel() const { return m_statusLabel; }

    // The Online menu's entries below the three window actions.
    void addTo(QMenu *menu);
    void retranslate();

public Q_SLOTS:
    // Compiles and starts an online session without running; false (messages in the pane) on errors.
    bool login();
    void logout();
    // F5: logs in when needed, then runs.
    void loginAndRun();
    void stop();
    // Ctrl+F5: logs in when needed, then runs exactly one cycle (or finishes a halted one).
    void singleCycle();
    void runCycles(int count);
    void runCyclesInteractive();
    void resetWarm();
    void resetCold();
    void write(const QString &name, const QString &literal);
    void force(const QString &name, const QString &literal);
    void release(const QString &name);
    void releaseAll();
    void setCycleTime(std::int64_t cycleNs);
    void setSpeed(iec::app::RunSpeed speed);
    void setBudget(std::uint64_t backwardJumps);
    // Debugging: the breakpoints the program halts at (sent again at every login), and going on
    // from a halt; a step logs in when needed and halts at the next line run.
    void setBreakpoints(const std::vector<interp::Breakpoint> &breakpoints);
    void resume(interp::ResumeKind kind);
    // Going back in time and the trace (RuntimeWorker): only while online; the trace settings
    // and the history's length are sent again by their panes at every login.
    void showScan(int cycle);
    void showPresent();
    void resumeFrom(int cycle);
    void setHistoryLimit(int scans);
    void setTrace(const interp::TraceSettings &settings);
    void setTracePaused(bool paused);
    void restartTrace();

Q_SIGNALS:
    void onlineChanged(bool online);
    // Every snapshot once it reached the views (tests wait on it).
    void snapshotShown(std::shared_ptr<const iec::interp::RuntimeSnapshot> snapshot);
    void faultShown(const iec::interp::RuntimeFault &fault);
    void traceProblems(const QStringList &problems);

private:
    void send(std::function<void(RuntimeWorker &)> command);
    void shutDownWorker();
    void showSnapshot(std::shared_ptr<const interp::RuntimeSnapshot> snapshot);
    void showFault(const interp::RuntimeFault &fault);
    void showLog(const QStringList &texts, const QList<int> &levels);
    // What the watch pane and the open views want, by name and by chart (instance, POU id):
    // cheap to build and compare on every snapshot; the POUs are copied only when it changed.
    struct Wanted {
        QStringList names;
        struct Chart {
            QString instance;
            model::PouId pou;
            QString action; // empty: the POU's own chart
            bool operator==(const Chart &) const = default;
        };
        std::vector<Chart> charts;
        bool operator==(const Wanted &) const = default;
    };
    void updateWatchRequest();
    void updateWatchRequestFor(const QList<DocumentArea::OnlineDocument> &views);
    [[nodiscard]] Wanted wanted(const QList<DocumentArea::OnlineDocument> &views) const;
    [[nodiscard]] WatchRequest requestFor(const Wanted &wanted) const;
    void updateActions();
    void updateStatus();
    void createActions();

    model::ProjectModel &m_projectModel;
    DocumentArea &m_documents;
    MessagesPane &m_messages;
    QList<Message> m_log; // what the program logged this session (messages pane, "log")
    BuildController &m_build;
    WatchPane &m_watch;
    QStatusBar &m_statusBar;
    Actions m_windowActions;

    QAction *m_logoutAction = nullptr;
    QAction *m_runCyclesAction = nullptr;
    QAction *m_resetWarmAction = nullptr;
    QAction *m_resetColdAction = nullptr;
    QMenu *m_cycleTimeMenu = nullptr;
    QMenu *m_speedMenu = nullptr;
    QActionGroup *m_cycleTimeGroup = nullptr;
    QActionGroup *m_speedGroup = nullptr;
    QLabel *m_statusLabel = nullptr;

    bool m_threaded = true;
    QThread *m_thread = nullptr;
    RuntimeWorker *m_worker = nullptr;
    int m_session = 0;
    std::shared_ptr<const interp::Module> m_module;
    std::shared_ptr<const interp::RuntimeSnapshot> m_latest;
    Wanted m_sent;
    std::int64_t m_cycleNs = 10'000'000;
    RunSpeed m_speed = RunSpeed::RealTime;
    std::uint64_t m_budget = 0; // 0: the VM's default
    bool m_running = false;
};

} // namespace iec::app
