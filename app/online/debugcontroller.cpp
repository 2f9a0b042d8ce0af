#include "app/online/debugcontroller.h"

#include "app/online/onlinecontroller.h"
#include "model/projectmodel.h"

#include <QAction>
#include <QMenu>
#include <QStatusBar>
#include <QToolBar>

namespace iec::app {

DebugController::DebugController(model::ProjectModel &projectModel, DocumentArea &documents, OnlineController &online,
                                 QStatusBar &statusBar, QObject *parent)
    : QObject(parent)
    , m_projectModel(projectModel)
    , m_documents(documents)
    , m_online(online)
    , m_statusBar(statusBar)
{
    m_toggle = new QAction(this);
    m_toggle->setShortcut(QKeySequence(Qt::Key_F9));
    connect(m_toggle, &QAction::triggered, this, &DebugController::toggleBreakpointAtCursor);
    m_removeAll = new QAction(this);
    connect(m_removeAll, &QAction::triggered, this, &DebugController::removeAllBreakpoints);
    m_stepOver = new QAction(this);
    m_stepOver->setShortcut(QKeySequence(Qt::Key_F10));
    connect(m_stepOver, &QAction::triggered, this, [this] { m_online.resume(interp::ResumeKind::StepOver); });
    m_stepInto = new QAction(this);
    m_stepInto->setShortcut(QKeySequence(Qt::Key_F8));
    connect(m_stepInto, &QAction::triggered, this, [this] { m_online.resume(interp::ResumeKind::StepInto); });
    m_stepOut = new QAction(this);
    m_stepOut->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F10));
    connect(m_stepOut, &QAction::triggered, this, [this] { m_online.resume(interp::ResumeKind::StepOut); });

    connect(&m_online, &OnlineController::onlineChanged, this, [this](bool online) {
        if (online)
            sendBreakpoints();
        else
            m_halt.reset();
        refreshMarks();
        updateActions();
    });
    connect(&m_online, &OnlineController::snapshotShown, this,
            [this](std::shared_ptr<const interp::RuntimeSnapshot> snapshot) { showHalt(*snapshot); });
    // Editors opened later show the marks too.
    connect(&m_documents, &QTabWidget::currentChanged, this, &DebugController::refreshMarks);
    // A body that is gone takes its breakpoints with it.
    connect(&m_projectModel, &model::ProjectModel::projectReset, this, [this] {
        m_breakpoints.clear();
        Q_EMIT breakpointsChanged();
    });
    retranslate();
    updateActions();
}

void DebugController::addTo(QMenu *menu, QToolBar *toolBar)
{
    menu->addSeparator();
    menu->addAction(m_toggle);
    menu->addAction(m_removeAll);
    menu->addAction(m_stepOver);
    menu->addAction(m_stepInto);
    menu->addAction(m_stepOut);
    if (toolBar) {
        toolBar->addAction(m_stepOver);
        toolBar->addAction(m_stepInto);
        toolBar->addAction(m_stepOut);
    }
}

void DebugController::retranslate()
{
    m_toggle->setText(tr("Toggle &Breakpoint"));
    m_removeAll->setText(tr("Remove All Breakpoints"));
    m_stepOver->setText(tr("Step &Over"));
    m_stepInto->setText(tr("Step &Into"));
    m_stepOut->setText(tr("Step O&ut"));
}

void DebugController::updateActions()
{
    const bool running = m_online.isRunning();
    m_stepOver->setEnabled(!running);
    m_stepInto->setEnabled(!running);
    // Only while halted: Shift+F10 is also the keyboard's context menu key elsewhere.
    m_stepOut->setEnabled(m_halt.has_value());
    m_removeAll->setEnabled(!m_breakpoints.empty());
}

void DebugController::toggleBreakpointAtCursor()
{
    const std::optional<model::BodyRef> body = m_documents.currentBody();
    if (!body)
        return;
    for (const DocumentArea::OnlineDocument &document : m_documents.onlineViews()) {
        if (!(document.body == *body))
            continue;
        if (const std::optional<editors::OnlineView::Place> place = document.view->breakpointPlace()) {
            toggleBreakpoint(*body, *place);
            return;
        }
    }
    m_statusBar.showMessage(tr("A breakpoint goes on a line of an ST or IL body."), 8000);
}

