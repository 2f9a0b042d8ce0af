#pragma once

#include "app/messagespane.h"

#include <QElapsedTimer>
#include <QObject>
#include <QThreadPool>
#include <QTimer>

#include <memory>

namespace iec::model {
class ProjectModel;
}

namespace iec::app {

class BuildController;

// Diagnostics while typing: a short pause after the project changed (what is typed reaches the
// model after the editor's own pause), the project is compiled on a worker thread, never on the
// thread that takes the keys, and the result is shown as Build shows it (BuildController::publish:
// the messages pane, underlines, graphical diagnostics). A result is shown only when the model is
// still at the revision that was compiled, so results for older text never land on newer text; a
// change during a compile schedules the next one. One compile runs at a time.
class LiveDiagnostics : public QObject
{
    Q_OBJECT

public:
    LiveDiagnostics(model::ProjectModel &model, BuildController &build, QObject *parent = nullptr);
    ~LiveDiagnostics() override;

    void setEnabled(bool enabled);
    [[nodiscard]] bool isEnabled() const { return m_enabled; }
    // Milliseconds of quiet after a change before compiling (default 250; the editors wait 300 ms before they push typing).
    void setDelay(int milliseconds) { m_timer.setInterval(milliseconds); }
    [[nodiscard]] bool isCompiling() const { return m_running; }
    // What the last finished compile took on its thread, and how long the UI thread spent starting
    // it (copying the project); for the benchmark.
    [[nodiscard]] qint64 lastCompileMs() const { return m_lastCompileMs; }
    [[nodiscard]] qint64 lastSnapshotMs() const { return m_lastSnapshotMs; }

public Q_SLOTS:
    // Compiles now (as if the pause had passed).
    void compileNow();

Q_SIGNALS:
    // A result was shown (`revision` is the model's); or dropped because the model moved on.
    void published(quint64 revision, int errors, int warnings);
    void discarded(quint64 revision);

private:
    struct Result;
    void schedule();
    void finish(const std::shared_ptr<Result> &result);

    model::ProjectModel &m_model;
    BuildController &m_build;
    QTimer m_timer;
    QThreadPool m_pool;
    bool m_enabled = true;
    bool m_running = false;
    bool m_again = false;
    qint64 m_lastCompileMs = 0;
    qint64 m_lastSnapshotMs = 0;
};

} // namespace iec::app
