#include "editors/cfc/cfceditor.h"

#include "editors/cfc/cfcoverlay.h"
#include "editors/cfc/cfcscene.h"
#include "editors/cfc/cfcstorage.h"
#include "editors/common/boxspec.h"
#include "editors/common/diagramclipboard.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/text/completion.h"
#include "model/projectmodel.h"
#include "model/undo/elementcommands.h"

#include <QGraphicsSceneMouseEvent>
#include <QInputDialog>

namespace iec::editors::cfc {

using namespace model;

namespace {

// The text of an element the user types: a variable, an instance (a box's type when it has
// none), a label, a jump's target, a mark's name, a comment.
QString textOf(const Element &e)
{
    return std::visit([](const auto &x) -> QString {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, InVariable> || std::is_same_v<T, OutVariable> || std::is_same_v<T, InOutVariable>)
            return x.expression;
        else if constexpr (std::is_same_v<T, Block>)
            return x.instanceName.value_or(x.typeName);
        else if constexpr (std::is_same_v<T, Label> || std::is_same_v<T, Jump>)
            return x.label;
        else if constexpr (std::is_same_v<T, Connector> || std::is_same_v<T, Continuation>)
            return x.name;
        else if constexpr (std::is_same_v<T, Comment>)
            return x.content.text;
        else
            return QString();
    }, e);
}

void setTextOf(Element &e, const QString &text)
{
    std::visit([&](auto &x) {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, InVariable> || std::is_same_v<T, OutVariable> || std::is_same_v<T, InOutVariable>)
            x.expression = text;
        else if constexpr (std::is_same_v<T, Block>) {
            if (x.instanceName)
                x.instanceName = text;
        } else if constexpr (std::is_same_v<T, Label> || std::is_same_v<T, Jump>)
            x.label = text;
        else if constexpr (std::is_same_v<T, Connector> || std::is_same_v<T, Continuation>)
            x.name = text;
        else if constexpr (std::is_same_v<T, Comment>)
            x.content.text = text;
    }, e);
}

bool isIdentifierPath(const QString &text)
{
    const QString t = text.trimmed();
    if (t.isEmpty() || !(t.front().isLetter() || t.front() == QLatin1Char('_')))
        return false;
    return std::ranges::all_of(t, [](QChar c) { return c.isLetterOrNumber() || c == QLatin1Char('_') || c == QLatin1Char('.'); });
}

} // namespace

CfcEditor::CfcEditor(ProjectModel &model, BodyRef ref, QUndoStack *undoStack, QWidget *parent)
    : DiagramEditor(model, std::move(ref), undoStack, std::make_unique<CfcPolicy>(), parent)
{
    auto overlay = std::make_unique<CfcOverlayMapper>(cfcPolicy());
    m_overlay = overlay.get();
    setOverlayMapper(std::move(overlay));
    createActions();
    scene()->installEventFilter(this);
    sceneRefreshed();
}

CfcEditor::~CfcEditor() = default;

const CfcPolicy &CfcEditor::cfcPolicy() const
{
    return static_cast<const CfcPolicy &>(policy());
}

const std::vector<Element> &CfcEditor::elements() const
{
    static const std::vector<Element> none;
    const std::vector<Element> *shown = scene()->shownElements();
    return shown ? *shown : none;
}

const Element *CfcEditor::element(quint64 localId) const
{
    for (const Element &e : elements())
        if (header(e).localId == localId)
            return &e;
    return nullptr;
}

quint64 CfcEditor::elementNamed(const QString &name) const
{
    for (const Element &e : elements()) {
        if (textOf(e).compare(name, Qt::CaseInsensitive) == 0)
            return header(e).localId;
        if (const auto *block = std::get_if<Block>(&e); block && block->typeName.compare(name, Qt::CaseInsensitive) == 0)
            return header(e).localId;
    }
    return 0;
}

void CfcEditor::setInsertPosition(QPointF scenePos)
{
    m_insertAt = QPointF(std::max(0.0, scenePos.x()), std::max(0.0, scenePos.y()));
}

void CfcEditor::sceneRefreshed()
{
    if (const QString error = cfcPolicy().readError(); !error.isEmpty())
        showMessage(tr("This CFC diagram cannot be shown: %1").arg(error));
}