void DebugController::toggleBreakpoint(const model::BodyRef &body, const editors::OnlineView::Place &place)
{
    if (body.part == model::BodyRef::Part::Transition) {
        m_statusBar.showMessage(tr("Breakpoints in transitions are not supported; put one on the step before it."), 8000);
        return;
    }
    const auto same = [&](const StoredBreakpoint &b) { return b.body == body && b.place == place; };
    if (std::erase_if(m_breakpoints, same) == 0)
        m_breakpoints.push_back({body, place, {}});
    sendBreakpoints();
    refreshMarks();
    updateActions();
    Q_EMIT breakpointsChanged();
}

void DebugController::removeAllBreakpoints()
{
    m_breakpoints.clear();
    sendBreakpoints();
    refreshMarks();
    updateActions();
    Q_EMIT breakpointsChanged();
}

// The name the compiled module gives a body: the POU's, or "Pou.Action".
QString DebugController::ownerName(const model::BodyRef &body) const
{
    const model::Pou *pou = m_projectModel.project().findPou(body.pou);
    if (!pou)
        return {};
    return body.part == model::BodyRef::Part::Action ? pou->name + QLatin1Char('.') + body.name : pou->name;
}

std::optional<model::BodyRef> DebugController::bodyOfOwner(const QString &owner) const
{
    for (const model::Pou &pou : m_projectModel.project().types.pous) {
        if (pou.name.compare(owner, Qt::CaseInsensitive) == 0)
            return model::BodyRef{pou.id, model::BodyRef::Part::Pou, {}};
        for (const model::PouAction &action : pou.actions)
            if (QString(pou.name + QLatin1Char('.') + action.name).compare(owner, Qt::CaseInsensitive) == 0)
                return model::BodyRef{pou.id, model::BodyRef::Part::Action, action.name};
    }
    return std::nullopt;
}

void DebugController::sendBreakpoints()
{
    if (!m_online.isOnline())
        return;
    std::vector<interp::Breakpoint> breakpoints;
    for (const StoredBreakpoint &stored : m_breakpoints) {
        interp::Breakpoint b = stored.settings;
        b.at = {ownerName(stored.body), stored.place.line, stored.place.localId};
        breakpoints.push_back(std::move(b));
    }
    m_online.setBreakpoints(breakpoints);
}

void DebugController::refreshMarks()
{
    const std::optional<model::BodyRef> haltedBody = m_halt ? bodyOfOwner(m_halt->at.pou) : std::nullopt;
    for (const DocumentArea::OnlineDocument &document : m_documents.onlineViews()) {
        std::vector<editors::OnlineView::Place> places;
        for (const StoredBreakpoint &stored : m_breakpoints)
            if (stored.body == document.body)
                places.push_back(stored.place);
        std::optional<editors::OnlineView::Place> halted;
        if (haltedBody && *haltedBody == document.body)
            halted = editors::OnlineView::Place{m_halt->at.line, m_halt->at.localId};
        document.view->setBreakpointMarks(places, halted);
        const model::BodyRef body = document.body;
        document.view->setBreakpointToggle([this, body](const editors::OnlineView::Place &place) { toggleBreakpoint(body, place); });
    }
}

void DebugController::showHalt(const interp::RuntimeSnapshot &snapshot)
{
    const bool changed = snapshot.halt.has_value() != m_halt.has_value()
        || (snapshot.halt && (snapshot.halt->at != m_halt->at || snapshot.halt->cycle != m_halt->cycle
                              || snapshot.halt->hits != m_halt->hits));
    m_halt = snapshot.halt;
    updateActions();
    if (!changed)
        return;
    if (m_halt) {
        // The body it halted in comes to the front, opened if need be.
        if (const std::optional<model::BodyRef> body = bodyOfOwner(m_halt->at.pou))
            m_documents.openBody(*body);
        const QString place = m_halt->at.localId >= 0 ? tr("element %1").arg(m_halt->at.localId)
                                                      : tr("line %1").arg(m_halt->at.line);
        QString message = tr("Halted in %1 at %2 (cycle %3). F5 continues, F10 steps over, F8 steps into, Shift+F10 steps out.")
                              .arg(m_halt->at.pou, place)
                              .arg(m_halt->cycle);
        if (!m_halt->conditionProblem.isEmpty())
            message += QLatin1Char(' ') + tr("The breakpoint's condition could not be checked: %1").arg(m_halt->conditionProblem);
        m_statusBar.showMessage(message);
    }
    refreshMarks();
}

} // namespace iec::app
