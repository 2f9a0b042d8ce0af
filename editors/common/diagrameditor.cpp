#include "editors/common/diagrameditor.h"

#include "editors/common/diagramexport.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/common/overlaymapper.h"
#include "model/projectmodel.h"
#include "model/undo/bodyelementscommand.h"
#include "model/undo/elementcommands.h"

#include <QAction>
#include <QClipboard>
#include <QGuiApplication>
#include <QContextMenuEvent>
#include <QCoreApplication>
#include <QFileDialog>
#include <QKeyEvent>
#include <QLabel>
#include <QMenu>
#include <QPrintDialog>
#include <QPrinter>
#include <QScrollBar>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>

#include <cmath>

namespace iec::editors {

DiagramEditor::DiagramEditor(model::ProjectModel &model, model::BodyRef ref, QUndoStack *undoStack,
    std::unique_ptr<DiagramPolicy> policy, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_ref(std::move(ref))
    , m_undoStack(undoStack ? undoStack : new QUndoStack(this))
    , m_policy(std::move(policy))
{
    m_scene = new DiagramScene(model, m_ref, *m_policy, this);
    m_view = new DiagramView;
    m_view->setObjectName(QStringLiteral("diagramView"));
    m_view->setScene(m_scene);
    m_view->setBackgroundBrush(Qt::white);
    m_view->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_view->installEventFilter(this);
    m_view->viewport()->installEventFilter(this);
    m_view->viewport()->setAcceptDrops(true); // boxes from the library pane (acceptsPouDrops)
    setGridSize(10);
    m_toolBar = new QToolBar;
    m_toolBar->setObjectName(QStringLiteral("diagramToolBar"));
    m_toolBar->setIconSize(QSize(16, 16));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_messageLabel = new QLabel;
    m_messageLabel->setObjectName(QStringLiteral("diagramMessage"));
    m_messageLabel->setWordWrap(true);
    m_messageLabel->setStyleSheet(QStringLiteral("color: #a03000;"));
    m_messageLabel->hide();
    m_layout = new QVBoxLayout(this);
    m_layout->setContentsMargins(0, 0, 0, 0);
    m_layout->setSpacing(0);
    m_layout->addWidget(m_toolBar);
    m_layout->addWidget(m_view, 1);
    m_layout->addWidget(m_messageLabel);
    addViewActions();

    connect(m_scene, &DiagramScene::elementDoubleClicked, this, &DiagramEditor::activateElement);
    connect(m_scene, &DiagramScene::elementShiftClicked, this, &DiagramEditor::extendSelection);
    connect(m_scene, &DiagramScene::rebuilt, this, &DiagramEditor::onSceneRefreshed);
    connect(m_scene, &DiagramScene::updated, this, &DiagramEditor::onSceneRefreshed);
    // An overlay may paint only what is on screen (LD does): what scrolls into view gets the
    // values too, also while the program is halted and no new snapshot comes.
    for (QScrollBar *bar : {m_view->horizontalScrollBar(), m_view->verticalScrollBar()})
        connect(bar, &QScrollBar::valueChanged, this, [this] {
            if (m_snapshot && m_overlay)
                m_overlay->apply(*m_scene, *m_snapshot, m_onlineInstance);
        });
    connect(m_scene, &QGraphicsScene::selectionChanged, this, [this] {
        // A message about the last command no longer fits once the user looks elsewhere.
        if (!m_online)
            showMessage(QString());
        updateActionStates();
    });
    connect(m_scene, &DiagramScene::elementsMoved, this, &DiagramEditor::moveElements);
    connect(m_scene, &DiagramScene::wireDrawn, this, &DiagramEditor::connectWire);
    connect(m_view, &DiagramView::zoomChanged, this, [this] { Q_EMIT zoomChanged(zoomPercent()); });
    // Paste is enabled by what the clipboard holds.
    connect(QGuiApplication::clipboard(), &QClipboard::dataChanged, this, &DiagramEditor::updateActionStates);
    m_scene->rebuild();
}

DiagramEditor::~DiagramEditor()
{
    // An open line would commit when it loses the focus on the way out.
    if (m_inPlace) {
        m_inPlace->disconnect(this);
        delete m_inPlace;
    }
    // The scene goes first, while the policy it draws with still exists; its items' removal
    // must not reach this half-destroyed editor.
    m_scene->disconnect(this);
    delete m_scene;
    m_scene = nullptr;
}

// ---- actions

void DiagramEditor::addViewActions()
{
    const ActionSpec specs[] = {
        {"zoomIn", QT_TR_NOOP("Zoom In"), "Ctrl++", ActionGroup::View, false, true, [this] { zoomIn(); }, {}, QT_TR_NOOP("Zoom +")},
        {"zoomOut", QT_TR_NOOP("Zoom Out"), "Ctrl+-", ActionGroup::View, false, true, [this] { zoomOut(); }, {}, QT_TR_NOOP("Zoom −")},
        {"zoomReset", QT_TR_NOOP("Zoom 100 %"), "", ActionGroup::View, false, false, [this] { resetZoom(); }},
        {"fitToWindow", QT_TR_NOOP("Fit to Window"), "Ctrl+0", ActionGroup::View, false, true, [this] { fitToWindow(); }, {},
            QT_TR_NOOP("Fit")},
        {"exportPicture", QT_TR_NOOP("Export Picture…"), "", ActionGroup::View, false, true, [this] { exportInteractive(); },
            {}, QT_TR_NOOP("Export…")},
        {"printDiagram", QT_TR_NOOP("Print…"), "Ctrl+P", ActionGroup::View, false, false, [this] { print(); }},
    };
    m_viewActionsStart = m_toolBar->addSeparator();
    addActionEntries(specs, QByteArray(staticMetaObject.className()), nullptr);
}

void DiagramEditor::addActionTable(std::span<const ActionSpec> specs)
{
    addActionEntries(specs, QByteArray(metaObject()->className()), m_viewActionsStart);
    updateActionStates();
}

void DiagramEditor::addActionEntries(std::span<const ActionSpec> specs, const QByteArray &context, QAction *before)
{
    for (const ActionSpec &spec : specs) {
        auto entry = std::make_unique<ActionEntry>(ActionEntry {spec, context, new QAction(this)});
        QAction *action = entry->action;
        action->setObjectName(QString::fromLatin1(spec.id));
        if (*spec.shortcut) {
            action->setShortcut(QKeySequence(QString::fromLatin1(spec.shortcut), QKeySequence::PortableText));
            action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        }
        const ActionEntry *raw = entry.get();
        translateAction(*raw);
        connect(action, &QAction::triggered, this, [this, raw] { runAction(*raw); });
        addAction(action);
        if (spec.onToolBar) {
            m_toolBar->insertAction(before, action);
            if (spec.group == ActionGroup::Insert && acceptsInsertDrops())
                if (QWidget *button = m_toolBar->widgetForAction(action)) {
                    button->installEventFilter(this);
                    m_insertButtons.insert(button, action->objectName());
                }
        }
        m_actions.push_back(std::move(entry));
    }
}

void DiagramEditor::translateAction(const ActionEntry &entry)
{
    const QString text = QCoreApplication::translate(entry.context.constData(), entry.spec.text);
    entry.action->setText(text);
    if (entry.spec.toolBarText) {
        entry.action->setIconText(QCoreApplication::translate(entry.context.constData(), entry.spec.toolBarText));
        entry.action->setToolTip(QString(text).remove(QStringLiteral("…")));
    }
}

void DiagramEditor::runAction(const ActionEntry &entry)
{
    if (entry.spec.changesModel && refuseWhileOnline())
        return;
    m_lastCommandOk = true;
    entry.spec.run();
}

const DiagramEditor::ActionEntry *DiagramEditor::entryFor(const QString &id) const
{
    for (const auto &entry : m_actions) {
        if (entry->action->objectName() == id)
            return entry.get();
    }
    return nullptr;
}

QAction *DiagramEditor::action(const QString &id) const
{
    const ActionEntry *entry = entryFor(id);
    return entry ? entry->action : nullptr;
}

QList<QAction *> DiagramEditor::actionsIn(ActionGroup group) const
{
    QList<QAction *> list;
    for (const auto &entry : m_actions) {
        if (entry->spec.group == group)
            list << entry->action;
    }
    return list;
}

QList<QAction *> DiagramEditor::contextMenuActions()
{
    updateActionStates();
    QList<QAction *> list;
    int separator = 0;
    for (const ActionGroup group : {ActionGroup::Insert, ActionGroup::Element, ActionGroup::Edit}) {
        const QList<QAction *> actions = actionsIn(group);
        if (actions.isEmpty())
            continue;
        if (!list.isEmpty()) {
            if (m_separators.size() <= separator) {
                auto *line = new QAction(this);
                line->setSeparator(true);
                m_separators << line;
            }
            list << m_separators[separator++];
        }
        list << actions;
    }
    return list;
}

bool DiagramEditor::trigger(const QString &id)
{
    const ActionEntry *entry = entryFor(id);
    if (!entry)
        return false;
    runAction(*entry);
    return m_lastCommandOk;
}

void DiagramEditor::updateActionStates()
{
    for (const auto &entry : m_actions) {
        const bool allowed = !(entry->spec.changesModel && m_online);
        entry->action->setEnabled(allowed && (!entry->spec.enabled || entry->spec.enabled()));
    }
}

// ---- messages

QString DiagramEditor::lastMessage() const
{
    return m_messageLabel->text();
}

void DiagramEditor::showMessage(const QString &message)
{
    if (message == m_messageLabel->text() && m_messageLabel->isVisible() == !message.isEmpty())
        return;
    m_messageLabel->setText(message);
    m_messageLabel->setVisible(!message.isEmpty());
    Q_EMIT messageChanged(message);
}

void DiagramEditor::showError(const QString &message)
{
    m_lastCommandOk = false;
    showMessage(message);
}

bool DiagramEditor::refuseWhileOnline()
{
    if (!m_online)
        return false;
    showError(tr("The diagram cannot be changed while online. Log out first (Online → Logout)."));
    return true;
}

// ---- selection

QList<quint64> DiagramEditor::selection() const
{
    return m_scene->selectedLocalIds();
}

std::vector<quint64> DiagramEditor::selectedIds() const
{
    const QList<quint64> ids = selection();
    return {ids.begin(), ids.end()};
}

void DiagramEditor::select(const QList<quint64> &localIds)
{
    m_scene->rebuildIfDirty();
    m_scene->selectLocalIds(localIds);
    if (!localIds.isEmpty()) {
        if (DiagramItem *item = m_scene->itemFor(localIds.front()))
            m_view->ensureVisible(item->frame(), 30, 30);
    }
}

// ---- the edit path

void DiagramEditor::moveElements(const QList<quint64> &ids, const QList<QPointF> &to)
{
    std::vector<model::MoveElementsCommand::Move> moves;
    for (qsizetype i = 0; i < ids.size(); ++i)
        moves.push_back({ids[i], model::Position {to[i].x(), to[i].y()}});
    // Under a parent of its own: a second drag of the same items is a gesture of its own, not
    // merged into this one (MoveElementsCommand merges the steps of one continuing drag).
    auto *gesture = new QUndoCommand;
    const auto *move = new model::MoveElementsCommand(m_model, m_ref, std::move(moves), gesture);
    gesture->setText(move->text());
    if (!pushCommand(gesture, ids))
        m_scene->rebuild(); // the items go back where the model has them
}

void DiagramEditor::connectWire(quint64 source, const QString &formalParameter, quint64 target, int inputIndex)
{
    model::Connection connection;
    connection.refLocalId = source;
    if (!formalParameter.isEmpty())
        connection.formalParameter = formalParameter;
    pushCommand(new model::ConnectCommand(m_model, m_ref, target, inputIndex, connection), {target});
}

QUndoCommand *DiagramEditor::elementsCommand(std::vector<model::Element> after, const QString &undoText)
{
    const model::Body *body = m_model.body(m_ref);
    if (!body || !body->elements())
        return nullptr;
    return new model::SetBodyElementsCommand(m_model, m_ref, std::move(after), undoText);
}

std::vector<model::Element> DiagramEditor::bodyElementsFor(std::vector<model::Element> shown) const
{
    return shown;
}

EditOutcome DiagramEditor::prepareEdit(const ElementEdit &edit, std::vector<model::Element> &bodyElements) const
{
    const std::vector<model::Element> *shown = m_scene->shownElements();
    if (!shown)
        return {tr("This body cannot be edited here."), {}};
    std::vector<model::Element> copy = *shown;
    EditOutcome outcome = edit(copy);
    if (outcome.ok())
        bodyElements = bodyElementsFor(std::move(copy));
    return outcome;
}

bool DiagramEditor::applyEdit(const QString &undoText, const ElementEdit &edit)
{
    return applyRewrite(undoText, [&](const std::vector<model::Element> &, std::vector<model::Element> &after) {
        return prepareEdit(edit, after);
    });
}

bool DiagramEditor::applyRewrite(const QString &undoText, const ElementRewrite &rewrite)
{
    if (refuseWhileOnline())
        return false;
    const std::vector<model::Element> *shown = m_scene->shownElements();
    if (!shown) {
        showError(tr("This body cannot be edited here."));
        return false;
    }
    std::vector<model::Element> after;
    const EditOutcome outcome = rewrite(*shown, after);
    if (!outcome.ok()) {
        showError(outcome.error);
        return false;
    }
    // An edit that changes nothing pushes nothing (the command makes itself obsolete).
    if (QUndoCommand *command = elementsCommand(std::move(after), undoText))
        m_undoStack->push(command);
    showMessage(QString());
    m_scene->rebuildIfDirty();
    select(QList<quint64>(outcome.select.begin(), outcome.select.end()));
    return true;
}

bool DiagramEditor::pushCommand(QUndoCommand *command, const QList<quint64> &selectAfter)
{
    if (refuseWhileOnline()) {
        delete command;
        return false;
    }
    m_undoStack->push(command);
    showMessage(QString());
    m_scene->rebuildIfDirty();
    if (!selectAfter.isEmpty())
        select(selectAfter);
    return true;
}

// ---- keyboard and mouse

void DiagramEditor::navigate(Qt::Key key)
{
    const QList<quint64> ids = selection();
    DiagramItem *current = ids.isEmpty() ? nullptr : m_scene->itemFor(ids.front());
    const QList<DiagramItem *> items = m_scene->diagramItems();
    if (!current) {
        if (!items.isEmpty())
            select({items.front()->localId()});
        return;
    }
    const QPointF from = current->frame().center();
    DiagramItem *best = nullptr;
    double bestCost = 0;
    for (DiagramItem *item : items) {
        if (item == current)
            continue;
        const QPointF delta = item->frame().center() - from;
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
        // Straight ahead first: a step sideways costs three steps forward.
        const double cost = along + 3 * std::abs(across);
        if (!best || cost < bestCost) {
            best = item;
            bestCost = cost;
        }
    }
    if (best)
        select({best->localId()});
}

void DiagramEditor::activateElement(quint64, QPointF)
{
}

void DiagramEditor::extendSelection(quint64 localId)
{
    QList<quint64> ids = selection();
    if (!ids.contains(localId))
        ids << localId;
    select(ids);
}

bool DiagramEditor::handleKey(QKeyEvent *event)
{
    const int key = event->key();
    const Qt::KeyboardModifiers modifiers = event->modifiers() & ~Qt::KeypadModifier;
    if (key == Qt::Key_Menu || (key == Qt::Key_F10 && modifiers == Qt::ShiftModifier)) {
        openContextMenu(selectionMenuPosition());
        return true;
    }
    if (modifiers == Qt::NoModifier) {
        switch (key) {
        case Qt::Key_Up:
        case Qt::Key_Down:
        case Qt::Key_Left:
        case Qt::Key_Right:
            navigate(Qt::Key(key));
            return true;
        case Qt::Key_Return:
        case Qt::Key_Enter:
            if (const QList<quint64> ids = selection(); !ids.isEmpty()) {
                const DiagramItem *item = m_scene->itemFor(ids.front());
                activateElement(ids.front(), item ? item->frame().center() : QPointF());
            }
            return true;
        default:
            break;
        }
    }
    // A greyed command's shortcut still runs it, so that it says why it does nothing (online:
    // the one refusal; otherwise the command's own message).
    const QKeySequence pressed(QKeyCombination(modifiers, Qt::Key(key)));
    for (const auto &entry : m_actions) {
        if (!entry->action->isEnabled() && !entry->action->shortcut().isEmpty() && entry->action->shortcut() == pressed) {
            runAction(*entry);
            return true;
        }
    }
    return false;
}

bool DiagramEditor::eventFilter(QObject *watched, QEvent *event)
{
    if ((watched == m_view || watched == m_view->viewport()) && event->type() == QEvent::KeyPress
        && handleKey(static_cast<QKeyEvent *>(event)))
        return true;
    if (watched == m_view->viewport() && handleDrop(event))
        return true;
    if (m_insertButtons.contains(watched) && dragInsertButton(watched, event))
        return true;
    return QWidget::eventFilter(watched, event);
}

QPoint DiagramEditor::selectionMenuPosition() const
{
    const QList<quint64> ids = selection();
    const DiagramItem *item = ids.isEmpty() ? nullptr : m_scene->itemFor(ids.front());
    const QPoint inView = item ? m_view->mapFromScene(item->frame().center()) : m_view->viewport()->rect().center();
    return m_view->viewport()->mapToGlobal(inView);
}

void DiagramEditor::openContextMenu(QPoint globalPos)
{
    QMenu menu(this);
    menu.setObjectName(QStringLiteral("diagramContextMenu"));
    menu.addActions(contextMenuActions());
    menu.exec(globalPos);
    updateActionStates();
}

void DiagramEditor::contextMenuEvent(QContextMenuEvent *event)
{
    openContextMenu(event->reason() == QContextMenuEvent::Keyboard ? selectionMenuPosition() : event->globalPos());
    event->accept();
}

void DiagramEditor::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    // A view scrolls to the middle of its scene when it is first laid out; a body is read from
    // the top left, where its first network or initial step is.
    if (!m_shownOnce) {
        m_shownOnce = true;
        m_view->horizontalScrollBar()->setValue(m_view->horizontalScrollBar()->minimum());
        m_view->verticalScrollBar()->setValue(m_view->verticalScrollBar()->minimum());
    }
}

void DiagramEditor::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        for (const auto &entry : m_actions)
            translateAction(*entry);
        // A message was composed in the old language (with its arguments): it goes rather than
        // mixing two languages in one window.
        showMessage(QString());
        retranslate();
    }
    QWidget::changeEvent(event);
}

