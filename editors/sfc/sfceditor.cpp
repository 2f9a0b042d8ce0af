#include "editors/sfc/sfceditor.h"

#include "editors/common/diagramexport.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/sfc/sfcdialogs.h"
#include "editors/sfc/sfcgeometry.h"
#include "editors/sfc/sfcitems.h"
#include "editors/sfc/sfclayout.h"
#include "editors/sfc/sfcplacement.h"
#include "interpreter/runtime/snapshot.h"
#include "model/body.h"
#include "model/projectmodel.h"
#include "model/undo/partcommands.h"
#include "model/undo/sfccommands.h"

#include <QAction>
#include <QContextMenuEvent>
#include <QFileDialog>
#include <QInputDialog>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPrintDialog>
#include <QPrinter>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>

namespace iec::editors::sfc {

using namespace model;

namespace {

// The chart clipboard: fragments keep their element values, which the text clipboard cannot.
std::optional<Fragment> &chartClipboard()
{
    static std::optional<Fragment> fragment;
    return fragment;
}

QString formatElapsed(std::int64_t ns)
{
    qint64 ms = ns / 1000000;
    const qint64 h = ms / 3600000;
    ms %= 3600000;
    const qint64 m = ms / 60000;
    ms %= 60000;
    const qint64 s = ms / 1000;
    ms %= 1000;
    QString text = QStringLiteral("T#");
    if (h)
        text += QString::number(h) + QStringLiteral("h");
    if (m)
        text += QString::number(m) + QStringLiteral("m");
    if (s || (!h && !m && !ms))
        text += QString::number(s) + QStringLiteral("s");
    if (ms)
        text += QString::number(ms) + QStringLiteral("ms");
    return text;
}

QStringList partNames(const ProjectModel &model, PouId pou, bool actions)
{
    QStringList names;
    if (const Pou *p = model.project().findPou(pou)) {
        for (const PouPart &part : actions ? p->actions : p->transitions)
            names << part.name;
    }
    return names;
}

} // namespace

SfcEditor::SfcEditor(ProjectModel &model, BodyRef ref, QUndoStack *undoStack, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_ref(std::move(ref))
    , m_undoStack(undoStack ? undoStack : new QUndoStack(this))
{
    m_scene = new DiagramScene(model, m_ref, m_policy, this);
    m_view = new DiagramView;
    m_view->setScene(m_scene);
    m_view->setGridSize(10);
    m_view->setBackgroundBrush(Qt::white);
    m_view->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_view->installEventFilter(this);
    m_view->viewport()->installEventFilter(this);
    m_toolBar = new QToolBar;
    m_toolBar->setIconSize(QSize(16, 16));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_levelLabel = new QLabel;
    m_messageLabel = new QLabel;
    m_messageLabel->setWordWrap(true);
    m_messageLabel->setStyleSheet(QStringLiteral("color: #a03000;"));
    m_messageLabel->hide();
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(m_toolBar);
    layout->addWidget(m_levelLabel);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_messageLabel);
    createActions();
    connect(m_scene, &DiagramScene::elementDoubleClicked, this, &SfcEditor::onDoubleClicked);
    connect(m_scene, &DiagramScene::elementShiftClicked, this, &SfcEditor::onShiftClicked);
    connect(m_scene, &DiagramScene::rebuilt, this, &SfcEditor::applyOnlineState);
    connect(m_scene, &QGraphicsScene::selectionChanged, this, [this] {
        const QList<quint64> ids = selection();
        if (ids.size() == 1)
            m_shiftAnchor = ids.front();
    });
    m_scene->rebuild();
    updateLevelLabel();
    if (const Pou *pou = model.project().findPou(m_ref.pou))
        m_onlineInstance = pou->kind == PouKind::Program ? pou->name : QString();
}

SfcEditor::~SfcEditor()
{
    // The scene is a child: QWidget's destructor deletes it after this object stopped being an
    // SfcEditor, and its items' removal emits selectionChanged into our slots.
    m_scene->disconnect(this);
}

// ---- actions

void SfcEditor::createActions()
{
    struct Entry {
        const char *name;
        const char *text;
        const char *shortcut;
        std::function<void()> run;
        bool insert;
    };
    const Entry entries[] = {
        {"sfcStepAfter", QT_TR_NOOP("Step-Transition (after)"), "Ctrl+T", [this] { insertStepTransitionAfter(); }, true},
        {"sfcStepBefore", QT_TR_NOOP("Step-Transition (before)"), "Ctrl+Shift+T", [this] { insertStepTransitionBefore(); }, true},
        {"sfcAltRight", QT_TR_NOOP("Alternative Branch (right)"), "Ctrl+A", [this] { insertAlternativeBranch(true); }, true},
        {"sfcAltLeft", QT_TR_NOOP("Alternative Branch (left)"), "", [this] { insertAlternativeBranch(false); }, true},
        {"sfcParRight", QT_TR_NOOP("Parallel Branch (right)"), "Ctrl+L", [this] { insertParallelBranch(true); }, true},
        {"sfcParLeft", QT_TR_NOOP("Parallel Branch (left)"), "", [this] { insertParallelBranch(false); }, true},
        {"sfcJump", QT_TR_NOOP("Jump…"), "", [this] { chooseJumpTarget(false); }, true},
        {"sfcTransitionJump", QT_TR_NOOP("Transition-Jump…"), "", [this] { chooseJumpTarget(true); }, true},
        {"sfcMacro", QT_TR_NOOP("Macro Step"), "", [this] { insertMacroStep(); }, true},
        {"sfcDelete", QT_TR_NOOP("Delete"), "Del", [this] { deleteSelection(); }, false},
        {"sfcCut", QT_TR_NOOP("Cut"), "Ctrl+X", [this] { cutSelection(); }, false},
        {"sfcCopy", QT_TR_NOOP("Copy"), "Ctrl+C", [this] { copySelection(); }, false},
        {"sfcPaste", QT_TR_NOOP("Paste"), "Ctrl+V", [this] { paste(); }, false},
        {"sfcProperties", QT_TR_NOOP("Step Properties…"), "", [this] {
             if (const quint64 id = selectedOfKind(true))
                 editStepDialog(id);
             else
                 showMessage(tr("Select a step first."));
         }, false},
        {"sfcActions", QT_TR_NOOP("IEC Actions…"), "", [this] {
             if (const quint64 id = selectedOfKind(true))
                 editActionsDialog(id);
             else
                 showMessage(tr("Select a step first."));
         }, false},
        {"sfcCondition", QT_TR_NOOP("Edit Condition"), "", [this] {
             if (const quint64 id = selectedOfKind(false))
                 editConditionInPlace(id);
             else
                 showMessage(tr("Select a transition first."));
         }, false},
        {"sfcPriority", QT_TR_NOOP("Transition Priority…"), "", [this] {
             const quint64 id = selectedOfKind(false);
             if (!id) {
                 showMessage(tr("Select a transition first."));
                 return;
             }
             const ChartDocument doc = document();
             const auto &current = std::get<Transition>(*doc.element(id)).priority;
             bool ok = false;
             // 0 removes the priority: alternative branches are then tried from left to right.
             const int value = QInputDialog::getInt(this, tr("Transition Priority"),
                 tr("Priority (0: none, branches are tried from left to right):"), int(current.value_or(0)), 0, 9999, 1, &ok);
             if (ok)
                 setTransitionPriority(id, value > 0 ? std::optional<quint64>(quint64(value)) : std::nullopt);
         }, false},
        {"sfcZoomOutOfMacro", QT_TR_NOOP("Leave Macro"), "", [this] { leaveMacro(); }, false},
        {"sfcZoomIn", QT_TR_NOOP("Zoom In"), "Ctrl++", [this] { m_view->zoomIn(); }, false},
        {"sfcZoomOut", QT_TR_NOOP("Zoom Out"), "Ctrl+-", [this] { m_view->zoomOut(); }, false},
        {"sfcFit", QT_TR_NOOP("Fit to Window"), "", [this] { fitToWindow(); }, false},
        {"sfcArrange", QT_TR_NOOP("Arrange Chart"), "", [this] { arrangeChart(); }, false},
        {"sfcExport", QT_TR_NOOP("Export Picture…"), "", [this] {
             const QString path = QFileDialog::getSaveFileName(this, tr("Export Chart"), QString(),
                 tr("SVG picture (*.svg);;PNG picture (*.png);;PDF document (*.pdf)"));
             if (!path.isEmpty())
                 showMessage(exportTo(path));
         }, false},
        {"sfcPrint", QT_TR_NOOP("Print…"), "", [this] { print(); }, false},
    };
    for (const Entry &entry : entries) {
        auto *action = new QAction(tr(entry.text), this);
        action->setObjectName(QString::fromLatin1(entry.name));
        if (*entry.shortcut) {
            action->setShortcut(QKeySequence(QString::fromLatin1(entry.shortcut)));
            action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        }
        connect(action, &QAction::triggered, this, entry.run);
        addAction(action);
        action->setProperty("sfcInsert", entry.insert);
    }
    const QStringList onBar {QStringLiteral("sfcStepAfter"), QStringLiteral("sfcAltRight"), QStringLiteral("sfcParRight"),
        QStringLiteral("sfcJump"), QStringLiteral("sfcTransitionJump"), QStringLiteral("sfcMacro"),
        QStringLiteral("sfcDelete"), QStringLiteral("sfcProperties"), QStringLiteral("sfcActions"),
        QStringLiteral("sfcZoomOutOfMacro"), QStringLiteral("sfcZoomIn"), QStringLiteral("sfcZoomOut"),
        QStringLiteral("sfcFit"), QStringLiteral("sfcArrange"), QStringLiteral("sfcExport"), QStringLiteral("sfcPrint")};
    for (const QString &name : onBar)
        m_toolBar->addAction(action(name));
}

QAction *SfcEditor::action(const QString &objectName) const
{
    return findChild<QAction *>(objectName, Qt::FindDirectChildrenOnly);
}

QList<QAction *> SfcEditor::insertActions() const
{
    QList<QAction *> list;
    for (QAction *a : actions())
        if (a->property("sfcInsert").toBool())
            list << a;
    return list;
}

void SfcEditor::contextMenuEvent(QContextMenuEvent *event)
{
    QMenu menu(this);
    for (QAction *a : insertActions())
        menu.addAction(a);
    menu.addSeparator();
    for (const char *name : {"sfcProperties", "sfcActions", "sfcCondition", "sfcPriority", "sfcZoomOutOfMacro"})
        menu.addAction(action(QString::fromLatin1(name)));
    menu.addSeparator();
    for (const char *name : {"sfcCut", "sfcCopy", "sfcPaste", "sfcDelete"})
        menu.addAction(action(QString::fromLatin1(name)));
    menu.addSeparator();
    menu.addAction(action(QStringLiteral("sfcArrange")));
    menu.exec(event->globalPos());
}

// ---- state

QString SfcEditor::lastMessage() const
{
    return m_messageLabel->text();
}

void SfcEditor::showMessage(const QString &message)
{
    m_messageLabel->setText(message);
    m_messageLabel->setVisible(!message.isEmpty());
    Q_EMIT messageChanged(message);
}

ChartDocument SfcEditor::document() const
{
    const std::vector<Element> *elements = m_policy.elements(m_model, m_ref);
    return readChart(elements ? *elements : std::vector<Element> {});
}

QList<quint64> SfcEditor::selection() const
{
    return m_scene->selectedLocalIds();
}

void SfcEditor::select(const QList<quint64> &localIds)
{
    m_scene->rebuildIfDirty();
    m_scene->selectLocalIds(localIds);
    if (!localIds.isEmpty())
        m_shiftAnchor = localIds.front();
    if (!localIds.isEmpty())
        if (DiagramItem *item = m_scene->itemFor(localIds.front()))
            m_view->ensureVisible(item, 30, 30);
}

quint64 SfcEditor::stepId(const QString &name) const
{
    return document().stepNamed(name).value_or(0);
}

quint64 SfcEditor::selectedOfKind(bool steps) const
{
    const ChartDocument doc = document();
    for (quint64 id : selection()) {
        const Element *e = doc.element(id);
        if (!e)
            continue;
        if (steps && (std::holds_alternative<Step>(*e) || std::holds_alternative<MacroStep>(*e)))
            return id;
        if (steps && std::holds_alternative<ActionBlock>(*e)) {
            const auto &block = std::get<ActionBlock>(*e);
            if (block.connectionPointIn && !block.connectionPointIn->connections.empty())
                return block.connectionPointIn->connections.front().refLocalId;
        }
        if (!steps && std::holds_alternative<Transition>(*e))
            return id;
    }
    return 0;
}

bool SfcEditor::refuseWhenOnline()
{
    if (!m_online)
        return false;
    showMessage(tr("The chart cannot be changed while online. Log out first (Online → Logout)."));
    return true;
}

std::vector<quint64> SfcEditor::selectedIds() const
{
    const QList<quint64> ids = selection();
    return {ids.begin(), ids.end()};
}

bool SfcEditor::edit(const QString &text, const std::function<EditResult(ChartDocument &)> &change)
{
    if (refuseWhenOnline())
        return false;
    ChartDocument doc = document();
    const EditResult result = change(doc);
    return commit(std::move(doc), result, text);
}

bool SfcEditor::commit(ChartDocument doc, const EditResult &result, const QString &text)
{
    if (!result.ok()) {
        showMessage(result.error);
        return false;
    }
    const ChartDocument before = document();
    wireChart(doc);
    placeLevel(before, doc);
    if (!pushLevel(std::move(doc.elements), text))
        return false;
    select(QList<quint64>(result.select.begin(), result.select.end()));
    return true;
}

void SfcEditor::placeLevel(const ChartDocument &before, ChartDocument &edited) const
{
    // A chart imported without positions stays in the automatic layout; any other keeps the
    // positions it has and only the edited part is placed.
    const Body *body = m_model.body(m_ref);
    if (m_policy.macroPath().empty() && body && body->layoutGenerated)
        layoutChart(edited);
    else
        placeEdit(before, edited);
}

bool SfcEditor::pushLevel(std::vector<Element> level, const QString &text)
{
    const Body *body = m_model.body(m_ref);
    if (!body || !body->elements()) {
        showMessage(tr("This body is not a chart."));
        return false;
    }
    std::vector<Element> top = withLevel(*body->elements(), m_policy.macroPath(), std::move(level));
    showMessage(QString());
    if (top != *body->elements())
        m_undoStack->push(new SetChartElementsCommand(m_model, m_ref, std::move(top), text));
    m_scene->rebuildIfDirty();
    return true;
}

bool SfcEditor::arrangeChart()
{
    if (refuseWhenOnline())
        return false;
    ChartDocument doc = document();
    if (doc.chart.isEmpty()) {
        showMessage(tr("The chart is empty: there is nothing to arrange."));
        return false;
    }
    const QList<quint64> selected = selection();
    layoutChart(doc);
    if (!pushLevel(std::move(doc.elements), tr("Arrange chart")))
        return false;
    select(selected);
    return true;
}

// ---- structured commands

bool SfcEditor::createChart()
{
    return edit(tr("New chart"), [&](ChartDocument &doc) { return createDefaultChart(doc); });
}

bool SfcEditor::insertStepTransitionAfter()
{
    return edit(tr("Insert step-transition"),
        [&](ChartDocument &doc) { return sfc::insertStepTransition(doc, selectedIds(), true); });
}

bool SfcEditor::insertStepTransitionBefore()
{
    return edit(tr("Insert step-transition"),
        [&](ChartDocument &doc) { return sfc::insertStepTransition(doc, selectedIds(), false); });
}

bool SfcEditor::insertAlternativeBranch(bool right)
{
    return edit(tr("Insert alternative branch"),
        [&](ChartDocument &doc) { return sfc::insertAlternativeBranch(doc, selectedIds(), right); });
}

bool SfcEditor::insertParallelBranch(bool right)
{
    return edit(tr("Insert parallel branch"),
        [&](ChartDocument &doc) { return sfc::insertParallelBranch(doc, selectedIds(), right); });
}

bool SfcEditor::insertJump(const QString &target)
{
    return edit(tr("Insert jump"), [&](ChartDocument &doc) { return sfc::insertJump(doc, selectedIds(), target); });
}

bool SfcEditor::insertTransitionJump(const QString &target)
{
    return edit(tr("Insert transition-jump"),
        [&](ChartDocument &doc) { return sfc::insertTransitionJump(doc, selectedIds(), target); });
}

bool SfcEditor::insertMacroStep()
{
    return edit(
        tr("Insert macro step"), [&](ChartDocument &doc) { return sfc::insertMacroStep(doc, selectedIds(), true); });
}

bool SfcEditor::deleteSelection()
{
    return edit(tr("Delete"), [&](ChartDocument &doc) { return sfc::deleteSelection(doc, selectedIds()); });
}

bool SfcEditor::copySelection()
{
    ChartDocument doc = document();
    QString error;
    std::optional<Fragment> fragment = copyFragment(doc, selectedIds(), &error);
    if (!fragment) {
        showMessage(error);
        return false;
    }
    chartClipboard() = std::move(fragment);
    return true;
}

bool SfcEditor::cutSelection()
{
    if (refuseWhenOnline())
        return false;
    return copySelection() && deleteSelection();
}

bool SfcEditor::paste()
{
    if (refuseWhenOnline())
        return false;
    if (!chartClipboard()) {
        showMessage(tr("There is nothing to paste."));
        return false;
    }
    return edit(tr("Paste"), [&](ChartDocument &doc) { return pasteFragment(doc, selectedIds(), *chartClipboard()); });
}

// ---- properties

bool SfcEditor::setStepProperties(quint64 id, const StepProperties &properties)
{
    return edit(tr("Change step"), [&](ChartDocument &doc) { return sfc::setStepProperties(doc, id, properties); });
}

bool SfcEditor::addActionAssociation(quint64 id, const ActionBlockAction &action, int index)
{
    return edit(tr("Add action"), [&](ChartDocument &doc) { return sfc::addAction(doc, id, action, index); });
}

bool SfcEditor::changeActionAssociation(quint64 id, int index, const ActionBlockAction &action)
{
    return edit(tr("Change action"), [&](ChartDocument &doc) { return sfc::changeAction(doc, id, index, action); });
}

bool SfcEditor::removeActionAssociation(quint64 id, int index)
{
    return edit(tr("Remove action"), [&](ChartDocument &doc) { return sfc::removeAction(doc, id, index); });
}

bool SfcEditor::moveActionAssociation(quint64 id, int from, int to)
{
    return edit(tr("Move action"), [&](ChartDocument &doc) { return sfc::moveAction(doc, id, from, to); });
}

bool SfcEditor::setTransitionCondition(quint64 id, const QString &stText)
{
    return edit(tr("Change condition"), [&](ChartDocument &doc) { return setInlineCondition(doc, id, stText); });
}

bool SfcEditor::setTransitionReference(quint64 id, const QString &transitionName)
{
    return edit(
        tr("Change condition"), [&](ChartDocument &doc) { return setConditionReference(doc, id, transitionName); });
}

bool SfcEditor::setTransitionPriority(quint64 id, std::optional<quint64> priority)
{
    return edit(tr("Change priority"), [&](ChartDocument &doc) { return setPriority(doc, id, priority); });
}

bool SfcEditor::openStepAction(quint64 id, const QString &which)
{
    ChartDocument doc = document();
    std::optional<StepProperties> properties = stepProperties(doc, id);
    if (!properties) {
        showMessage(tr("Select a step first."));
        return false;
    }
    QString StepOptions::*field = which == QLatin1String("entry") ? &StepOptions::entryAction
        : which == QLatin1String("exit")                          ? &StepOptions::exitAction
                                                                  : &StepOptions::activeAction;
    QString name = properties->options.*field;
    const bool needsName = name.isEmpty();
    const bool needsPart = !m_model.findPouPart(m_ref.pou, BodyRef::Part::Action, needsName ? properties->name + QLatin1Char('_') + which : name);
    if (needsName || needsPart) {
        if (refuseWhenOnline())
            return false;
        if (needsName)
            name = properties->name + QLatin1Char('_') + which;
        auto *gesture = new QUndoCommand(tr("Add %1 action %2").arg(which, name));
        if (needsPart && !m_model.findPouPart(m_ref.pou, BodyRef::Part::Action, name)) {
            PouPart part;
            part.name = name;
            part.body = Body::withLanguage(BodyLanguage::ST);
            new AddPouPartCommand(m_model, m_ref.pou, BodyRef::Part::Action, part, gesture);
        }
        if (needsName) {
            properties->options.*field = name;
            const EditResult result = sfc::setStepProperties(doc, id, *properties);
            if (!result.ok()) {
                delete gesture;
                showMessage(result.error);
                return false;
            }
            wireChart(doc);
            placeLevel(document(), doc);
            std::vector<Element> top = withLevel(*m_model.body(m_ref)->elements(), m_policy.macroPath(), std::move(doc.elements));
            new SetChartElementsCommand(m_model, m_ref, std::move(top), gesture->text(), gesture);
        }
        m_undoStack->push(gesture);
        m_scene->rebuildIfDirty();
        select({id});
    }
    Q_EMIT openPartRequested(m_ref.pou, BodyRef::Part::Action, name);
    return true;
}

// ---- macro steps

bool SfcEditor::enterMacro(quint64 macroId)
{
    const ChartDocument doc = document();
    const Element *e = doc.element(macroId);
    if (!e || !std::holds_alternative<MacroStep>(*e)) {
        showMessage(tr("Select a macro step first."));
        return false;
    }
    std::vector<quint64> path = m_policy.macroPath();
    path.push_back(macroId);
    m_policy.setMacroPath(path);
    m_scene->rebuild();
    updateLevelLabel();
    return true;
}

bool SfcEditor::leaveMacro()
{
    std::vector<quint64> path = m_policy.macroPath();
    if (path.empty())
        return false;
    const quint64 macro = path.back();
    path.pop_back();
    m_policy.setMacroPath(path);
    m_scene->rebuild();
    updateLevelLabel();
    select({macro});
    return true;
}

void SfcEditor::updateLevelLabel()
{
    const bool nested = !m_policy.macroPath().empty();
    m_levelLabel->setVisible(nested);
    action(QStringLiteral("sfcZoomOutOfMacro"))->setEnabled(nested);
    if (!nested)
        return;
    QStringList names;
    const Body *body = m_model.body(m_ref);
    std::vector<quint64> prefix;
    for (quint64 id : m_policy.macroPath()) {
        const std::vector<Element> *level = body ? levelElements(*body->elements(), prefix) : nullptr;
        const ChartDocument doc = readChart(level ? *level : std::vector<Element> {});
        names << doc.stepName(id);
        prefix.push_back(id);
    }
    m_levelLabel->setText(tr("Inside macro step %1").arg(names.join(QStringLiteral(" › "))));
}

// ---- mouse and keys

void SfcEditor::onShiftClicked(quint64 localId)
{
    ChartDocument doc = document();
    const quint64 anchor = m_shiftAnchor ? m_shiftAnchor : localId;
    const std::vector<quint64> range = connectedRange(doc, anchor, localId);
    const quint64 keep = m_shiftAnchor;
    m_scene->selectLocalIds(QList<quint64>(range.begin(), range.end()));
    m_shiftAnchor = keep;
}

void SfcEditor::onDoubleClicked(quint64 localId, QPointF scenePos)
{
    const ChartDocument doc = document();
    const Element *e = doc.element(localId);
    if (!e)
        return;
    if (std::holds_alternative<MacroStep>(*e)) {
        enterMacro(localId);
        return;
    }
    if (std::holds_alternative<Step>(*e)) {
        auto *item = dynamic_cast<StepItem *>(m_scene->itemFor(localId));
        const StepItem::Corner corner = item ? item->cornerAt(scenePos) : StepItem::Corner::None;
        const StepOptions options = stepOptions(std::get<Step>(*e));
        if (corner == StepItem::Corner::Entry)
            openStepAction(localId, QStringLiteral("entry"));
        else if (corner == StepItem::Corner::Exit)
            openStepAction(localId, QStringLiteral("exit"));
        else if (corner == StepItem::Corner::Active && options.simplified)
            openStepAction(localId, QStringLiteral("active"));
        else
            editStepDialog(localId);
        return;
    }
    if (const auto *transition = std::get_if<Transition>(e)) {
        if (transition->condition && std::holds_alternative<Reference>(transition->condition->kind)) {
            const QString name = std::get<Reference>(transition->condition->kind).name;
            if (!m_model.findPouPart(m_ref.pou, BodyRef::Part::Transition, name) && !m_online) {
                PouPart part;
                part.name = name;
                part.body = Body::withLanguage(BodyLanguage::ST);
                part.body.setText(QStringLiteral("FALSE"));
                m_undoStack->push(new AddPouPartCommand(m_model, m_ref.pou, BodyRef::Part::Transition, part));
            }
            Q_EMIT openPartRequested(m_ref.pou, BodyRef::Part::Transition, name);
        } else
            editConditionInPlace(localId);
        return;
    }
    if (const auto *block = std::get_if<ActionBlock>(e)) {
        auto *item = dynamic_cast<ActionBlockItem *>(m_scene->itemFor(localId));
        const int row = item ? item->rowAt(scenePos) : -1;
        if (row >= 0 && block->actions[std::size_t(row)].reference) {
            const QString name = block->actions[std::size_t(row)].reference->name;
            if (m_model.findPouPart(m_ref.pou, BodyRef::Part::Action, name)) {
                Q_EMIT openPartRequested(m_ref.pou, BodyRef::Part::Action, name);
                return;
            }
        }
        if (block->connectionPointIn && !block->connectionPointIn->connections.empty())
            editActionsDialog(block->connectionPointIn->connections.front().refLocalId);
        return;
    }
    if (std::holds_alternative<JumpStep>(*e)) {
        select({localId});
        chooseJumpTarget(false);
    }
}

void SfcEditor::editConditionInPlace(quint64 transitionId)
{
    if (refuseWhenOnline())
        return;
    const ChartDocument doc = document();
    const auto *transition = doc.element(transitionId) ? std::get_if<Transition>(doc.element(transitionId)) : nullptr;
    if (!transition)
        return;
    QString text;
    if (transition->condition && std::holds_alternative<InlineCondition>(transition->condition->kind))
        text = std::get<InlineCondition>(transition->condition->kind).body->text();
    else
        text = conditionText(*transition);
    delete m_inlineEditor;
    m_inlineEditor = new QLineEdit(text, m_view->viewport());
    m_inlineEditor->setObjectName(QStringLiteral("sfcConditionEditor"));
    const QRectF frame = elementRect(*doc.element(transitionId));
    const QPoint at = m_view->mapFromScene(QPointF(frame.right() + kLabelGap - 2, frame.center().y() - 11));
    m_inlineEditor->setGeometry(at.x(), at.y(), 260, 24);
    m_inlineEditor->setToolTip(tr("An ST expression, or the name of a transition of the POU. Enter applies, Esc cancels."));
    m_inlineEditor->show();
    m_inlineEditor->setFocus();
    m_inlineEditor->selectAll();
    QLineEdit *editor = m_inlineEditor;
    connect(editor, &QLineEdit::returnPressed, this, [this, editor, transitionId] {
        const QString value = editor->text().trimmed();
        editor->deleteLater();
        m_inlineEditor = nullptr;
        // A bare name of an existing transition part refers to it; anything else is inline ST.
        if (partNames(m_model, m_ref.pou, false).contains(value, Qt::CaseInsensitive))
            setTransitionReference(transitionId, value);
        else
            setTransitionCondition(transitionId, value);
        m_view->setFocus();
    });
    editor->installEventFilter(this);
}

void SfcEditor::editStepDialog(quint64 stepId)
{
    if (refuseWhenOnline())
        return;
    const std::optional<StepProperties> properties = stepProperties(document(), stepId);
    if (!properties)
        return;
    StepPropertiesDialog dialog(*properties, partNames(m_model, m_ref.pou, true), this);
    if (dialog.exec() == QDialog::Accepted && !(dialog.properties() == *properties))
        setStepProperties(stepId, dialog.properties());
}

void SfcEditor::editActionsDialog(quint64 stepId)
{
    if (refuseWhenOnline())
        return;
    const ChartDocument doc = document();
    ActionAssociationsDialog dialog(stepActions(doc, stepId), partNames(m_model, m_ref.pou, true), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    edit(tr("Change actions"), [&](ChartDocument &edited) {
        EditResult result {{}, {stepId}};
        while (!stepActions(edited, stepId).empty() && result.ok())
            result = sfc::removeAction(edited, stepId, 0);
        for (const ActionBlockAction &action : dialog.actions()) {
            if (result.ok())
                result = sfc::addAction(edited, stepId, action);
        }
        return result;
    });
}

void SfcEditor::chooseJumpTarget(bool withTransition)
{
    if (refuseWhenOnline())
        return;
    const QStringList names = stepNames(document());
    if (names.isEmpty()) {
        showMessage(tr("The chart has no step to jump to."));
        return;
    }
    bool ok = false;
    const QString target = QInputDialog::getItem(this, tr("Jump"), tr("Jump to step:"), names, 0, false, &ok);
    if (!ok)
        return;
    if (withTransition)
        insertTransitionJump(target);
    else
        insertJump(target);
}

void SfcEditor::moveSelection(Qt::Key key)
{
    const QList<quint64> ids = selection();
    DiagramItem *current = ids.isEmpty() ? nullptr : m_scene->itemFor(ids.front());
    const QList<DiagramItem *> items = m_scene->diagramItems();
    if (!current) {
        if (!items.isEmpty())
            select({items.front()->localId()});
        return;
    }
    // Frames, not bounding boxes: a transition's box reaches out over its condition text.
    const auto centre = [](DiagramItem *item) { return static_cast<SfcItem *>(item)->frame().center(); };
    const QPointF from = centre(current);
    DiagramItem *best = nullptr;
    double bestCost = 0;
    for (DiagramItem *item : items) {
        if (item == current)
            continue;
        const QPointF delta = centre(item) - from;
        double along = 0;
        double across = 0;
        switch (key) {
        case Qt::Key_Down: along = delta.y(); across = delta.x(); break;
        case Qt::Key_Up: along = -delta.y(); across = delta.x(); break;
        case Qt::Key_Right: along = delta.x(); across = delta.y(); break;
        case Qt::Key_Left: along = -delta.x(); across = delta.y(); break;
        default: return;
        }
        if (along <= 1)
            continue;
        const double cost = along + 3 * std::abs(across);
        if (!best || cost < bestCost) {
            best = item;
            bestCost = cost;
        }
    }
    if (best)
        select({best->localId()});
}

bool SfcEditor::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_inlineEditor && event->type() == QEvent::KeyPress
        && static_cast<QKeyEvent *>(event)->key() == Qt::Key_Escape) {
        m_inlineEditor->deleteLater();
        m_inlineEditor = nullptr;
        return true;
    }
    if ((watched == m_view || watched == m_view->viewport()) && event->type() == QEvent::KeyPress) {
        auto *key = static_cast<QKeyEvent *>(event);
        switch (key->key()) {
        case Qt::Key_Up:
        case Qt::Key_Down:
        case Qt::Key_Left:
        case Qt::Key_Right:
            moveSelection(Qt::Key(key->key()));
            return true;
        case Qt::Key_Return:
        case Qt::Key_Enter:
            if (const QList<quint64> ids = selection(); !ids.isEmpty()) {
                if (DiagramItem *item = m_scene->itemFor(ids.front()))
                    onDoubleClicked(ids.front(), item->boundingRect().center());
            }
            return true;
        default:
            break;
        }
    }
    return QWidget::eventFilter(watched, event);
}

