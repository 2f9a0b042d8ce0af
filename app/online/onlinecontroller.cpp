#include "app/online/onlinecontroller.h"

#include "app/buildcontroller.h"
#include "app/documentarea.h"
#include "app/messagespane.h"
#include "app/online/watchpane.h"
#include "editors/common/onlineview.h"
#include "interpreter/frontend/projectsource.h"
#include "model/projectmodel.h"

#include <QAction>
#include <QActionGroup>
#include <QDockWidget>
#include <QInputDialog>
#include <QLabel>
#include <QMenu>
#include <QStatusBar>
#include <QThread>

namespace iec::app {

namespace {

const QString kRuntimeSource = QStringLiteral("runtime");
// What the program logs (LOGGER), kept across logout so it can be read afterwards; the newest
// kMaxLogMessages, so that a program logging every cycle cannot fill the memory.
const QString kLogSource = QStringLiteral("log");
constexpr qsizetype kMaxLogMessages = 500;
constexpr int kCycleTimesMs[] = {1, 2, 5, 10, 20, 50, 100};

void showDockOf(QWidget &pane)
{
    if (auto *dock = qobject_cast<QDockWidget *>(pane.parentWidget()))
        dock->show();
}

QString formatSeconds(std::int64_t ns)
{
    return QString::number(double(ns) / 1e9, 'f', 3);
}

} // namespace

OnlineController::OnlineController(model::ProjectModel &projectModel, DocumentArea &documents,
                                   MessagesPane &messages, BuildController &build, WatchPane &watch,
                                   QStatusBar &statusBar, Actions actions, QObject *parent)
    : QObject(parent)
    , m_projectModel(projectModel)
    , m_documents(documents)
    , m_messages(messages)
    , m_build(build)
    , m_watch(watch)
    , m_statusBar(statusBar)
    , m_windowActions(actions)
{
    qRegisterMetaType<std::shared_ptr<const interp::RuntimeSnapshot>>();
    qRegisterMetaType<interp::RuntimeFault>();
    createActions();
    m_statusLabel = new QLabel(&statusBar);
    m_statusLabel->setObjectName(QStringLiteral("onlineStatus"));
    statusBar.addPermanentWidget(m_statusLabel);

    connect(m_windowActions.login, &QAction::triggered, this, &OnlineController::loginAndRun);
    connect(m_windowActions.stop, &QAction::triggered, this, &OnlineController::stop);
    connect(m_windowActions.singleCycle, &QAction::triggered, this, &OnlineController::singleCycle);

    connect(&watch, &WatchPane::writeRequested, this, &OnlineController::write);
    connect(&watch, &WatchPane::forceRequested, this, &OnlineController::force);
    connect(&watch, &WatchPane::releaseRequested, this, &OnlineController::release);
    connect(&watch, &WatchPane::releaseAllRequested, this, &OnlineController::releaseAll);
    connect(&watch, &WatchPane::namesChanged, this, &OnlineController::updateWatchRequest);
    connect(&documents, &DocumentArea::addToWatchRequested, this, [this](const QString &name) {
        m_watch.addVariable(name);
        showDockOf(m_watch);
    });
    connect(&documents, &DocumentArea::prepareValueRequested, this, [this](const QString &name, const QString &literal) {
        m_watch.prepareValue(name, literal);
        showDockOf(m_watch);
    });
    // A document opened while online shows the program at once and asks for its names.
    connect(&documents, &QTabWidget::currentChanged, this, [this] {
        if (!m_latest)
            return;
        const QList<DocumentArea::OnlineDocument> views = m_documents.onlineViews();
        for (const DocumentArea::OnlineDocument &document : views)
            document.view->setOnlineSnapshot(m_latest.get());
        updateWatchRequestFor(views);
    });
    connect(&projectModel, &model::ProjectModel::projectReset, this, &OnlineController::logout);
    updateActions();
    updateStatus();
    retranslate();
}

OnlineController::~OnlineController()
{
    // The window's widgets may be gone already: only the thread is ended here.
    shutDownWorker();
}

void OnlineController::createActions()
{
    m_logoutAction = new QAction(this);
    m_logoutAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F8));
    connect(m_logoutAction, &QAction::triggered, this, &OnlineController::logout);
    m_runCyclesAction = new QAction(this);
    connect(m_runCyclesAction, &QAction::triggered, this, &OnlineController::runCyclesInteractive);
    m_resetWarmAction = new QAction(this);
    connect(m_resetWarmAction, &QAction::triggered, this, &OnlineController::resetWarm);
    m_resetColdAction = new QAction(this);
    connect(m_resetColdAction, &QAction::triggered, this, &OnlineController::resetCold);

    m_cycleTimeMenu = new QMenu;
    m_cycleTimeMenu->setObjectName(QStringLiteral("cycleTimeMenu"));
    m_cycleTimeGroup = new QActionGroup(this);
    for (const int ms : kCycleTimesMs) {
        QAction *action = m_cycleTimeMenu->addAction(QString());
        action->setCheckable(true);
        action->setData(ms);
        action->setChecked(std::int64_t(ms) * 1'000'000 == m_cycleNs);
        m_cycleTimeGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, ms] { setCycleTime(std::int64_t(ms) * 1'000'000); });
    }
    m_speedMenu = new QMenu;
    m_speedMenu->setObjectName(QStringLiteral("speedMenu"));
    m_speedGroup = new QActionGroup(this);
    for (const RunSpeed speed : {RunSpeed::RealTime, RunSpeed::Times10, RunSpeed::AsFastAsPossible}) {
        QAction *action = m_speedMenu->addAction(QString());
        action->setCheckable(true);
        action->setData(int(speed));
        action->setChecked(speed == m_speed);
        m_speedGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, speed] { setSpeed(speed); });
    }
    // The menus have no QWidget parent (they go into the window's menu): this object owns them.
    connect(this, &QObject::destroyed, m_cycleTimeMenu, &QObject::deleteLater);
    connect(this, &QObject::destroyed, m_speedMenu, &QObject::deleteLater);
}

