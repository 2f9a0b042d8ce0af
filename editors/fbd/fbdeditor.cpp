#include "editors/fbd/fbdeditor.h"

#include "editors/common/boxspec.h"
#include "editors/common/diagramclipboard.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/common/networkdialogs.h"
#include "editors/fbd/fbdoverlay.h"
#include "editors/fbd/fbdscene.h"
#include "editors/fbd/fbdwrite.h"
#include "editors/text/completion.h"
#include "interpreter/runtime/snapshot.h"
#include "model/projectmodel.h"

#include <QGraphicsRectItem>
#include <QGraphicsSceneMouseEvent>

namespace iec::editors::fbd {

using namespace model;
using Kind = FbdCursor::Kind;

namespace {

bool isIdentifierPath(const QString &text)
{
    const QString t = text.trimmed();
    if (t.isEmpty() || !(t.front().isLetter() || t.front() == QLatin1Char('_')))
        return false;
    return std::ranges::all_of(t, [](QChar c) { return c.isLetterOrNumber() || c == QLatin1Char('_') || c == QLatin1Char('.'); });
}

// The cursor's dotted frame. A rebuild of the scene deletes it with every other item: it then
// tells the editor, which holds no dangling pointer.
class CursorFrame : public QGraphicsRectItem
{
public:
    CursorFrame(const QRectF &rect, QGraphicsRectItem **holder)
        : QGraphicsRectItem(rect)
        , m_holder(holder)
    {
        *holder = this;
        setAcceptedMouseButtons(Qt::NoButton); // clicks go to the element under it
    }
    ~CursorFrame() override
    {
        if (*m_holder == this)
            *m_holder = nullptr;
    }

private:
    QGraphicsRectItem **m_holder;
};

bool isKeywordLiteral(const QString &text)
{
    return text.compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0 || text.compare(QLatin1String("FALSE"), Qt::CaseInsensitive) == 0;
}

} // namespace

FbdEditor::FbdEditor(ProjectModel &model, BodyRef ref, QUndoStack *undoStack, QWidget *parent)
    : DiagramEditor(model, std::move(ref), undoStack, std::make_unique<FbdPolicy>(), parent)
{
    auto overlay = std::make_unique<FbdOverlayMapper>(fbdPolicy());
    m_overlay = overlay.get();
    setOverlayMapper(std::move(overlay));
    createActions();
    scene()->installEventFilter(this);
    m_cursor = validCursor(document(), FbdCursor::atNetwork(0));
    applyCursor();
}

FbdEditor::~FbdEditor()
{
    delete m_cursorFrame; // before the scene goes: the frame writes back into this editor
    scene()->removeEventFilter(this);
    scene()->disconnect(this);
}

FbdPolicy &FbdEditor::fbdPolicy() const
{
    return static_cast<FbdPolicy &>(policy());
}

const FbdDocument &FbdEditor::document() const
{
    scene()->rebuildIfDirty();
    return fbdPolicy().document();
}

const std::vector<FbdGeometry> &FbdEditor::layout() const
{
    scene()->rebuildIfDirty();
    return fbdPolicy().layout();
}

quint64 FbdEditor::elementNamed(const QString &name) const
{
    for (const Element &e : document().elements) {
        const quint64 id = header(e).localId;
        if (elementText(document(), id).compare(name, Qt::CaseInsensitive) == 0)
            return id;
    }
    return 0;
}

const Element *FbdEditor::cursorElement() const
{
    return m_cursor.element ? document().element(m_cursor.element) : nullptr;
}

bool FbdEditor::cursorIs(std::initializer_list<Kind> kinds) const
{
    return std::ranges::find(kinds, m_cursor.kind) != kinds.end() && !document().networks.empty();
}

// ---- the edit path

bool FbdEditor::edit(const QString &undoText, const std::function<FbdEditResult(FbdDocument &, const FbdCursor &)> &change)
{
    scene()->rebuildIfDirty();
    const FbdCursor at = m_cursor;
    std::optional<FbdCursor> next;
    const bool ok = applyRewrite(undoText, [&](const std::vector<Element> &elements, std::vector<Element> &after) -> EditOutcome {
        const FbdDocument &shown = fbdPolicy().document();
        FbdDocument doc;
        doc.elements.reserve(elements.size() + 64);
        if (shown.elements.size() == elements.size())
            doc = shown; // the scene is up to date
        else
            doc = readFbd(elements, fbdPolicy().layoutGenerated());
        const FbdEditResult result = change(doc, at);
        if (!result.ok())
            return {result.error, {}};
        writeFbd(doc);
        after = std::move(doc.elements);
        next = result.cursor;
        m_cursor = result.cursor; // the scene refresh draws it
        return {{}, {}};
    });
    if (ok && next)
        setCursor(*next);
    return ok;
}

// ---- the cursor

void FbdEditor::setCursor(const FbdCursor &cursor)
{
    m_cursor = validCursor(document(), cursor);
    applyCursor();
}

void FbdEditor::applyCursor()
{
    m_applyingCursor = true;
    delete m_cursorFrame;
    m_cursorFrame = nullptr;
    // Texts and boxes are elements: they are selected too (the context menu and Enter use it).
    QList<quint64> selected;
    if ((m_cursor.kind == Kind::Text || m_cursor.kind == Kind::Box) && m_cursor.element)
        selected << m_cursor.element;
    select(selected);
    fbdPolicy().setCurrentNetwork(m_cursor.kind == Kind::Network ? m_cursor.network : -1);
    const std::optional<QRectF> rect = cursorRect(fbdPolicy().layout(), m_cursor);
    if (rect && m_cursor.kind != Kind::Network) {
        // The dotted rectangle of CoDeSys 2.3 (seed 002 §2: "虚线矩形框").
        new CursorFrame(rect->adjusted(-2, -2, 2, 2), &m_cursorFrame);
        m_cursorFrame->setPen(QPen(kSelectionColor, 1, Qt::DotLine));
        m_cursorFrame->setZValue(6);
        scene()->addItem(m_cursorFrame);
    }
    if (rect)
        view()->ensureVisible(*rect, 40, 40);
    m_applyingCursor = false;
    updateActionStates();
}

void FbdEditor::sceneRefreshed()
{
    m_cursor = validCursor(document(), m_cursor);
    applyCursor();
}

void FbdEditor::navigate(Qt::Key key)
{
    const int dx = key == Qt::Key_Left ? -1 : key == Qt::Key_Right ? 1 : 0;
    const int dy = key == Qt::Key_Up ? -1 : key == Qt::Key_Down ? 1 : 0;
    setCursor(moveCursor(layout(), m_cursor, dx, dy));
}

bool FbdEditor::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == scene() && event->type() == QEvent::GraphicsSceneMousePress) {
        auto *mouse = static_cast<QGraphicsSceneMouseEvent *>(event);
        if (mouse->button() == Qt::LeftButton || mouse->button() == Qt::RightButton) {
            // The click picks the position under it (an input, an output, a crossing are smaller
            // than the element they belong to); the scene selects the element afterwards.
            if (const auto at = cursorAt(layout(), mouse->scenePos())) {
                setCursor(*at);
                if (at->kind != Kind::Text && at->kind != Kind::Box) {
                    scene()->clearSelection();
                    return mouse->button() == Qt::LeftButton; // no rubber band, no drag
                }
            }
        }
    }
    return DiagramEditor::eventFilter(watched, event);
}

