#include "app/livediagnostics.h"

#include "app/buildcontroller.h"
#include "interpreter/frontend/projectsource.h"
#include "model/projectmodel.h"

#include <QPointer>

namespace iec::app {

struct LiveDiagnostics::Result {
    quint64 revision = 0;
    QList<Message> messages;
    qint64 milliseconds = 0;
};

LiveDiagnostics::LiveDiagnostics(model::ProjectModel &model, BuildController &build, QObject *parent)
    : QObject(parent)
    , m_model(model)
    , m_build(build)
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(250);
    connect(&m_timer, &QTimer::timeout, this, &LiveDiagnostics::compileNow);
    // One worker: compiles are queued behind each other, never in parallel with themselves.
    m_pool.setMaxThreadCount(1);
    // Every change the compiler can see.
    const auto changed = [this] { schedule(); };
    connect(&model, &model::ProjectModel::projectReset, this, changed);
    connect(&model, &model::ProjectModel::pouAdded, this, changed);
    connect(&model, &model::ProjectModel::pouRemoved, this, changed);
    connect(&model, &model::ProjectModel::pouRenamed, this, changed);
    connect(&model, &model::ProjectModel::pouPartsChanged, this, changed);
    connect(&model, &model::ProjectModel::dataTypesChanged, this, changed);
    connect(&model, &model::ProjectModel::instancesChanged, this, changed);
    connect(&model, &model::ProjectModel::variablesChanged, this, changed);
    connect(&model, &model::ProjectModel::pouAddDataChanged, this, changed);
    connect(&model, &model::ProjectModel::bodyTextChanged, this, changed);
    connect(&model, &model::ProjectModel::elementsInserted, this, changed);
    connect(&model, &model::ProjectModel::elementsRemoved, this, changed);
    connect(&model, &model::ProjectModel::elementsChanged, this, changed);
    connect(&model, &model::ProjectModel::connectionsChanged, this, changed);
}

LiveDiagnostics::~LiveDiagnostics()
{
    // A compile still running posts its result to this object: it must end first.
    m_pool.waitForDone();
}

void LiveDiagnostics::setEnabled(bool enabled)
{
    m_enabled = enabled;
    if (!enabled)
        m_timer.stop();
}

void LiveDiagnostics::schedule()
{
    if (m_enabled)
        m_timer.start();
}

void LiveDiagnostics::compileNow()
{
    m_timer.stop();
    if (m_running) {
        m_again = true; // after the running one, with what the model holds then
        return;
    }
    m_running = true;
    m_again = false;
    QElapsedTimer snapshotClock;
    snapshotClock.start();
    // A copy: the worker reads it while the user goes on editing the model.
    auto project = std::make_shared<const model::Project>(m_model.project());
    const quint64 revision = m_model.revision();
    m_lastSnapshotMs = snapshotClock.elapsed();
    m_pool.start([this, project, revision] {
        QElapsedTimer clock;
        clock.start();
        auto result = std::make_shared<Result>();
        result->revision = revision;
        interp::Diagnostics diagnostics;
        interp::frontend::compileProject(*project, diagnostics);
        result->messages = messagesOf(diagnostics);
        result->milliseconds = clock.elapsed();
        QMetaObject::invokeMethod(this, [this, result] { finish(result); }, Qt::QueuedConnection);
    });
}

void LiveDiagnostics::finish(const std::shared_ptr<Result> &result)
{
    m_running = false;
    m_lastCompileMs = result->milliseconds;
    if (result->revision == m_model.revision() && m_enabled) {
        m_build.publish(result->messages);
        int errors = 0;
        int warnings = 0;
        for (const Message &message : std::as_const(result->messages)) {
            errors += message.severity == Message::Severity::Error ? 1 : 0;
            warnings += message.severity == Message::Severity::Warning ? 1 : 0;
        }
        Q_EMIT published(result->revision, errors, warnings);
    } else {
        // The model moved on; its change restarted the pause, after which it is compiled.
        Q_EMIT discarded(result->revision);
    }
    if (m_again)
        compileNow();
}

} // namespace iec::app