void OnlineController::addTo(QMenu *menu)
{
    menu->addAction(m_runCyclesAction);
    menu->addSeparator();
    menu->addAction(m_resetWarmAction);
    menu->addAction(m_resetColdAction);
    menu->addSeparator();
    menu->addMenu(m_cycleTimeMenu);
    menu->addMenu(m_speedMenu);
    menu->addSeparator();
    menu->addAction(m_logoutAction);
}

void OnlineController::retranslate()
{
    m_logoutAction->setText(tr("Log&out"));
    m_runCyclesAction->setText(tr("Run &N Cycles..."));
    m_resetWarmAction->setText(tr("Reset &Warm"));
    m_resetColdAction->setText(tr("Reset C&old"));
    m_cycleTimeMenu->setTitle(tr("C&ycle Time"));
    m_speedMenu->setTitle(tr("S&peed"));
    for (QAction *action : m_cycleTimeGroup->actions())
        action->setText(tr("%1 ms").arg(action->data().toInt()));
    const QList<QAction *> speeds = m_speedGroup->actions();
    speeds[0]->setText(tr("&Real Time"));
    speeds[1]->setText(tr("&10 Times Faster"));
    speeds[2]->setText(tr("As &Fast as Possible"));
    m_cycleTimeMenu->setToolTip(tr("The cycle time takes effect at login and at a reset."));
    updateStatus();
}

bool OnlineController::isRunning() const
{
    return m_worker && m_running;
}

void OnlineController::send(std::function<void(RuntimeWorker &)> command)
{
    if (!m_worker)
        return;
    if (!m_threaded) {
        command(*m_worker);
        return;
    }
    RuntimeWorker *worker = m_worker;
    QMetaObject::invokeMethod(worker, [worker, command = std::move(command)] { command(*worker); }, Qt::QueuedConnection);
}