bool FbdEditor::dropPou(const QString &typeName, QPointF scenePos)
{
    if (refuseWhileOnline())
        return false;
    if (document().networks.empty() && !insertNetwork(true))
        return false;
    if (const auto at = cursorAt(layout(), scenePos))
        setCursor(at->kind == Kind::Network ? FbdCursor::at(Kind::End, at->network) : *at);
    else
        setCursor(FbdCursor::at(Kind::End, int(document().networks.size()) - 1));
    if (m_cursor.kind == Kind::Box || m_cursor.kind == Kind::Text)
        setCursor(FbdCursor::at(Kind::End, m_cursor.network)); // a drop adds, it does not replace
    return insertOperator(typeName);
}

// ---- typing

void FbdEditor::startTyping()
{
    const Element *e = cursorElement();
    const std::optional<QRectF> rect = cursorRect(layout(), m_cursor);
    if (!e || !rect)
        return;
    const quint64 id = m_cursor.element;
    if (m_cursor.kind == Kind::Box) {
        // The box's keyword: another operator, function or function block; its wires stay.
        const auto &block = std::get<Block>(*e);
        const QRectF title(rect->left(), rect->top(), std::max(120.0, rect->width()), 20);
        editTextInPlace(title, block.typeName, InPlaceEditor::Completion::BlockTypes, [this, id](const QString &text) {
            const auto *now = std::get_if<Block>(document().element(id));
            if (!text.isEmpty() && now && text.compare(now->typeName, Qt::CaseInsensitive) != 0)
                changeBoxType(id, text);
        });
        return;
    }
    if (m_cursor.kind != Kind::Text)
        return;
    editTextInPlace(*rect, elementText(document(), id), InPlaceEditor::Completion::Names, [this, id](const QString &text) {
        if (text.isEmpty() || text == elementText(document(), id))
            return;
        if (setElementText(id, text))
            offerDeclaration(id);
    });
}

