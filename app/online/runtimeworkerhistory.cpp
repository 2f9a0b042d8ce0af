// RuntimeWorker's history and trace (runtimeworker.h): the scans kept to go back to, and the
// trace recorder's samples, both taken after every finished cycle on the runtime's thread.
#include "app/online/runtimeworker.h"

#include <QTimer>

namespace iec::app {

void RuntimeWorker::startHistory()
{
    m_shownCycle.reset();
    m_history.clear();
    m_history.record(m_runtime->state());
    m_trace.restart();
    m_trace.sample(*m_runtime);
}

void RuntimeWorker::cycleFinished()
{
    m_runtime->copyStateTo(m_scanState);
    m_history.record(m_scanState);
    m_trace.sample(*m_runtime);
}

void RuntimeWorker::showScan(int cycle)
{
    if (m_running)
        finishRun();
    if (cycle == m_runtime->cycle() && !m_runtime->isHalted())
        m_shownCycle.reset();
    else if (m_history.contains(cycle))
        m_shownCycle = cycle;
    publish();
}

void RuntimeWorker::showPresent()
{
    m_shownCycle.reset();
    publish();
}

void RuntimeWorker::resumeFrom(int cycle)
{
    const std::optional<interp::RuntimeState> state = m_history.stateAt(cycle);
    if (!state)
        return;
    if (m_running)
        finishRun();
    m_runtime->restore(*state);
    m_history.truncateAfter(cycle);
    m_trace.truncateAfter(cycle);
    m_shownCycle.reset();
    publish();
}

void RuntimeWorker::setHistoryLimit(int scans)
{
    m_history.setLimits(scans, interp::ScanHistory::kDefaultBytes);
    publish();
}

void RuntimeWorker::setTrace(const interp::TraceSettings &settings)
{
    const QStringList problems = m_trace.configure(settings, *m_runtime);
    m_trace.sample(*m_runtime);
    if (!problems.isEmpty())
        Q_EMIT traceProblems(problems);
    publish();
}

void RuntimeWorker::setTracePaused(bool paused)
{
    m_trace.setPaused(paused);
    publish();
}

void RuntimeWorker::restartTrace()
{
    m_trace.restart();
    m_trace.sample(*m_runtime);
    publish();
}

void RuntimeWorker::fillHistory(interp::RuntimeSnapshot &snapshot)
{
    snapshot.history = {m_history.firstCycle(), m_history.lastCycle(), m_history.scanLimit(), m_history.bytesUsed()};
    if (!m_shownCycle)
        return;
    const std::optional<interp::RuntimeState> state = m_history.stateAt(*m_shownCycle);
    if (!state) {
        m_shownCycle.reset();
        return;
    }
    if (!m_pastViewer)
        m_pastViewer = std::make_unique<interp::Runtime>(m_module, m_runtime->cycleNs());
    m_pastViewer->restore(*state);
    snapshot.historyCycle = *m_shownCycle;
    snapshot.cycle = state->cycle;
    snapshot.timeNs = state->timeNs;
    snapshot.halt.reset();
    fillValues(snapshot, *m_pastViewer);
}

std::shared_ptr<const interp::TraceUpdate> RuntimeWorker::traceUpdate()
{
    const std::deque<interp::TraceRow> &rows = m_trace.rows();
    const bool reset = m_trace.generation() != m_traceSentGeneration;
    quint64 fresh = m_trace.appended() - (reset ? 0 : m_traceSentRows);
    if (!reset && fresh == 0 && m_trace.status() == m_traceSentStatus)
        return nullptr;
    auto update = std::make_shared<interp::TraceUpdate>();
    update->module = m_module;
    update->variables = m_trace.variables();
    update->reset = reset || fresh > rows.size();
    fresh = update->reset ? rows.size() : fresh;
    update->rows.assign(rows.end() - std::ptrdiff_t(fresh), rows.end());
    update->status = m_trace.status();
    update->triggerCycle = m_trace.triggerCycle();
    update->conditionProblem = m_trace.conditionProblem();
    update->capacity = m_trace.settings().capacity;
    m_traceSentGeneration = m_trace.generation();
    m_traceSentRows = m_trace.appended();
    m_traceSentStatus = update->status;
    return update;
}

} // namespace iec::app
