#include "app/online/debugcontroller.h"

#include "app/online/breakpointdialog.h"
#include "app/online/breakpointlines.h"
#include "app/messagespane.h"
#include "app/online/onlinecontroller.h"
#include "model/projectmodel.h"
#include "model/savedbreakpoints.h"

#include <QAction>

#include <algorithm>
#include <QMenu>
#include <QStatusBar>
#include <QToolBar>

namespace iec::app {

DebugController::DebugController(model::ProjectModel &projectModel, DocumentArea &documents, OnlineController &online,
                                 MessagesPane &messages, QStatusBar &statusBar, QObject *parent)
    : QObject(parent)
    , m_projectModel(projectModel)
    , m_documents(documents)
    , m_online(online)
    , m_messages(messages)
    , m_statusBar(statusBar)
{
    m_toggle = new QAction(this);
    m_toggle->setShortcut(QKeySequence(Qt::Key_F9));
    connect(m_toggle, &QAction::triggered, this, &DebugController::toggleBreakpointAtCursor);
    m_properties = new QAction(this);
    connect(m_properties, &QAction::triggered, this, &DebugController::editBreakpointAtCursor);
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

    m_runToCursor = new QAction(this);
    m_runToCursor->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F10));
    connect(m_runToCursor, &QAction::triggered, this, &DebugController::runToCursor);

    connect(&m_online, &OnlineController::onlineChanged, this, [this](bool online) {
        if (online) {
            sendBreakpoints();
        } else {
            m_halt.reset();
            m_cursorTarget.reset();
            listCallStack();
        }
        refreshMarks();
        updateActions();
    });
    connect(&m_online, &OnlineController::snapshotShown, this,
            [this](std::shared_ptr<const interp::RuntimeSnapshot> snapshot) { showHalt(*snapshot); });
    // Editors opened later show the marks too.
    connect(&m_documents, &QTabWidget::currentChanged, this, &DebugController::refreshMarks);
    // Another project: its own breakpoints, as it saved them.
    connect(&m_projectModel, &model::ProjectModel::projectReset, this, &DebugController::loadFromProject);
    connect(&m_projectModel, &model::ProjectModel::bodyTextChanged, this, &DebugController::followTextEdit);
    retranslate();
    updateActions();
}

void DebugController::addTo(QMenu *menu, QToolBar *toolBar)
{
    menu->addSeparator();
    menu->addAction(m_toggle);
    menu->addAction(m_properties);
    menu->addAction(m_removeAll);
    menu->addAction(m_stepOver);
    menu->addAction(m_stepInto);
    menu->addAction(m_stepOut);
    menu->addAction(m_runToCursor);
    if (toolBar) {
        toolBar->addAction(m_stepOver);
        toolBar->addAction(m_stepInto);
        toolBar->addAction(m_stepOut);
    }
}

void DebugController::retranslate()
{
    m_toggle->setText(tr("Toggle &Breakpoint"));
    m_properties->setText(tr("Breakpoint &Properties..."));
    m_removeAll->setText(tr("Remove All Breakpoints"));
    m_stepOver->setText(tr("Step &Over"));
    m_stepInto->setText(tr("Step &Into"));
    m_stepOut->setText(tr("Step O&ut"));
    m_runToCursor->setText(tr("Run to &Cursor"));
}

void DebugController::updateActions()
{
    const bool running = m_online.isRunning();
    m_stepOver->setEnabled(!running);
    m_stepInto->setEnabled(!running);
    m_runToCursor->setEnabled(!running);
    // Only while halted: Shift+F10 is also the keyboard's context menu key elsewhere.
    m_stepOut->setEnabled(m_halt.has_value());
    m_removeAll->setEnabled(!m_breakpoints.empty());
}