bool OnlineController::login()
{
    if (isOnline())
        return true;
    // Build lists the messages (and flushes what was just typed); errors keep the program offline.
    interp::CompileOptions options;
    options.cycleNs = m_cycleNs;
    if (!m_build.build(options)) {
        m_statusBar.showMessage(tr("Login refused: the project has errors. See the Messages pane."));
        return false;
    }
    std::shared_ptr<const interp::Module> module = m_build.lastModule();
    if (!module)
        return false;
    m_module = module;
    m_messages.model().setMessages(kRuntimeSource, {});
    m_log.clear();
    m_messages.model().setMessages(kLogSource, {});

    ++m_session;
    const int session = m_session;
    m_worker = new RuntimeWorker(module, m_projectModel.revision(), m_cycleNs);
    if (m_budget > 0)
        m_worker->setBudget(m_budget);
    m_worker->setSpeed(m_speed);
    connect(m_worker, &RuntimeWorker::snapshotReady, this,
        [this, session](std::shared_ptr<const interp::RuntimeSnapshot> snapshot) {
            if (session == m_session)
                showSnapshot(std::move(snapshot));
        });
    connect(m_worker, &RuntimeWorker::faulted, this, [this, session](const interp::RuntimeFault &fault) {
        if (session == m_session)
            showFault(fault);
    });
    connect(m_worker, &RuntimeWorker::commandFailed, this, [this, session](const QString &message) {
        if (session == m_session)
            m_statusBar.showMessage(message, 10000);
    });
    connect(m_worker, &RuntimeWorker::logged, this, [this, session](const QStringList &texts, const QList<int> &levels) {
        if (session == m_session)
            showLog(texts, levels);
    });
    connect(m_worker, &RuntimeWorker::traceProblems, this, [this, session](const QStringList &problems) {
        if (session == m_session)
            Q_EMIT traceProblems(problems);
    });
    connect(m_worker, &RuntimeWorker::stopped, this, [this, session] {
        if (session != m_session)
            return;
        m_running = false;
        updateActions();
    });
    if (m_threaded) {
        m_thread = new QThread(this);
        m_thread->setObjectName(QStringLiteral("runtime"));
        m_worker->moveToThread(m_thread);
        m_thread->start();
    }
    m_watch.setModule(module);
    m_sent = wanted(m_documents.onlineViews());
    send([request = requestFor(m_sent)](RuntimeWorker &worker) { worker.setWatch(request); });
    // Editing is refused while online (the window locks the editors on onlineChanged): say so.
    m_statusBar.showMessage(
        tr("Logged in. F5 runs the program, Ctrl+F5 runs one cycle. Log out to edit (Online → Logout)."), 10000);
    updateActions();
    updateStatus();
    Q_EMIT onlineChanged(true);
    return true;
}

void OnlineController::shutDownWorker()
{
    if (!m_worker)
        return;
    ++m_session; // whatever the worker still sends is for a session that is over
    RuntimeWorker *worker = m_worker;
    m_worker = nullptr;
    if (m_thread) {
        // The worker stops its timer on its own thread, comes back to this one, and ends the thread.
        QThread *home = thread();
        QMetaObject::invokeMethod(worker, [worker, home] {
            worker->blockSignals(true);
            worker->stop();
            worker->moveToThread(home);
            QThread::currentThread()->quit();
        }, Qt::QueuedConnection);
        m_thread->wait();
        delete m_thread;
        m_thread = nullptr;
    }
    delete worker;
}

void OnlineController::logout()
{
    if (!m_worker)
        return;
    shutDownWorker();
    m_latest.reset();
    m_running = false;
    for (const DocumentArea::OnlineDocument &document : m_documents.onlineViews())
        document.view->setOnlineSnapshot(nullptr);
    m_watch.setSnapshot(nullptr);
    updateActions();
    updateStatus();
    m_statusBar.showMessage(tr("Logged out."), 3000);
    Q_EMIT onlineChanged(false);
}

void OnlineController::loginAndRun()
{
    if (!login())
        return;
    m_running = true;
    send([](RuntimeWorker &worker) { worker.run(); });
    updateActions();
}

void OnlineController::stop()
{
    send([](RuntimeWorker &worker) { worker.stop(); });
}

void OnlineController::singleCycle()
{
    if (!login())
        return;
    send([](RuntimeWorker &worker) { worker.singleCycle(); });
}

void OnlineController::setBreakpoints(const std::vector<interp::Breakpoint> &breakpoints)
{
    send([breakpoints](RuntimeWorker &worker) { worker.setBreakpoints(breakpoints); });
}

void OnlineController::resume(interp::ResumeKind kind)
{
    if (!login())
        return;
    send([kind](RuntimeWorker &worker) { worker.resume(kind); });
}

void OnlineController::showScan(int cycle)
{
    send([cycle](RuntimeWorker &worker) { worker.showScan(cycle); });
}

void OnlineController::showPresent()
{
    send([](RuntimeWorker &worker) { worker.showPresent(); });
}

void OnlineController::resumeFrom(int cycle)
{
    send([cycle](RuntimeWorker &worker) { worker.resumeFrom(cycle); });
}

void OnlineController::setHistoryLimit(int scans)
{
    send([scans](RuntimeWorker &worker) { worker.setHistoryLimit(scans); });
}

void OnlineController::setTrace(const interp::TraceSettings &settings)
{
    send([settings](RuntimeWorker &worker) { worker.setTrace(settings); });
}

void OnlineController::setTracePaused(bool paused)
{
    send([paused](RuntimeWorker &worker) { worker.setTracePaused(paused); });
}

void OnlineController::restartTrace()
{
    send([](RuntimeWorker &worker) { worker.restartTrace(); });
}