bool FbdEditor::offerDeclaration(quint64 localId)
{
    const CompletionProvider *names = completionProvider();
    const Element *e = document().element(localId);
    if (!names || !e)
        return false;
    const QString text = elementText(document(), localId).trimmed();
    if (!isIdentifierPath(text) || text == kPlaceholder || isKeywordLiteral(text))
        return false;
    const bool variableLike = std::holds_alternative<InVariable>(*e) || std::holds_alternative<OutVariable>(*e)
        || (std::holds_alternative<Block>(*e) && std::get<Block>(*e).instanceName);
    const QString head = text.section(QLatin1Char('.'), 0, 0);
    if (!variableLike || !names->typeOf(head).isEmpty())
        return false;
    for (const CompletionItem &item : names->variables())
        if (item.text.compare(head, Qt::CaseInsensitive) == 0)
            return false;
    Q_EMIT declareVariableRequested(bodyRef(), head);
    return true;
}

// ---- online

void FbdEditor::activateElement(quint64 localId, QPointF scenePos)
{
    if (isOnline()) {
        prepareValue(localId);
        return;
    }
    if (const auto at = cursorAt(layout(), scenePos); at && at->element == localId)
        setCursor(*at);
    else if (m_cursor.element != localId)
        setCursor(FbdCursor::at(Kind::Text, document().networkOf(localId), localId));
    startTyping();
}

void FbdEditor::prepareValue(quint64 localId)
{
    const QString name = m_overlay->variableName(localId, onlineInstance());
    const Element *e = document().element(localId);
    if (name.isEmpty() || !e || !(std::holds_alternative<InVariable>(*e) || std::holds_alternative<OutVariable>(*e)))
        return;
    if (const std::optional<QString> literal = askValueToPrepare(name, m_overlay->value(name)))
        announcePrepared(name, *literal);
}

// ---- commands

bool FbdEditor::insertNetwork(bool after)
{
    if (!edit(tr("Insert network"), [after](FbdDocument &d, const FbdCursor &c) { return fbd::insertNetwork(d, c, after); }))
        return false;
    startTyping();
    return true;
}

bool FbdEditor::insertOperator(const QString &typeName, bool withEn)
{
    QString error;
    std::optional<BoxSpec> spec = boxSpecFor(projectModel().project(), typeName, withEn, &error);
    if (!spec) {
        showError(error);
        return false;
    }
    spec->withEn = withEn; // FBD passes data, not a rung: EN/ENO only when asked for
    if (!edit(tr("Insert %1").arg(spec->typeName), [&](FbdDocument &d, const FbdCursor &c) { return fbd::insertOperator(d, c, *spec); }))
        return false;
    // The seed's workflow: a new operator is AND, and typing over its keyword makes it another.
    if (typeName.compare(QLatin1String("AND"), Qt::CaseInsensitive) == 0 && !withEn)
        startTyping();
    else if (spec->functionBlock) {
        setCursor(FbdCursor::at(Kind::Text, m_cursor.network, m_cursor.element)); // its instance name
        startTyping();
    }
    return true;
}

bool FbdEditor::changeBoxType(quint64 box, const QString &typeName)
{
    QString error;
    const auto *block = std::get_if<Block>(document().element(box));
    const bool withEn = block && !block->inputVariables.empty()
        && block->inputVariables.front().formalParameter.compare(QLatin1String("EN"), Qt::CaseInsensitive) == 0;
    std::optional<BoxSpec> spec = boxSpecFor(projectModel().project(), typeName, withEn, &error);
    if (!spec) {
        showError(error);
        return false;
    }
    spec->withEn = withEn;
    const int network = document().networkOf(box);
    if (!edit(tr("Change box to %1").arg(spec->typeName), [&](FbdDocument &d, const FbdCursor &) {
            return fbd::insertOperator(d, FbdCursor::at(Kind::Box, network, box), *spec);
        }))
        return false;
    if (spec->functionBlock) {
        setCursor(FbdCursor::at(Kind::Text, network, box));
        startTyping();
    }
    return true;
}

bool FbdEditor::insertInput()
{
    return edit(tr("Insert input"), [](FbdDocument &d, const FbdCursor &c) { return fbd::insertInput(d, c); });
}

bool FbdEditor::insertOutput()
{
    if (!edit(tr("Insert output"), [](FbdDocument &d, const FbdCursor &c) { return fbd::insertOutput(d, c); }))
        return false;
    startTyping();
    return true;
}

bool FbdEditor::insertAssignment()
{
    if (!edit(tr("Insert assignment"), [](FbdDocument &d, const FbdCursor &c) { return fbd::insertAssignment(d, c); }))
        return false;
    startTyping();
    return true;
}

bool FbdEditor::insertJump(const QString &label)
{
    return edit(tr("Insert jump"), [&](FbdDocument &d, const FbdCursor &c) { return fbd::insertJump(d, c, label); });
}

bool FbdEditor::insertReturn()
{
    return edit(tr("Insert return"), [](FbdDocument &d, const FbdCursor &c) { return fbd::insertReturn(d, c); });
}