std::optional<std::pair<model::BodyRef, editors::OnlineView::Place>> DebugController::placeAtCursor() const
{
    const std::optional<model::BodyRef> body = m_documents.currentBody();
    if (!body)
        return std::nullopt;
    for (const DocumentArea::OnlineDocument &document : m_documents.onlineViews())
        if (document.body == *body)
            if (const std::optional<editors::OnlineView::Place> place = document.view->breakpointPlace())
                return std::pair{*body, *place};
    return std::nullopt;
}

void DebugController::editBreakpointAtCursor()
{
    const auto at = placeAtCursor();
    if (!at) {
        toggleBreakpointAtCursor(); // says where a breakpoint can go
        return;
    }
    interp::Breakpoint settings;
    for (const StoredBreakpoint &stored : m_breakpoints)
        if (stored.body == at->first && stored.place == at->second)
            settings = stored.settings;
    const QString place = at->second.localId >= 0 ? tr("%1, element %2").arg(ownerName(at->first)).arg(at->second.localId)
                                                  : tr("%1, line %2").arg(ownerName(at->first)).arg(at->second.line);
    BreakpointDialog dialog(place, settings, m_documents.window());
    if (dialog.exec() == QDialog::Accepted)
        setBreakpointSettings(at->first, at->second, dialog.settings());
}

void DebugController::setBreakpointSettings(const model::BodyRef &body, const editors::OnlineView::Place &place,
                                            const interp::Breakpoint &settings)
{
    auto stored = std::ranges::find_if(m_breakpoints, [&](const StoredBreakpoint &b) { return b.body == body && b.place == place; });
    if (stored == m_breakpoints.end())
        stored = m_breakpoints.insert(m_breakpoints.end(), {body, place, {}});
    stored->settings = settings;
    breakpointsEdited();
}

void DebugController::runToCursor()
{
    const auto at = placeAtCursor();
    if (!at) {
        toggleBreakpointAtCursor(); // says where the cursor must be
        return;
    }
    m_cursorTarget = StoredBreakpoint{at->first, at->second, {}};
    sendBreakpoints();
    m_online.loginAndRun();
}

void DebugController::toggleBreakpointAtCursor()
{
    if (const auto at = placeAtCursor()) {
        toggleBreakpoint(at->first, at->second);
        return;
    }
    m_statusBar.showMessage(tr("A breakpoint goes on a line of an ST or IL body, a network of an LD or FBD body, or a step "
                               "or transition of a chart: put the cursor there first."),
                            8000);
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
    breakpointsEdited();
}

// After any change of the breakpoints: the runtime, the marks and the actions follow.
void DebugController::breakpointsEdited()
{
    rememberTexts();
    sendBreakpoints();
    refreshMarks();
    updateActions();
    Q_EMIT breakpointsChanged();
}

void DebugController::rememberTexts()
{
    std::vector<std::pair<model::BodyRef, QString>> texts;
    for (const StoredBreakpoint &breakpoint : m_breakpoints) {
        const model::Body *body = m_projectModel.body(breakpoint.body);
        const bool known = std::any_of(texts.begin(), texts.end(), [&](const auto &t) { return t.first == breakpoint.body; });
        if (breakpoint.place.line > 0 && body && !body->isGraphical() && !known)
            texts.emplace_back(breakpoint.body, body->text());
    }
    m_textsUnderBreakpoints = std::move(texts);
}

