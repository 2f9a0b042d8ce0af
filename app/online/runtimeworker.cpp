#include "app/online/runtimeworker.h"

#include "interpreter/sfc/sfcstatus.h"

#include <QTimer>

#include <algorithm>

namespace iec::app {

namespace {

// Behind by more than this many cycles in real time (the program is slower than its cycle
// time): the pace starts afresh instead of racing to catch up.
constexpr std::int64_t kMaxBacklogCycles = 200;

} // namespace

RuntimeWorker::RuntimeWorker(std::shared_ptr<const interp::Module> module, quint64 modelRevision,
                             std::int64_t cycleNs, QObject *parent)
    : QObject(parent)
    , m_module(std::move(module))
    , m_modelRevision(modelRevision)
    , m_cycleNs(std::max<std::int64_t>(cycleNs, 1'000'000 / 10))
    , m_tick(new QTimer(this))
{
    m_tick->setSingleShot(true);
    m_tick->setTimerType(Qt::PreciseTimer);
    connect(m_tick, &QTimer::timeout, this, &RuntimeWorker::runSlice);
    m_runtime = std::make_unique<interp::Runtime>(m_module, m_cycleNs);
    m_budget = m_runtime->vm().budgetPerRun;
    startHistory();
}

RuntimeWorker::~RuntimeWorker() = default;

void RuntimeWorker::rebuildRuntime(bool keepRetain)
{
    if (m_runtime->cycleNs() == m_cycleNs) {
        if (keepRetain)
            m_runtime->warmRestart();
        else
            m_runtime->coldRestart();
    } else {
        auto fresh = std::make_unique<interp::Runtime>(m_module, m_cycleNs);
        if (keepRetain) {
            fresh->vm().memory() = m_runtime->vm().memory();
            fresh->warmRestart();
        }
        m_runtime = std::move(fresh);
        for (const Forced &forced : m_forced)
            m_runtime->force(forced.name, forced.literal);
    }
    m_runtime->vm().budgetPerRun = m_budget;
    m_runtime->setBreakpoints(m_breakpoints);
    m_pendingWrites.clear();
    resolveWatch(); // a rebuilt runtime is a new symbol owner
    startHistory();
}

void RuntimeWorker::run(int cycles)
{
    m_shownCycle.reset();
    if (m_runtime->fault())
        return;
    m_cyclesLeft = std::max(0, cycles);
    if (!m_running) {
        m_running = true;
        startPacing();
        m_lastPublish.start();
    }
    publish();
    m_tick->start(0);
}

void RuntimeWorker::stop()
{
    if (!m_running)
        return;
    finishRun();
}

void RuntimeWorker::finishRun()
{
    m_running = false;
    m_cyclesLeft = 0;
    m_tick->stop();
    publish();
    Q_EMIT stopped();
}

void RuntimeWorker::singleCycle()
{
    m_shownCycle.reset();
    if (m_running)
        finishRun();
    stepOnce();
    publish();
}

void RuntimeWorker::warmReset()
{
    reset(true);
}

void RuntimeWorker::coldReset()
{
    reset(false);
}

void RuntimeWorker::reset(bool keepRetain)
{
    const bool wasRunning = m_running;
    m_running = false;
    m_tick->stop();
    rebuildRuntime(keepRetain);
    publish();
    if (wasRunning)
        Q_EMIT stopped();
}

QString RuntimeWorker::writableName(const QString &name) const
{
    // A variable declared AT %IX0.1 is overwritten from the input image at the start of each
    // cycle; writing the input itself makes the program see the value.
    const std::optional<interp::VariableRef> ref = m_runtime->find(name);
    if (!ref || ref->imageArea != 0)
        return name;
    for (const interp::LocatedVar &located : m_module->located) {
        if (located.area == 'I' && located.offset == ref->offset && ref->bit < 0)
            return located.address;
    }
    return name;
}

std::optional<QString> RuntimeWorker::checkLiteral(const QString &name, const QString &literal) const
{
    const std::optional<interp::VariableRef> ref = m_runtime->find(name);
    if (!ref)
        return tr("There is no variable called %1.").arg(name);
    // Tried on copies, so that a bad literal is reported now rather than at the next cycle.
    std::vector<std::uint8_t> memory = m_runtime->vm().memory();
    std::vector<std::uint8_t> image = m_runtime->image(ref->imageArea ? ref->imageArea : 'M');
    if (std::optional<QString> problem = interp::writeLiteral(*ref, literal, memory.data(), image.data()))
        return tr("%1: %2").arg(name, *problem);
    return std::nullopt;
}

void RuntimeWorker::write(const QString &name, const QString &literal)
{
    if (const std::optional<QString> problem = checkLiteral(name, literal)) {
        Q_EMIT commandFailed(*problem);
        return;
    }
    m_pendingWrites.emplace_back(writableName(name), literal);
}

void RuntimeWorker::force(const QString &name, const QString &literal)
{
    if (std::optional<QString> problem = m_runtime->force(name, literal)) {
        Q_EMIT commandFailed(tr("%1: %2").arg(name, *problem));
        return;
    }
    std::erase_if(m_forced, [&](const Forced &f) { return f.name.compare(name, Qt::CaseInsensitive) == 0; });
    m_forced.push_back({name, literal});
    publish();
}

void RuntimeWorker::release(const QString &name)
{
    m_runtime->unforce(name);
    std::erase_if(m_forced, [&](const Forced &f) { return f.name.compare(name, Qt::CaseInsensitive) == 0; });
    publish();
}

void RuntimeWorker::releaseAll()
{
    for (const Forced &forced : m_forced)
        m_runtime->unforce(forced.name);
    m_forced.clear();
    publish();
}

void RuntimeWorker::setWatch(const WatchRequest &request)
{
    m_request = request;
    resolveWatch();
    publish();
}

void RuntimeWorker::resolveWatch()
{
    m_watched.clear();
    m_watched.reserve(size_t(m_request.names.size()));
    for (const QString &name : std::as_const(m_request.names))
        m_watched.push_back({name, m_runtime->find(name)});
}

void RuntimeWorker::setCycleTime(std::int64_t cycleNs)
{
    m_cycleNs = std::max<std::int64_t>(cycleNs, 100'000);
    if (m_runtime->cycle() == 0 && !m_running)
        rebuildRuntime(false); // nothing ran yet: nothing to lose
    startPacing();
}

void RuntimeWorker::setSpeed(RunSpeed speed)
{
    m_speed = speed;
    startPacing();
    if (m_running)
        m_tick->start(0);
}

void RuntimeWorker::setBudget(std::uint64_t backwardJumps)
{
    m_budget = backwardJumps;
    m_runtime->vm().budgetPerRun = backwardJumps;
}

void RuntimeWorker::startPacing()
{
    m_paceClock.start();
    m_paceStartCycle = m_runtime->cycle();
}

int RuntimeWorker::speedFactor() const
{
    return m_speed == RunSpeed::Times10 ? 10 : 1;
}

std::int64_t RuntimeWorker::cyclesDue() const
{
    return m_paceClock.nsecsElapsed() * speedFactor() / m_runtime->cycleNs();
}

bool RuntimeWorker::stepOnce()
{
    if (m_runtime->fault())
        return false; // stopped until a reset; the fault was reported when it happened
    applyPendingWrites();
    return checkCycleEnd(m_runtime->runCycle());
}

// Writes wait for the start of a cycle: a halted program goes on without them.
void RuntimeWorker::applyPendingWrites()
{
    if (m_runtime->isHalted())
        return;
    for (const auto &[name, literal] : m_pendingWrites) {
        if (std::optional<QString> problem = m_runtime->write(name, literal))
            Q_EMIT commandFailed(tr("%1: %2").arg(name, *problem));
    }
    m_pendingWrites.clear();
}

// After a cycle ran (or went on from a halt): a halt or a fault ends Run.
bool RuntimeWorker::checkCycleEnd(bool finished)
{
    if (finished) {
        cycleFinished();
        return true;
    }
    if (m_running) {
        m_running = false;
        m_cyclesLeft = 0;
        m_tick->stop();
        Q_EMIT stopped();
    }
    if (m_runtime->fault())
        Q_EMIT faulted(*m_runtime->fault());
    return false;
}

void RuntimeWorker::setBreakpoints(const std::vector<interp::Breakpoint> &breakpoints)
{
    m_breakpoints = breakpoints;
    m_runtime->setBreakpoints(breakpoints);
}

void RuntimeWorker::resume(interp::ResumeKind kind)
{
    m_shownCycle.reset();
    if (m_running)
        finishRun();
    if (m_runtime->fault())
        return;
    applyPendingWrites();
    checkCycleEnd(m_runtime->resume(kind));
    publish();
}

void RuntimeWorker::runSlice()
{
    QElapsedTimer slice;
    slice.start();
    while (m_running) {
        if (m_speed != RunSpeed::AsFastAsPossible) {
            std::int64_t due = cyclesDue();
            std::int64_t done = m_runtime->cycle() - m_paceStartCycle;
            if (due - done > kMaxBacklogCycles) {
                startPacing();
                due = done = 0;
            }
            if (done >= due) {
                // Sleep until the next cycle is due on the wall clock.
                const std::int64_t nextNs = (done + 1) * m_runtime->cycleNs() / speedFactor();
                const std::int64_t waitNs = nextNs - m_paceClock.nsecsElapsed();
                m_tick->start(int(std::max<std::int64_t>(0, (waitNs + 999'999) / 1'000'000)));
                break;
            }
        }
        if (!stepOnce()) {
            publish();
            return;
        }
        if (m_cyclesLeft > 0 && --m_cyclesLeft == 0) {
            finishRun();
            return;
        }
        if (slice.elapsed() >= kSliceMs) {
            m_tick->start(0); // let queued commands in
            break;
        }
    }
    if (m_running && m_lastPublish.elapsed() >= kPublishIntervalMs)
        publish();
}

void RuntimeWorker::publish()
{
    auto snapshot = std::make_shared<interp::RuntimeSnapshot>();
    snapshot->modelRevision = m_modelRevision;
    snapshot->cycle = m_runtime->cycle();
    snapshot->presentCycle = m_runtime->cycle();
    snapshot->timeNs = m_runtime->timeNs();
    snapshot->cycleNs = m_runtime->cycleNs();
    snapshot->running = m_running;
    snapshot->fault = m_runtime->fault();
    snapshot->halt = m_runtime->halt();
    for (const Forced &forced : m_forced)
        snapshot->forced.insert(forced.name.toUpper());
    fillHistory(*snapshot);
    if (!snapshot->historyCycle)
        fillValues(*snapshot, *m_runtime);
    snapshot->trace = traceUpdate();
    m_lastPublish.start();
    if (const std::vector<interp::Runtime::LogEntry> log = m_runtime->takeLog(); !log.empty()) {
        QStringList texts;
        QList<int> levels;
        for (const interp::Runtime::LogEntry &entry : log) {
            texts << entry.toString();
            levels << entry.level;
        }
        Q_EMIT logged(texts, levels);
    }
    Q_EMIT snapshotReady(std::move(snapshot));
}

void RuntimeWorker::fillValues(interp::RuntimeSnapshot &snapshot, const interp::Runtime &runtime) const
{
    snapshot.values.reserve(qsizetype(m_watched.size()));
    for (const Watched &watched : m_watched) {
        if (watched.ref)
            snapshot.values.insert(watched.name, runtime.read(*watched.ref));
    }
    for (const ChartRequest &chart : m_request.charts) {
        if (std::optional<interp::sfc::ChartState> state = interp::sfc::chartState(runtime, chart.pou, chart.instance, chart.action))
            snapshot.charts.push_back(std::move(*state));
    }
}

} // namespace iec::app