// ---- in-place text editing

InPlaceEditor *DiagramEditor::editTextInPlace(const QRectF &sceneRect, const QString &text,
    InPlaceEditor::Completion completion, const std::function<void(const QString &)> &commit)
{
    if (refuseWhileOnline())
        return nullptr;
    if (m_inPlace)
        m_inPlace->cancel();
    auto *editor = new InPlaceEditor(text, completion, m_completion, m_view->viewport());
    const QRect at = m_view->mapFromScene(sceneRect).boundingRect();
    const int height = std::max(24, at.height());
    editor->setGeometry(at.x(), at.center().y() - height / 2, std::max(160, at.width()), height);
    m_inPlace = editor;
    connect(editor, &InPlaceEditor::committed, this, [this, commit](const QString &value) {
        m_view->setFocus();
        commit(value);
    });
    connect(editor, &InPlaceEditor::cancelled, this, [this] { m_view->setFocus(); });
    editor->show();
    editor->setFocus();
    return editor;
}

// ---- view

void DiagramEditor::addHeaderWidget(QWidget *widget)
{
    m_layout->insertWidget(m_layout->indexOf(m_view), widget);
}

void DiagramEditor::zoomIn()
{
    m_view->zoomIn();
}

void DiagramEditor::zoomOut()
{
    m_view->zoomOut();
}