void OnlineController::runCycles(int count)
{
    if (count <= 0 || !login())
        return;
    m_running = true;
    send([count](RuntimeWorker &worker) { worker.run(count); });
    updateActions();
}

void OnlineController::runCyclesInteractive()
{
    bool ok = false;
    const int count = QInputDialog::getInt(m_documents.window(), tr("Run N Cycles"), tr("Number of cycles:"), 10, 1,
                                           1'000'000, 1, &ok);
    if (ok)
        runCycles(count);
}

void OnlineController::showLog(const QStringList &texts, const QList<int> &levels)
{
    for (qsizetype i = 0; i < texts.size(); ++i) {
        Message message;
        const int level = levels.value(i, 2);
        message.severity = level == 0 ? Message::Severity::Error : level == 1 ? Message::Severity::Warning : Message::Severity::Info;
        message.text = tr("Program log: %1").arg(texts[i]);
        m_log.append(message);
    }
    if (m_log.size() > kMaxLogMessages)
        m_log.remove(0, m_log.size() - kMaxLogMessages);
    m_messages.model().setMessages(kLogSource, m_log);
}

void OnlineController::resetWarm()
{
    m_messages.model().setMessages(kRuntimeSource, {});
    send([](RuntimeWorker &worker) { worker.warmReset(); });
}

void OnlineController::resetCold()
{
    m_messages.model().setMessages(kRuntimeSource, {});
    send([](RuntimeWorker &worker) { worker.coldReset(); });
}

void OnlineController::write(const QString &name, const QString &literal)
{
    if (!isOnline()) {
        m_statusBar.showMessage(tr("Log in to write values."), 5000);
        return;
    }
    send([name, literal](RuntimeWorker &worker) { worker.write(name, literal); });
}

void OnlineController::force(const QString &name, const QString &literal)
{
    if (!isOnline()) {
        m_statusBar.showMessage(tr("Log in to force values."), 5000);
        return;
    }
    send([name, literal](RuntimeWorker &worker) { worker.force(name, literal); });
}

void OnlineController::release(const QString &name)
{
    send([name](RuntimeWorker &worker) { worker.release(name); });
}

void OnlineController::releaseAll()
{
    send([](RuntimeWorker &worker) { worker.releaseAll(); });
}

void OnlineController::setCycleTime(std::int64_t cycleNs)
{
    m_cycleNs = cycleNs;
    for (QAction *action : m_cycleTimeGroup->actions())
        action->setChecked(std::int64_t(action->data().toInt()) * 1'000'000 == cycleNs);
    send([cycleNs](RuntimeWorker &worker) { worker.setCycleTime(cycleNs); });
    if (isOnline() && m_latest && m_latest->cycle > 0)
        m_statusBar.showMessage(tr("The new cycle time takes effect at the next reset."), 5000);
    updateStatus();
}

void OnlineController::setSpeed(RunSpeed speed)
{
    m_speed = speed;
    for (QAction *action : m_speedGroup->actions())
        action->setChecked(action->data().toInt() == int(speed));
    send([speed](RuntimeWorker &worker) { worker.setSpeed(speed); });
    updateStatus();
}

void OnlineController::setBudget(std::uint64_t backwardJumps)
{
    m_budget = backwardJumps;
    send([backwardJumps](RuntimeWorker &worker) { worker.setBudget(backwardJumps); });
}

OnlineController::Wanted OnlineController::wanted(const QList<DocumentArea::OnlineDocument> &views) const
{
    Wanted wanted;
    QSet<QString> seen;
    const auto addName = [&](const QString &name) {
        const QString key = name.toUpper();
        if (seen.contains(key))
            return;
        seen.insert(key);
        wanted.names.append(name);
    };
    for (const QString &name : m_watch.model().names())
        addName(name);
    for (const DocumentArea::OnlineDocument &document : views) {
        for (const QString &name : document.view->onlineNames())
            addName(name);
        // Chart editors get their chart through chartState (the SFC engine's view of the instance).
        const QString instance = document.view->onlineInstance();
        if (!document.view->wantsChartState() || instance.isEmpty())
            continue;
        if (document.body.part == model::BodyRef::Part::Pou)
            wanted.charts.push_back({instance, document.body.pou, {}});
        else if (document.body.part == model::BodyRef::Part::Action) // a chart in an action
            wanted.charts.push_back({instance, document.body.pou, document.body.name});
    }
    return wanted;
}