// ---- view

void SfcEditor::fitToWindow()
{
    m_scene->rebuildIfDirty();
    // An editor not shown yet has not laid out its view: size the view as the layout will, so
    // that the view fits the chart to that size (small charts up to the largest zoom step).
    if (!isVisible())
        layout()->setGeometry(rect());
    m_view->fitToWindow();
}

QString SfcEditor::exportTo(const QString &path)
{
    m_scene->rebuildIfDirty();
    return exportScene(*m_scene, path);
}

void SfcEditor::print()
{
    QPrinter printer;
    QPrintDialog dialog(&printer, this);
    if (dialog.exec() == QDialog::Accepted)
        printScene(*m_scene, printer);
}

// ---- online

QString SfcEditor::onlineInstance() const
{
    return m_onlineInstance;
}

QStringList SfcEditor::onlineNames() const
{
    return {}; // the chart's state comes with ChartState
}

void SfcEditor::setOnlineSnapshot(const interp::RuntimeSnapshot *snapshot)
{
    if (m_online != (snapshot != nullptr)) {
        // Online the chart is only looked at: the commands that would change it are off (they
        // refuse anyway); copy, zoom, export and print stay.
        static const QStringList kChanging {QStringLiteral("sfcDelete"), QStringLiteral("sfcCut"),
            QStringLiteral("sfcPaste"), QStringLiteral("sfcProperties"), QStringLiteral("sfcActions"),
            QStringLiteral("sfcCondition"), QStringLiteral("sfcPriority"), QStringLiteral("sfcArrange")};
        for (QAction *action : findChildren<QAction *>(Qt::FindDirectChildrenOnly))
            if (kChanging.contains(action->objectName()) || insertActions().contains(action))
                action->setEnabled(snapshot == nullptr);
    }
    m_online = snapshot != nullptr;
    m_chartState.reset();
    if (snapshot) {
        if (const interp::sfc::ChartState *state = snapshot->chart(onlineInstance()))
            m_chartState = *state;
    } else
        showMessage(QString());
    if (m_inlineEditor && m_online) {
        m_inlineEditor->deleteLater();
        m_inlineEditor = nullptr;
    }
    applyOnlineState();
}