void DebugController::followTextEdit(const model::BodyRef &body)
{
    const auto known = std::find_if(m_textsUnderBreakpoints.begin(), m_textsUnderBreakpoints.end(),
        [&](const auto &t) { return t.first == body; });
    const model::Body *now = m_projectModel.body(body);
    if (known == m_textsUnderBreakpoints.end() || !now || now->isGraphical())
        return;
    const QStringList before = known->second.split(QLatin1Char('\n'));
    const QStringList after = now->text().split(QLatin1Char('\n'));
    bool moved = false;
    for (auto it = m_breakpoints.begin(); it != m_breakpoints.end();) {
        const int line = it->body == body ? it->place.line : 0;
        const int followed = line > 0 ? lineAfterEdit(line, before, after) : line;
        moved = moved || followed != line;
        const bool takenTwice = followed > 0 && std::any_of(m_breakpoints.begin(), it, [&](const StoredBreakpoint &b) {
            return b.body == body && b.place.line == followed;
        });
        if (line > 0 && (followed == 0 || takenTwice)) { // its line was deleted, or joined another's
            it = m_breakpoints.erase(it);
            continue;
        }
        it->place.line = followed;
        ++it;
    }
    known->second = now->text();
    if (moved)
        breakpointsEdited();
}

void DebugController::removeAllBreakpoints()
{
    m_breakpoints.clear();
    breakpointsEdited();
}

// The name the compiled module gives a body, which is its tab's title: Main, or Main.Reset.
QString DebugController::ownerName(const model::BodyRef &body) const
{
    return DocumentArea::title(m_projectModel.project(), body);
}

std::optional<model::BodyRef> DebugController::bodyOfOwner(const QString &owner) const
{
    const model::Project &project = m_projectModel.project();
    for (const model::Pou &pou : project.types.pous) {
        std::vector<model::BodyRef> bodies{{pou.id, model::BodyRef::Part::Pou, {}}};
        for (const model::PouAction &action : pou.actions)
            bodies.push_back({pou.id, model::BodyRef::Part::Action, action.name});
        for (const model::BodyRef &body : bodies)
            if (DocumentArea::title(project, body).compare(owner, Qt::CaseInsensitive) == 0)
                return body;
    }
    return std::nullopt;
}

void DebugController::loadFromProject()
{
    m_breakpoints.clear();
    for (const model::SavedBreakpoint &saved : model::savedBreakpoints(m_projectModel.project())) {
        const QString owner = saved.action.isEmpty() ? saved.pou : saved.pou + QLatin1Char('.') + saved.action;
        const std::optional<model::BodyRef> body = bodyOfOwner(owner);
        if (!body)
            continue;
        StoredBreakpoint stored{*body, {saved.line, saved.localId, saved.elements}, {}};
        stored.settings.hitRule = interp::HitRule(saved.hitRule);
        stored.settings.hitTarget = saved.hitTarget;
        stored.settings.condition = saved.condition;
        stored.settings.enabled = saved.enabled;
        m_breakpoints.push_back(std::move(stored));
    }
    m_halt.reset();
    breakpointsEdited();
}

model::Project DebugController::projectToSave() const
{
    model::Project project = m_projectModel.project();
    std::vector<model::SavedBreakpoint> saved;
    for (const StoredBreakpoint &stored : m_breakpoints) {
        const model::Pou *pou = project.findPou(stored.body.pou);
        if (!pou)
            continue;
        model::SavedBreakpoint b;
        b.pou = pou->name;
        if (stored.body.part == model::BodyRef::Part::Action)
            b.action = stored.body.name;
        b.line = stored.place.line;
        b.localId = stored.place.localId;
        b.elements = stored.place.elements;
        b.hitRule = int(stored.settings.hitRule);
        b.hitTarget = stored.settings.hitTarget;
        b.condition = stored.settings.condition;
        b.enabled = stored.settings.enabled;
        saved.push_back(std::move(b));
    }
    model::setSavedBreakpoints(project, saved);
    return project;
}

void DebugController::sendBreakpoints()
{
    if (!m_online.isOnline())
        return;
    std::vector<interp::Breakpoint> breakpoints;
    const auto add = [&](const StoredBreakpoint &stored) {
        interp::Breakpoint b = stored.settings;
        b.at = {ownerName(stored.body), stored.place.line, stored.place.localId, stored.place.elements};
        breakpoints.push_back(std::move(b));
    };
    for (const StoredBreakpoint &stored : m_breakpoints)
        add(stored);
    if (m_cursorTarget)
        add(*m_cursorTarget);
    m_online.setBreakpoints(breakpoints);
}