// ---- the storage

QUndoCommand *CfcEditor::elementsCommand(std::vector<Element> after, const QString &undoText)
{
    const Body *body = projectModel().body(bodyRef());
    if (!body || cfcPolicy().storage() != CfcStorage::Codesys) {
        writeCfcSizes(after, elements());
        return DiagramEditor::elementsCommand(std::move(after), undoText);
    }
    AddData addData = body->addData;
    addData[std::size_t(codesysCfcEntry(*body))].content = writeCodesysCfc(after);
    return new SetBodyAddDataCommand(projectModel(), bodyRef(), std::move(addData), undoText);
}

// ---- mouse gestures

void CfcEditor::moveElements(const QList<quint64> &localIds, const QList<QPointF> &positions)
{
    const std::vector<quint64> ids(localIds.begin(), localIds.end());
    const std::vector<QPointF> to(positions.begin(), positions.end());
    if (!applyEdit(tr("Move"), [&](std::vector<Element> &e) { return cfc::moveElements(e, ids, to); }))
        scene()->rebuild(); // the items go back where the model has them
}

void CfcEditor::connectWire(quint64 source, const QString &formalParameter, quint64 target, int inputIndex)
{
    const std::optional<QString> output = formalParameter.isEmpty() ? std::nullopt : std::optional<QString>(formalParameter);
    applyEdit(tr("Connect"), [&](std::vector<Element> &e) { return connectPins(e, source, output, target, inputIndex); });
}

bool CfcEditor::eventFilter(QObject *watched, QEvent *event)
{
    // New elements go where the mouse last pressed on the sheet.
    if (watched == scene() && event->type() == QEvent::GraphicsSceneMousePress) {
        const auto *mouse = static_cast<QGraphicsSceneMouseEvent *>(event);
        if (!scene()->diagramItemAt(mouse->scenePos()))
            setInsertPosition(mouse->scenePos());
    }
    return DiagramEditor::eventFilter(watched, event);
}

void CfcEditor::navigate(Qt::Key key)
{
    // The arrow keys move the selection (by the grid, or 10 units without one). CODESYS's form
    // keeps positions on its own grid: a smaller step would be rounded back, and Left or Up would
    // never move.
    const std::vector<quint64> ids = selectedIds();
    if (ids.empty()) {
        DiagramEditor::navigate(key);
        return;
    }
    const double step = cfcPolicy().storage() == CfcStorage::Codesys ? kCodesysGrid
        : scene()->gridSize() > 0                                    ? scene()->gridSize()
                                                                     : 10;
    const QPointF by(key == Qt::Key_Left ? -step : key == Qt::Key_Right ? step : 0,
        key == Qt::Key_Up ? -step : key == Qt::Key_Down ? step : 0);
    applyEdit(tr("Move"), [&](std::vector<Element> &e) { return nudgeElements(e, ids, by); });
}

bool CfcEditor::dropPou(const QString &typeName, QPointF scenePos)
{
    setInsertPosition(scenePos);
    return insertBox(typeName);
}

bool CfcEditor::dropInsertAction(const QString &actionId, QPointF scenePos)
{
    QAction *dropped = action(actionId);
    if (!dropped || !insertActions().contains(dropped))
        return false;
    setInsertPosition(scenePos);
    return trigger(actionId);
}

// ---- inserting

bool CfcEditor::insert(const QString &undoText, Element element, bool typeAfterwards)
{
    const QPointF at = m_insertAt;
    const double height = cfcRect(element).height();
    if (!applyEdit(undoText, [&](std::vector<Element> &e) { return insertElement(e, std::move(element), at); }))
        return false;
    // The next element goes below this one, as a column builds up.
    m_insertAt = at + QPointF(0, height + 20);
    if (typeAfterwards)
        startTyping();
    return true;
}