bool FbdEditor::setNetworkLabel(const QString &label)
{
    return edit(tr("Change label"), [&](FbdDocument &d, const FbdCursor &c) { return fbd::setNetworkLabel(d, c.network, label); });
}

bool FbdEditor::setNetworkComment(const QString &comment)
{
    return edit(tr("Change comment"), [&](FbdDocument &d, const FbdCursor &c) { return fbd::setNetworkComment(d, c.network, comment); });
}

bool FbdEditor::toggleNegation()
{
    return edit(tr("Negate"), [](FbdDocument &d, const FbdCursor &c) { return fbd::toggleNegation(d, c); });
}

bool FbdEditor::cycleSetReset()
{
    return edit(tr("Set/Reset"), [](FbdDocument &d, const FbdCursor &c) { return fbd::cycleSetReset(d, c); });
}

bool FbdEditor::cycleEdge()
{
    return edit(tr("Edge"), [](FbdDocument &d, const FbdCursor &c) { return fbd::cycleEdge(d, c); });
}

bool FbdEditor::setElementText(quint64 localId, const QString &text)
{
    return edit(tr("Rename"), [&](FbdDocument &d, const FbdCursor &) { return fbd::setElementText(d, localId, text); });
}

bool FbdEditor::deleteAtCursor()
{
    return edit(tr("Delete"), [](FbdDocument &d, const FbdCursor &c) { return fbd::deleteAtCursor(d, c); });
}

bool FbdEditor::copy()
{
    QString error;
    const std::vector<Element> fragment = copyAtCursor(document(), m_cursor, &error);
    if (fragment.empty()) {
        showError(error);
        return false;
    }
    copyElementsToClipboard(EditorLanguage::FBD, fragment);
    return true;
}

bool FbdEditor::cut()
{
    if (refuseWhileOnline())
        return false;
    return copy() && deleteAtCursor();
}

bool FbdEditor::paste()
{
    PastedElements pasted = elementsFromClipboard(EditorLanguage::FBD, 1);
    if (!pasted.ok()) {
        showError(pasted.error);
        return false;
    }
    return edit(tr("Paste"), [&](FbdDocument &d, const FbdCursor &c) { return fbd::pasteFragment(d, c, pasted.elements); });
}

// ---- dialogs for the commands that need a name

void FbdEditor::askLabel()
{
    if (refuseWhileOnline() || document().networks.empty())
        return;
    const int index = std::clamp(m_cursor.network, 0, int(document().networks.size()) - 1);
    const FbdNetwork &network = document().networks[std::size_t(index)];
    const QString current = network.label ? elementText(document(), network.label) : QString();
    if (const auto label = NetworkDialogs::askLabel(this, index, current))
        setNetworkLabel(*label);
}

void FbdEditor::askComment()
{
    if (refuseWhileOnline() || document().networks.empty())
        return;
    const int index = std::clamp(m_cursor.network, 0, int(document().networks.size()) - 1);
    const FbdNetwork &network = document().networks[std::size_t(index)];
    QString current;
    if (network.comment)
        current = std::get<Comment>(*document().element(network.comment)).content.text;
    if (const auto comment = NetworkDialogs::askComment(this, index, current))
        setNetworkComment(*comment);
}

void FbdEditor::askJump()
{
    if (refuseWhileOnline())
        return;
    QStringList labels;
    for (const FbdNetwork &network : document().networks)
        if (network.label)
            labels << elementText(document(), network.label);
    if (const auto label = NetworkDialogs::askJumpTarget(this, labels))
        insertJump(*label);
}

void FbdEditor::askBoxWithEn()
{
    if (refuseWhileOnline())
        return;
    QRectF where(view()->mapToScene(view()->viewport()->rect().center()), QSizeF(160, 24));
    if (const std::optional<QRectF> rect = cursorRect(layout(), m_cursor))
        where.moveTopLeft(rect->topLeft());
    editTextInPlace(where, QStringLiteral("ADD"), InPlaceEditor::Completion::BlockTypes, [this](const QString &text) {
        if (!text.isEmpty())
            insertOperator(text, true);
    });
}

// A breakpoint is on the cursor's network: every element of it but its rails, label and comment.
std::vector<quint64> FbdEditor::breakpointElementsAtCursor() const
{
    const auto &networks = document().networks;
    if (m_cursor.network < 0 || m_cursor.network >= int(networks.size()))
        return {};
    const auto &n = networks[std::size_t(m_cursor.network)];
    return networkMembersExcept(n, {n.label, n.comment});
}

int FbdEditor::networkOfElement(qint64 localId) const
{
    return localId < 0 ? -1 : document().networkOf(quint64(localId));
}

QRectF FbdEditor::networkBand(int network) const
{
    return networkBandRect(fbdPolicy().networkItems(), network);
}

} // namespace iec::editors::fbd