void DebugController::refreshMarks()
{
    const std::optional<model::BodyRef> haltedBody = m_halt ? bodyOfOwner(m_halt->at.pou) : std::nullopt;
    for (const DocumentArea::OnlineDocument &document : m_documents.onlineViews()) {
        std::vector<editors::OnlineView::Place> places;
        for (const StoredBreakpoint &stored : m_breakpoints)
            if (stored.body == document.body)
            {
                editors::OnlineView::Place place = stored.place;
                place.enabled = stored.settings.enabled;
                places.push_back(std::move(place));
            }
        std::optional<editors::OnlineView::Place> halted;
        if (haltedBody && *haltedBody == document.body)
            halted = editors::OnlineView::Place{m_halt->at.line, m_halt->at.localId};
        document.view->setBreakpointMarks(places, halted);
        const model::BodyRef body = document.body;
        document.view->setBreakpointToggle([this, body](const editors::OnlineView::Place &place) { toggleBreakpoint(body, place); });
    }
}

// Innermost first, as debuggers list it; each entry opens its place.
void DebugController::listCallStack()
{
    QList<Message> list;
    if (m_halt) {
        for (auto frame = m_halt->stack.rbegin(); frame != m_halt->stack.rend(); ++frame) {
            const QString where = frame->localId >= 0 ? tr("element %1").arg(frame->localId) : tr("line %1").arg(frame->line);
            const QString body = frame->instance.isEmpty() || frame->instance.compare(frame->pou, Qt::CaseInsensitive) == 0
                ? frame->pou
                : tr("%1 (instance %2)").arg(frame->pou, frame->instance);
            Message message;
            message.severity = Message::Severity::Info;
            message.text = frame == m_halt->stack.rbegin() ? tr("Halted in %1 at %2 (cycle %3).").arg(body, where).arg(m_halt->cycle)
                                                            : tr("Called from %1 at %2.").arg(body, where);
            message.pouName = frame->pou;
            message.line = frame->line;
            if (frame->localId >= 0)
                message.localId = quint64(frame->localId);
            list.append(message);
        }
    }
    m_messages.model().setMessages(QStringLiteral("debugger"), list);
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
    if (!m_halt && !m_haltMessage.isEmpty() && m_statusBar.currentMessage() == m_haltMessage)
        m_statusBar.clearMessage(); // it went on: "Halted in …" is no longer true
    if (m_halt && m_cursorTarget) {
        m_cursorTarget.reset(); // reached, or another breakpoint came first: Run to Cursor is over
        sendBreakpoints();
    }
    listCallStack();
    if (m_halt) {
        // The body it halted in comes to the front, opened if need be.
        QString place = m_halt->at.localId >= 0 ? tr("element %1").arg(m_halt->at.localId) : tr("line %1").arg(m_halt->at.line);
        if (const std::optional<model::BodyRef> body = bodyOfOwner(m_halt->at.pou)) {
            m_documents.openBody(*body);
            for (const DocumentArea::OnlineDocument &document : m_documents.onlineViews())
                if (document.body == *body && m_halt->at.localId >= 0)
                    if (const QString name = document.view->placeName(m_halt->at.localId); !name.isEmpty())
                        place = name;
        }
        QString message = tr("Halted in %1 at %2 (cycle %3). F5 continues, F10 steps over, F8 steps into, Shift+F10 steps out.")
                              .arg(m_halt->at.pou, place)
                              .arg(m_halt->cycle);
        if (!m_halt->conditionProblem.isEmpty())
            message += QLatin1Char(' ') + tr("The breakpoint's condition could not be checked: %1").arg(m_halt->conditionProblem);
        m_statusBar.showMessage(message);
        m_haltMessage = message;
    }
    refreshMarks();
}

} // namespace iec::app