bool CfcEditor::insertBox(const QString &typeName, bool withEn)
{
    QString error;
    std::optional<BoxSpec> spec = boxSpecFor(projectModel().project(), typeName, withEn, &error);
    if (!spec) {
        showError(error);
        return false;
    }
    spec->withEn = withEn; // CFC passes data: EN/ENO only when asked for
    const bool functionBlock = spec->functionBlock;
    if (!insert(tr("Insert %1").arg(spec->typeName), blockFromSpec(*spec), false))
        return false;
    // The seed's workflow: a new box is AND, and typing over its keyword makes it another; a
    // function block wants its instance name first.
    if (functionBlock || typeName.compare(QLatin1String("AND"), Qt::CaseInsensitive) == 0)
        startTyping(!functionBlock);
    return true;
}

bool CfcEditor::insertInput()
{
    InVariable variable;
    variable.expression = kPlaceholder;
    variable.connectionPointOut.emplace();
    return insert(tr("Insert input"), variable, true);
}

bool CfcEditor::insertOutput()
{
    OutVariable variable;
    variable.expression = kPlaceholder;
    variable.connectionPointIn.emplace();
    return insert(tr("Insert output"), variable, true);
}

bool CfcEditor::insertJump()
{
    Jump jump;
    jump.label = kPlaceholder;
    jump.connectionPointIn.emplace();
    return insert(tr("Insert jump"), jump, true);
}

bool CfcEditor::insertLabel()
{
    Label label;
    label.label = kPlaceholder;
    return insert(tr("Insert label"), label, true);
}

bool CfcEditor::insertReturn()
{
    Return ret;
    ret.connectionPointIn.emplace();
    return insert(tr("Insert return"), ret, false);
}

bool CfcEditor::insertComment(const QString &text)
{
    Comment comment;
    comment.content.text = text;
    return insert(tr("Insert comment"), comment, false);
}

bool CfcEditor::insertConnector()
{
    Connector connector;
    connector.name = kPlaceholder;
    connector.connectionPointIn.emplace();
    return insert(tr("Insert connection mark"), connector, true);
}

bool CfcEditor::insertContinuation()
{
    Continuation continuation;
    continuation.name = kPlaceholder;
    continuation.connectionPointOut.emplace();
    return insert(tr("Insert connection mark"), continuation, true);
}

// ---- changing elements

bool CfcEditor::setElementText(quint64 localId, const QString &text)
{
    return applyEdit(tr("Rename"), [&](std::vector<Element> &elements) -> EditOutcome {
        for (Element &e : elements)
            if (header(e).localId == localId) {
                setTextOf(e, text);
                return {{}, {localId}};
            }
        return {tr("The element is gone."), {}};
    });
}

bool CfcEditor::changeBoxType(quint64 box, const QString &typeName)
{
    const auto *old = std::get_if<Block>(element(box));
    return old && rebuildBox(box, typeName, hasEnEno(*old), tr("Change box to %1"));
}

bool CfcEditor::toggleEnEno()
{
    const std::vector<quint64> ids = selectedIds();
    const auto *old = ids.size() == 1 ? std::get_if<Block>(element(ids.front())) : nullptr;
    if (!old) {
        showError(tr("Select a box to give it EN/ENO or take them away."));
        return false;
    }
    return rebuildBox(ids.front(), old->typeName, !hasEnEno(*old), hasEnEno(*old) ? tr("Remove EN/ENO from %1") : tr("Add EN/ENO to %1"));
}

bool CfcEditor::hasEnEno(const Block &box)
{
    return !box.inputVariables.empty() && box.inputVariables.front().formalParameter.compare(QLatin1String("EN"), Qt::CaseInsensitive) == 0;
}

// The box built again for `typeName` (with EN/ENO when asked), keeping its wires (replaceBlock).
bool CfcEditor::rebuildBox(quint64 box, const QString &typeName, bool withEn, const QString &undoText)
{
    const auto *old = std::get_if<Block>(element(box));
    if (!old)
        return false;
    QString error;
    std::optional<BoxSpec> spec = boxSpecFor(projectModel().project(), typeName, withEn, &error);
    if (!spec) {
        showError(error);
        return false;
    }
    spec->withEn = withEn;
    Block fresh = blockFromSpec(*spec);
    const bool needsInstance = spec->functionBlock && (!old->instanceName || *old->instanceName == kPlaceholder);
    if (!applyEdit(undoText.arg(spec->typeName), [&](std::vector<Element> &e) { return replaceBlock(e, box, std::move(fresh)); }))
        return false;
    if (needsInstance)
        startTyping();
    return true;
}