void DiagramEditor::resetZoom()
{
    m_view->resetZoom();
}

int DiagramEditor::zoomPercent() const
{
    return int(std::lround(m_view->zoom() * 100));
}

void DiagramEditor::fitToWindow()
{
    m_scene->rebuildIfDirty();
    // An editor not shown yet has not laid out its view: size the view as the layout will, so
    // that the view fits the drawing to that size (small drawings up to the largest zoom step).
    if (!isVisible())
        layout()->setGeometry(rect());
    m_view->fitToWindow();
}

QString DiagramEditor::exportTo(const QString &path)
{
    m_scene->rebuildIfDirty();
    return exportScene(*m_scene, path);
}

void DiagramEditor::exportInteractive()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Picture"), QString(),
        tr("SVG picture (*.svg);;PNG picture (*.png);;PDF document (*.pdf)"));
    if (path.isEmpty())
        return;
    if (const QString problem = exportTo(path); !problem.isEmpty())
        showError(problem);
}

void DiagramEditor::print()
{
    QPrinter printer;
    QPrintDialog dialog(&printer, this);
    if (dialog.exec() == QDialog::Accepted)
        printScene(*m_scene, printer);
}

void DiagramEditor::setGridSize(int size)
{
    m_view->setGridSize(size);
    m_scene->setGridSize(size);
}

} // namespace iec::editors