WatchRequest OnlineController::requestFor(const Wanted &wanted) const
{
    WatchRequest request;
    request.names = wanted.names;
    const model::Project &project = m_projectModel.project();
    for (const Wanted::Chart &chart : wanted.charts) {
        if (const model::Pou *pou = project.findPou(chart.pou))
            request.charts.push_back({chart.instance, *pou, chart.action});
    }
    return request;
}

void OnlineController::updateWatchRequest()
{
    if (isOnline())
        updateWatchRequestFor(m_documents.onlineViews());
}

void OnlineController::updateWatchRequestFor(const QList<DocumentArea::OnlineDocument> &views)
{
    if (!isOnline())
        return;
    Wanted now = wanted(views);
    if (now == m_sent)
        return;
    m_sent = std::move(now);
    send([request = requestFor(m_sent)](RuntimeWorker &worker) { worker.setWatch(request); });
}

void OnlineController::showSnapshot(std::shared_ptr<const interp::RuntimeSnapshot> snapshot)
{
    m_latest = std::move(snapshot);
    m_running = m_latest->running;
    const QList<DocumentArea::OnlineDocument> views = m_documents.onlineViews();
    updateWatchRequestFor(views); // a document opened or closed since the last one
    for (const DocumentArea::OnlineDocument &document : views)
        document.view->setOnlineSnapshot(m_latest.get());
    m_watch.setSnapshot(m_latest.get());
    updateStatus();
    updateActions();
    Q_EMIT snapshotShown(m_latest);
}

void OnlineController::showFault(const interp::RuntimeFault &fault)
{
    m_running = false;
    Message message;
    message.severity = Message::Severity::Error;
    message.text = tr("Runtime fault in cycle %1: %2 The program stopped; Reset starts it again.")
                       .arg(fault.cycle)
                       .arg(fault.message);
    message.pouName = fault.pou;
    message.line = fault.line;
    m_messages.model().setMessages(kRuntimeSource, {message});
    showDockOf(m_messages);
    m_statusBar.showMessage(tr("The program stopped: %1").arg(fault.toString()));
    updateActions();
    Q_EMIT faultShown(fault);
}

void OnlineController::updateActions()
{
    const bool online = isOnline();
    m_windowActions.login->setEnabled(!online || !m_running);
    m_windowActions.stop->setEnabled(online && m_running);
    m_windowActions.singleCycle->setEnabled(true);
    m_logoutAction->setEnabled(online);
    m_runCyclesAction->setEnabled(!online || !m_running);
    m_resetWarmAction->setEnabled(online);
    m_resetColdAction->setEnabled(online);
}

void OnlineController::updateStatus()
{
    if (!isOnline()) {
        m_statusLabel->setText(tr("Offline"));
        m_statusLabel->setStyleSheet(QString());
        return;
    }
    const QString speed = m_speed == RunSpeed::RealTime ? tr("real time")
        : m_speed == RunSpeed::Times10                  ? tr("10x")
                                                        : tr("full speed");
    const std::int64_t cycleNs = m_latest ? m_latest->cycleNs : m_cycleNs;
    if (m_latest && m_latest->historyCycle) {
        m_statusLabel->setText(tr("ONLINE HISTORY | scan %1 of %2 | t = %3 s")
                                   .arg(*m_latest->historyCycle)
                                   .arg(m_latest->presentCycle)
                                   .arg(formatSeconds(m_latest->timeNs)));
        m_statusLabel->setStyleSheet(QStringLiteral("color: #7a4a00; background: #ffecb3; font-weight: bold;"));
        return;
    }
    QString state = m_latest && m_latest->fault ? tr("FAULT")
        : m_latest && m_latest->halt             ? tr("HALT")
        : m_running                              ? tr("RUN")
                                                 : tr("STOP");
    QString text = tr("ONLINE %1 | cycle %2 | t = %3 s | %4 ms, %5")
                       .arg(state)
                       .arg(m_latest ? m_latest->cycle : 0)
                       .arg(formatSeconds(m_latest ? m_latest->timeNs : 0))
                       .arg(double(cycleNs) / 1e6)
                       .arg(speed);
    if (m_latest && m_latest->modelRevision != m_projectModel.revision())
        text += tr(" | changed since login");
    m_statusLabel->setText(text);
    m_statusLabel->setStyleSheet(m_latest && m_latest->fault  ? QStringLiteral("color: #b00000; font-weight: bold;")
                                     : m_latest && m_latest->halt ? QStringLiteral("color: #8a6d00; font-weight: bold;")
                                                                  : QStringLiteral("color: #0b4fa0; font-weight: bold;"));
}

} // namespace iec::app