bool CfcEditor::toggleNegation()
{
    const std::vector<quint64> ids = selectedIds();
    return applyEdit(tr("Negate"), [&](std::vector<Element> &elements) -> EditOutcome {
        bool any = false;
        for (Element &e : elements) {
            if (std::ranges::find(ids, header(e).localId) == ids.end())
                continue;
            if (auto *in = std::get_if<InVariable>(&e))
                in->negated = !in->negated, any = true;
            else if (auto *out = std::get_if<OutVariable>(&e))
                out->negated = !out->negated, any = true;
        }
        if (!any)
            return {tr("Select an input or an output to negate."), {}};
        return {{}, ids};
    });
}

bool CfcEditor::deleteSelection()
{
    const std::vector<quint64> ids = selectedIds();
    return applyEdit(tr("Delete"), [&](std::vector<Element> &e) { return deleteElements(e, ids); });
}

bool CfcEditor::copy()
{
    const std::vector<quint64> ids = selectedIds();
    std::vector<Element> fragment;
    for (const Element &e : elements())
        if (std::ranges::find(ids, header(e).localId) != ids.end())
            fragment.push_back(e);
    if (fragment.empty()) {
        showError(tr("Select the elements to copy first."));
        return false;
    }
    copyElementsToClipboard(EditorLanguage::CFC, fragment);
    return true;
}

bool CfcEditor::cut()
{
    if (refuseWhileOnline())
        return false;
    return copy() && deleteSelection();
}

bool CfcEditor::paste()
{
    quint64 firstFree = 1;
    for (const Element &e : elements())
        firstFree = std::max(firstFree, header(e).localId + 1);
    PastedElements pasted = elementsFromClipboard(EditorLanguage::CFC, firstFree);
    if (!pasted.ok()) {
        showError(pasted.error);
        return false;
    }
    const QPointF at = m_insertAt;
    return applyEdit(tr("Paste"), [&](std::vector<Element> &e) { return insertElements(e, std::move(pasted.elements), at); });
}

// ---- execution order

bool CfcEditor::orderByDataFlow()
{
    return applyEdit(tr("Order by data flow"), [](std::vector<Element> &e) { return cfc::orderByDataFlow(e); });
}

bool CfcEditor::orderByTopology()
{
    return applyEdit(tr("Order by topology"), [](std::vector<Element> &e) { return cfc::orderByTopology(e); });
}

bool CfcEditor::moveInOrder(OrderMove move)
{
    const std::vector<quint64> ids = selectedIds();
    return applyEdit(tr("Change execution order"), [&](std::vector<Element> &e) { return cfc::moveInOrder(e, ids, move); });
}

bool CfcEditor::setOrderNumber(quint64 localId, int number)
{
    return applyEdit(tr("Set execution order"), [&](std::vector<Element> &e) { return cfc::setOrderNumber(e, localId, number); });
}

bool CfcEditor::selectionRuns() const
{
    for (quint64 id : selectedIds())
        if (const Element *e = element(id); e && runsInOrder(*e))
            return true;
    return false;
}

void CfcEditor::askOrderNumber()
{
    if (refuseWhileOnline())
        return;
    const std::vector<quint64> ids = selectedIds();
    const Element *e = ids.size() == 1 ? element(ids.front()) : nullptr;
    if (!e || !runsInOrder(*e)) {
        showError(tr("Select one element that has an execution order number."));
        return;
    }
    const int count = int(executionOrder(elements()).size());
    bool ok = false;
    const int number = QInputDialog::getInt(this, tr("Execution Order"), tr("Number of this element (1 to %1):").arg(count),
        int(header(*e).executionOrderId.value_or(1)), 1, count, 1, &ok);
    if (ok)
        setOrderNumber(ids.front(), number);
}

void CfcEditor::askComment()
{
    if (refuseWhileOnline())
        return;
    bool ok = false;
    const QString text = QInputDialog::getMultiLineText(this, tr("Insert Comment"), tr("Comment:"), QString(), &ok);
    if (ok && !text.trimmed().isEmpty())
        insertComment(text);
}

// ---- typing