void SfcEditor::applyOnlineState()
{
    QSet<QString> activeActions;
    std::unordered_map<quint64, const interp::sfc::StepState *> stepsById;
    QHash<QString, const interp::sfc::StepState *> stepsByName;
    std::unordered_map<quint64, bool> transitions;
    const bool top = m_policy.macroPath().empty();
    if (m_chartState) {
        for (const auto &step : m_chartState->steps) {
            if (top)
                stepsById[step.localId] = &step;
            stepsByName.insert(step.name.toLower(), &step);
        }
        for (const auto &action : m_chartState->actions)
            if (action.active)
                activeActions.insert(action.name.toLower());
        if (top)
            for (const auto &transition : m_chartState->transitions)
                transitions[transition.localId] = transition.condition;
    }
    for (DiagramItem *item : m_scene->diagramItems()) {
        auto *sfcItem = static_cast<SfcItem *>(item);
        const Element &e = sfcItem->element();
        if (std::holds_alternative<Step>(e) || std::holds_alternative<MacroStep>(e)) {
            const interp::sfc::StepState *state = nullptr;
            if (const auto it = stepsById.find(item->localId()); it != stepsById.end())
                state = it->second;
            else
                state = stepsByName.value(
                    std::holds_alternative<Step>(e) ? std::get<Step>(e).name.toLower() : std::get<MacroStep>(e).name.value_or(QString()).toLower());
            const bool active = state && state->active;
            item->setActive(active);
            item->setOnlineText(active ? formatElapsed(state->elapsedNs) : QString());
        } else if (std::holds_alternative<Transition>(e)) {
            const auto it = transitions.find(item->localId());
            item->setActive(it != transitions.end() && it->second);
        } else if (auto *block = dynamic_cast<ActionBlockItem *>(item)) {
            block->setActiveActions(activeActions);
        }
    }
}

} // namespace iec::editors::sfc
