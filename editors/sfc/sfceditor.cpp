#include "editors/sfc/sfceditor.h"

#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/sfc/sfcdialogs.h"
#include "editors/sfc/sfcgeometry.h"
#include "editors/sfc/sfcitems.h"
#include "editors/sfc/sfclayout.h"
#include "editors/sfc/sfcoverlay.h"
#include "editors/sfc/sfcplacement.h"
#include "editors/text/completion.h"
#include "interpreter/compiler/lexer.h"
#include "model/body.h"
#include "model/projectmodel.h"
#include "model/undo/bodyelementscommand.h"
#include "model/undo/partcommands.h"

#include <QInputDialog>
#include <QLabel>

namespace iec::editors::sfc {

using namespace model;

namespace {

// IEC 61131-3 lets a BOOL variable stand for an action: the POU's and the global ones.
QStringList booleanVariables(const CompletionProvider *provider)
{
    QStringList names;
    if (!provider)
        return names;
    for (const CompletionItem &item : provider->variables()) {
        if (item.detail.compare(QLatin1String("BOOL"), Qt::CaseInsensitive) == 0)
            names << item.text;
    }
    return names;
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

Body newChartBody()
{
    ChartDocument document = readChart({});
    createDefaultChart(document);
    wireChart(document);
    layoutChart(document);
    Body body = Body::withLanguage(BodyLanguage::SFC);
    *body.elements() = std::move(document.elements);
    return body;
}

SfcEditor::SfcEditor(ProjectModel &model, BodyRef ref, QUndoStack *undoStack, QWidget *parent)
    : DiagramEditor(model, std::move(ref), undoStack, std::make_unique<SfcPolicy>(), parent)
{
    setOverlayMapper(std::make_unique<SfcOverlayMapper>(sfcPolicy(),
        bodyRef().part == model::BodyRef::Part::Action ? bodyRef().name : QString()));
    m_levelLabel = new QLabel;
    m_levelLabel->setObjectName(QStringLiteral("sfcLevelLabel"));
    addHeaderWidget(m_levelLabel);
    createActions();
    connect(scene(), &QGraphicsScene::selectionChanged, this, [this] {
        const QList<quint64> ids = selection();
        if (ids.size() == 1)
            m_shiftAnchor = ids.front();
    });
    updateLevelLabel();
    if (const Pou *pou = model.project().findPou(bodyRef().pou))
        setOnlineInstance(pou->kind == PouKind::Program ? pou->name : QString());
}

SfcEditor::~SfcEditor() = default;

// ---- reading the chart

ChartDocument SfcEditor::document() const
{
    const std::vector<Element> *elements = scene()->shownElements();
    return readChart(elements ? *elements : std::vector<Element> {});
}

quint64 SfcEditor::stepId(const QString &name) const
{
    return document().stepNamed(name).value_or(0);
}

// ---- the edit path

ElementEdit SfcEditor::chartEdit(const ChartEdit &change, std::vector<quint64> selection) const
{
    return [this, change, selection = std::move(selection)](std::vector<Element> &elements) {
        const ChartDocument before = readChart(elements);
        ChartDocument edited = before;
        EditResult result = change(edited, selection);
        if (!result.ok())
            return result;
        wireChart(edited);
        placeLevel(before, edited);
        elements = std::move(edited.elements);
        return result;
    };
}

bool SfcEditor::edit(const QString &undoText, const ChartEdit &change)
{
    const std::vector<quint64> selected = selectedIds();
    const bool done = applyEdit(undoText, chartEdit(change, selected));
    if (done && !selection().isEmpty())
        m_shiftAnchor = selection().front();
    return done;
}

void SfcEditor::placeLevel(const ChartDocument &before, ChartDocument &edited) const
{
    // A chart imported without positions stays in the automatic layout; any other keeps the
    // positions it has and only the edited part is placed.
    const Body *body = projectModel().body(bodyRef());
    if (macroPath().empty() && body && body->layoutGenerated)
        layoutChart(edited);
    else
        placeEdit(before, edited);
}

std::vector<Element> SfcEditor::bodyElementsFor(std::vector<Element> shown) const
{
    const Body *body = projectModel().body(bodyRef());
    if (!body || !body->elements())
        return shown;
    return withLevel(*body->elements(), macroPath(), std::move(shown));
}

bool SfcEditor::arrangeChart()
{
    const std::vector<quint64> selected = selectedIds();
    return applyEdit(tr("Arrange chart"), [&](std::vector<Element> &elements) -> EditResult {
        ChartDocument doc = readChart(elements);
        if (doc.chart.isEmpty())
            return {tr("The chart is empty: there is nothing to arrange."), {}};
        layoutChart(doc);
        elements = std::move(doc.elements);
        return {{}, selected};
    });
}

bool SfcEditor::openStepAction(quint64 id, const QString &which)
{
    const std::optional<StepProperties> properties = stepProperties(document(), id);
    if (!properties) {
        showError(tr("Select a step first."));
        return false;
    }
    QString StepOptions::*field = which == QLatin1String("entry") ? &StepOptions::entryAction
        : which == QLatin1String("exit")                          ? &StepOptions::exitAction
                                                                  : &StepOptions::activeAction;
    StepProperties named = *properties;
    if ((named.options.*field).isEmpty())
        named.options.*field = properties->name + QLatin1Char('_') + which;
    const QString name = named.options.*field;
    if (!changeStep(id, named, tr("Add %1 action %2").arg(which, name)))
        return false;
    Q_EMIT openPartRequested(bodyRef().pou, BodyRef::Part::Action, name);
    return true;
}

QString SfcEditor::stepChangeProblem(quint64 id, const StepProperties &changed) const
{
    ChartDocument copy = document();
    return sfc::setStepProperties(copy, id, changed).error;
}

bool SfcEditor::changeStep(quint64 id, const StepProperties &changed, const QString &undoText)
{
    const std::optional<StepProperties> before = stepProperties(document(), id);
    if (!before) {
        showError(tr("Select a step first."));
        return false;
    }
    // One gesture: the POU actions the step names and does not find (in ST, as CODESYS creates
    // them from the step), and the step's new properties.
    auto gesture = std::make_unique<QUndoCommand>(undoText);
    QStringList created;
    for (const QString &name : stepActionNames(changed.options)) {
        if (created.contains(name, Qt::CaseInsensitive) || !interp::isIecIdentifier(name)
            || projectModel().findPouPart(bodyRef().pou, BodyRef::Part::Action, name))
            continue;
        created << name;
        PouPart part;
        part.name = name;
        part.body = Body::withLanguage(BodyLanguage::ST);
        new AddPouPartCommand(projectModel(), bodyRef().pou, BodyRef::Part::Action, part, gesture.get());
    }
    if (!(changed == *before)) {
        std::vector<Element> after;
        const EditResult result = prepareEdit(
            chartEdit([&](ChartDocument &doc, const auto &) { return sfc::setStepProperties(doc, id, changed); }, {}), after);
        if (!result.ok()) {
            showError(result.error);
            return false;
        }
        new SetBodyElementsCommand(projectModel(), bodyRef(), std::move(after), undoText, gesture.get());
    }
    if (gesture->childCount() == 0)
        return true;
    return pushCommand(gesture.release(), {id});
}

// ---- macro steps

bool SfcEditor::enterMacro(quint64 macroId)
{
    const ChartDocument doc = document();
    const Element *e = doc.element(macroId);
    if (!e || !std::holds_alternative<MacroStep>(*e)) {
        showError(tr("Select a macro step first."));
        return false;
    }
    std::vector<quint64> path = macroPath();
    path.push_back(macroId);
    sfcPolicy().setMacroPath(path);
    scene()->rebuild();
    updateLevelLabel();
    return true;
}

bool SfcEditor::leaveMacro()
{
    std::vector<quint64> path = macroPath();
    if (path.empty())
        return false;
    const quint64 macro = path.back();
    path.pop_back();
    sfcPolicy().setMacroPath(path);
    scene()->rebuild();
    updateLevelLabel();
    select({macro});
    return true;
}

void SfcEditor::updateLevelLabel()
{
    const bool nested = !macroPath().empty();
    m_levelLabel->setVisible(nested);
    updateActionStates();
    if (!nested)
        return;
    QStringList names;
    const Body *body = projectModel().body(bodyRef());
    std::vector<quint64> prefix;
    for (quint64 id : macroPath()) {
        const std::vector<Element> *level = body ? levelElements(*body->elements(), prefix) : nullptr;
        const ChartDocument doc = readChart(level ? *level : std::vector<Element> {});
        names << doc.stepName(id);
        prefix.push_back(id);
    }
    m_levelLabel->setText(tr("Inside macro step %1").arg(names.join(QStringLiteral(" › "))));
}

void SfcEditor::retranslate()
{
    updateLevelLabel();
}

// ---- mouse and keys

void SfcEditor::extendSelection(quint64 localId)
{
    ChartDocument doc = document();
    const quint64 anchor = m_shiftAnchor ? m_shiftAnchor : localId;
    const std::vector<quint64> range = connectedRange(doc, anchor, localId);
    const quint64 keep = m_shiftAnchor;
    scene()->selectLocalIds(QList<quint64>(range.begin(), range.end()));
    m_shiftAnchor = keep;
}

void SfcEditor::activateElement(quint64 localId, QPointF scenePos)
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
        auto *item = dynamic_cast<StepItem *>(scene()->itemFor(localId));
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
            if (!projectModel().findPouPart(bodyRef().pou, BodyRef::Part::Transition, name) && !isOnline()) {
                PouPart part;
                part.name = name;
                part.body = Body::withLanguage(BodyLanguage::ST);
                part.body.setText(QStringLiteral("FALSE"));
                pushCommand(new AddPouPartCommand(projectModel(), bodyRef().pou, BodyRef::Part::Transition, part));
            }
            Q_EMIT openPartRequested(bodyRef().pou, BodyRef::Part::Transition, name);
        } else {
            editConditionInPlace(localId);
        }
        return;
    }
    if (const auto *block = std::get_if<ActionBlock>(e)) {
        auto *item = dynamic_cast<ActionBlockItem *>(scene()->itemFor(localId));
        const int row = item ? item->rowAt(scenePos) : -1;
        if (row >= 0 && block->actions[std::size_t(row)].reference) {
            const QString name = block->actions[std::size_t(row)].reference->name;
            if (projectModel().findPouPart(bodyRef().pou, BodyRef::Part::Action, name)) {
                Q_EMIT openPartRequested(bodyRef().pou, BodyRef::Part::Action, name);
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
    const ChartDocument doc = document();
    const auto *transition = doc.element(transitionId) ? std::get_if<Transition>(doc.element(transitionId)) : nullptr;
    if (!transition)
        return;
    QString text;
    if (transition->condition && std::holds_alternative<InlineCondition>(transition->condition->kind))
        text = std::get<InlineCondition>(transition->condition->kind).body->text();
    else
        text = conditionText(*transition);
    const QRectF frame = elementRect(*doc.element(transitionId));
    const QRectF line(frame.right() + kLabelGap - 2, frame.center().y() - 11, 260, 22);
    InPlaceEditor *editor = editTextInPlace(line, text, InPlaceEditor::Completion::Names, [this, transitionId](const QString &value) {
        // A bare name of an existing transition part refers to it; anything else is inline ST.
        if (partNames(projectModel(), bodyRef().pou, false).contains(value, Qt::CaseInsensitive))
            edit(tr("Change condition"), [&](ChartDocument &d, const auto &) { return setConditionReference(d, transitionId, value); });
        else
            edit(tr("Change condition"), [&](ChartDocument &d, const auto &) { return setInlineCondition(d, transitionId, value); });
    });
    if (editor)
        editor->setToolTip(tr("An ST expression, or the name of a transition of the POU. Enter applies, Esc cancels."));
}

void SfcEditor::editStepDialog(quint64 stepId)
{
    if (refuseWhileOnline())
        return;
    const std::optional<StepProperties> properties = stepProperties(document(), stepId);
    if (!properties)
        return;
    // A refusal (a duplicate name, ...) is shown in the dialog, which keeps what was typed.
    StepPropertiesDialog dialog(*properties, partNames(projectModel(), bodyRef().pou, true),
        [this, stepId](const StepProperties &changed) { return stepChangeProblem(stepId, changed); }, this);
    if (dialog.exec() == QDialog::Accepted)
        changeStep(stepId, dialog.properties(), tr("Change step"));
}

void SfcEditor::editActionsDialog(quint64 stepId)
{
    if (refuseWhileOnline())
        return;
    ActionAssociationsDialog dialog(
        stepActions(document(), stepId), partNames(projectModel(), bodyRef().pou, true), booleanVariables(completionProvider()), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const std::vector<ActionBlockAction> actions = dialog.actions();
    edit(tr("Change actions"), [&](ChartDocument &edited, const auto &) {
        EditResult result {{}, {stepId}};
        while (!stepActions(edited, stepId).empty() && result.ok())
            result = sfc::removeAction(edited, stepId, 0);
        for (const ActionBlockAction &action : actions) {
            if (result.ok())
                result = sfc::addAction(edited, stepId, action);
        }
        return result;
    });
}

void SfcEditor::editPriorityDialog(quint64 transitionId)
{
    const ChartDocument doc = document();
    const auto &current = std::get<Transition>(*doc.element(transitionId)).priority;
    bool ok = false;
    // 0 removes the priority: alternative branches are then tried from left to right.
    const int value = QInputDialog::getInt(this, tr("Transition Priority"),
        tr("Priority (0: none, branches are tried from left to right):"), int(current.value_or(0)), 0, 9999, 1, &ok);
    if (!ok)
        return;
    const std::optional<quint64> priority = value > 0 ? std::optional<quint64>(quint64(value)) : std::nullopt;
    edit(tr("Change priority"), [&](ChartDocument &d, const auto &) { return setPriority(d, transitionId, priority); });
}

void SfcEditor::chooseJumpTarget(bool withTransition)
{
    if (refuseWhileOnline())
        return;
    const QStringList names = stepNames(document());
    if (names.isEmpty()) {
        showError(tr("The chart has no step to jump to."));
        return;
    }
    bool ok = false;
    const QString target = QInputDialog::getItem(this, tr("Jump"), tr("Jump to step:"), names, 0, false, &ok);
    if (!ok)
        return;
    if (withTransition)
        edit(tr("Insert transition-jump"), [&](ChartDocument &d, const auto &s) { return insertTransitionJump(d, s, target); });
    else
        edit(tr("Insert jump"), [&](ChartDocument &d, const auto &s) { return insertJump(d, s, target); });
}

QString SfcEditor::placeName(qint64 localId) const
{
    if (localId < 0)
        return {};
    const ChartDocument chart = document();
    const model::Element *element = chart.element(quint64(localId));
    if (!element)
        return {};
    if (const auto *step = std::get_if<model::Step>(element))
        return tr("step %1").arg(step->name);
    // A transition or an action block is named by the step wired into it.
    QString before;
    for (const model::ConnectionPointIn *point : model::inputPoints(*element))
        for (const model::Connection &c : point->connections)
            if (before.isEmpty())
                before = chart.stepName(c.refLocalId);
    if (std::holds_alternative<model::Transition>(*element))
        return before.isEmpty() ? tr("a transition") : tr("the transition after %1").arg(before);
    if (std::holds_alternative<model::ActionBlock>(*element))
        return before.isEmpty() ? tr("an action block") : tr("the actions of %1").arg(before);
    return {};
}

} // namespace iec::editors::sfc