void CfcEditor::startTyping(bool boxType)
{
    const std::vector<quint64> ids = selectedIds();
    const Element *e = ids.size() == 1 ? element(ids.front()) : nullptr;
    if (!e || std::holds_alternative<Return>(*e))
        return;
    const quint64 id = ids.front();
    const QRectF rect = cfcRect(*e);
    if (const auto *block = std::get_if<Block>(e); block && (boxType || !block->instanceName)) {
        const QRectF title(rect.left(), rect.top(), std::max(120.0, rect.width()), 20);
        editTextInPlace(title, block->typeName, InPlaceEditor::Completion::BlockTypes, [this, id](const QString &text) {
            const auto *now = std::get_if<Block>(element(id));
            if (!text.isEmpty() && now && text.compare(now->typeName, Qt::CaseInsensitive) != 0)
                changeBoxType(id, text);
        });
        return;
    }
    QRectF where = rect;
    if (std::holds_alternative<Block>(*e))
        where = QRectF(rect.left(), rect.top() - 18, std::max(120.0, rect.width()), 18); // the instance name
    const bool names = !std::holds_alternative<Comment>(*e);
    editTextInPlace(where, textOf(*e), names ? InPlaceEditor::Completion::Names : InPlaceEditor::Completion::None,
        [this, id](const QString &text) {
            const Element *now = element(id);
            if (text.isEmpty() || !now || text == textOf(*now))
                return;
            if (setElementText(id, text))
                offerDeclaration(id);
        });
}

bool CfcEditor::offerDeclaration(quint64 localId)
{
    const CompletionProvider *names = completionProvider();
    const Element *e = element(localId);
    if (!names || !e)
        return false;
    const QString text = textOf(*e).trimmed();
    if (!isIdentifierPath(text) || text == kPlaceholder || text.compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0
        || text.compare(QLatin1String("FALSE"), Qt::CaseInsensitive) == 0)
        return false;
    const bool variableLike = std::holds_alternative<InVariable>(*e) || std::holds_alternative<OutVariable>(*e)
        || std::holds_alternative<InOutVariable>(*e) || (std::holds_alternative<Block>(*e) && std::get<Block>(*e).instanceName);
    const QString head = text.section(QLatin1Char('.'), 0, 0);
    if (!variableLike || !names->typeOf(head).isEmpty())
        return false;
    for (const CompletionItem &item : names->variables())
        if (item.text.compare(head, Qt::CaseInsensitive) == 0)
            return false;
    Q_EMIT declareVariableRequested(bodyRef(), head);
    return true;
}

void CfcEditor::activateElement(quint64 localId, QPointF scenePos)
{
    if (isOnline()) {
        prepareValue(localId);
        return;
    }
    select({localId});
    const Element *e = element(localId);
    // A double-click on a box's title row changes its type; elsewhere its instance name.
    const bool onTitle = e && std::holds_alternative<Block>(*e) && scenePos.y() < cfcRect(*e).top() + 20;
    startTyping(onTitle);
}

void CfcEditor::prepareValue(quint64 localId)
{
    const QString name = m_overlay->variableName(*scene(), localId, onlineInstance());
    const Element *e = element(localId);
    if (name.isEmpty() || !e || !(std::holds_alternative<InVariable>(*e) || std::holds_alternative<OutVariable>(*e)))
        return;
    if (const std::optional<QString> literal = askValueToPrepare(name, m_overlay->value(name)))
        announcePrepared(name, *literal);
}

QString CfcEditor::placeName(qint64 localId) const
{
    const model::Element *shown = localId < 0 ? nullptr : element(quint64(localId));
    if (!shown)
        return {};
    int number = model::header(*shown).executionOrderId.value_or(0);
    if (number <= 0) {
        const std::vector<quint64> order = executionOrder(elements());
        const auto at = std::ranges::find(order, quint64(localId));
        number = at == order.end() ? 0 : int(at - order.begin()) + 1;
    }
    if (const auto *box = std::get_if<model::Block>(shown))
        return tr("box %1 (%2)").arg(number).arg(box->typeName);
    if (const auto *out = std::get_if<model::OutVariable>(shown))
        return tr("output %1 (%2)").arg(number).arg(out->expression);
    return tr("element %1").arg(number);
}

} // namespace iec::editors::cfc
