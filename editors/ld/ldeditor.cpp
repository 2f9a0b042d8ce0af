#include "editors/ld/ldeditor.h"

#include "editors/common/diagramclipboard.h"
#include "editors/common/diagramscene.h"
#include "editors/common/diagramview.h"
#include "editors/common/networkdialogs.h"
#include "editors/common/boxspec.h"
#include "editors/ld/lditems.h"
#include "editors/ld/ldoverlay.h"
#include "editors/ld/ldscene.h"
#include "editors/ld/ldwrite.h"
#include "editors/text/completion.h"
#include "interpreter/runtime/snapshot.h"
#include "model/projectmodel.h"

#include <QGraphicsSceneMouseEvent>

namespace iec::editors::ld {

using namespace model;

namespace {

bool isIdentifierPath(const QString &text)
{
    const QString t = text.trimmed();
    if (t.isEmpty() || !(t.front().isLetter() || t.front() == QLatin1Char('_')))
        return false;
    return std::ranges::all_of(t, [](QChar c) { return c.isLetterOrNumber() || c == QLatin1Char('_') || c == QLatin1Char('.'); });
}

} // namespace

LdEditor::LdEditor(ProjectModel &model, BodyRef ref, QUndoStack *undoStack, QWidget *parent)
    : DiagramEditor(model, std::move(ref), undoStack, std::make_unique<LdPolicy>(), parent)
{
    auto overlay = std::make_unique<LdOverlayMapper>(ldPolicy());
    m_overlay = overlay.get();
    setOverlayMapper(std::move(overlay));
    createActions();
    scene()->installEventFilter(this);
    connect(scene(), &QGraphicsScene::selectionChanged, this, &LdEditor::cursorFromSelection);
    m_cursor = validCursor(document(), LdCursor::atNetwork(0));
    applyCursor();
}

LdEditor::~LdEditor()
{
    scene()->removeEventFilter(this);
    scene()->disconnect(this);
}

LdPolicy &LdEditor::ldPolicy() const
{
    return static_cast<LdPolicy &>(policy());
}

const LadderDocument &LdEditor::document() const
{
    scene()->rebuildIfDirty();
    return ldPolicy().document();
}

quint64 LdEditor::elementNamed(const QString &name) const
{
    for (const Element &e : document().elements) {
        const quint64 id = header(e).localId;
        if (elementText(document(), id).compare(name, Qt::CaseInsensitive) == 0)
            return id;
    }
    return 0;
}

// ---- the edit path

bool LdEditor::edit(const QString &undoText, const std::function<LdEditResult(LadderDocument &, const LdCursor &)> &change)
{
    scene()->rebuildIfDirty();
    const LdCursor at = m_cursor;
    std::optional<LdCursor> next;
    const bool ok = applyRewrite(undoText, [&](const std::vector<Element> &elements, std::vector<Element> &after) -> EditOutcome {
        const LadderDocument &shown = ldPolicy().document();
        const bool current = shown.elements.size() == elements.size(); // the scene is up to date
        LadderDocument doc;
        doc.elements.reserve(elements.size() + 64); // an edit adds a few: no reallocation of a large body
        if (current)
            doc = shown; // into the reserved room (a conditional expression would copy it twice)
        else
            doc = readLadder(elements, ldPolicy().layoutGenerated());
        const LdEditResult result = change(doc, at);
        if (!result.ok())
            return {result.error, {}};
        if (current)
            writeLadder(doc, shown, ldPolicy().layout()); // untouched networks only move
        else
            writeLadder(doc);
        after = std::move(doc.elements);
        next = result.cursor;
        m_cursor = result.cursor; // the scene refresh draws it
        return {{}, result.cursor.kind == LdCursor::Kind::Element ? result.cursor.elements : std::vector<quint64> {}};
    });
    if (ok && next)
        setCursor(*next);
    return ok;
}

// ---- the cursor

void LdEditor::setCursor(const LdCursor &cursor)
{
    m_cursor = validCursor(document(), cursor);
    applyCursor();
}

void LdEditor::applyCursor()
{
    m_applyingCursor = true;
    const std::vector<NetworkGeometry> &layout = ldPolicy().layout();
    delete m_wireCursor;
    m_wireCursor = nullptr;
    QList<quint64> selected;
    if (m_cursor.kind == LdCursor::Kind::Element)
        selected = QList<quint64>(m_cursor.elements.begin(), m_cursor.elements.end());
    select(selected);
    ldPolicy().setCurrentNetwork(m_cursor.kind == LdCursor::Kind::Network ? m_cursor.network : -1);
    QRectF focus;
    if (m_cursor.kind == LdCursor::Kind::Wire && m_cursor.network < int(layout.size())) {
        for (const WirePoint &point : layout[std::size_t(m_cursor.network)].wirePoints) {
            if (point == m_cursor.wire) {
                m_wireCursor = new WireCursorItem(point.position);
                scene()->addItem(m_wireCursor);
                focus = QRectF(point.position, QSizeF(1, 1));
            }
        }
    } else if (m_cursor.kind == LdCursor::Kind::Network && m_cursor.network < int(layout.size())) {
        const NetworkGeometry &g = layout[std::size_t(m_cursor.network)];
        focus = QRectF(0, g.top, 60, g.height);
    } else if (m_cursor.kind == LdCursor::Kind::Element && m_cursor.network < int(layout.size())) {
        const auto &rects = layout[std::size_t(m_cursor.network)].rects;
        if (const auto it = rects.find(m_cursor.element()); it != rects.end())
            focus = it->second;
    }
    if (!focus.isNull())
        view()->ensureVisible(focus, 40, 40);
    m_applyingCursor = false;
    updateActionStates();
}

void LdEditor::cursorFromSelection()
{
    if (m_applyingCursor)
        return;
    const QList<quint64> ids = selection();
    if (ids.isEmpty())
        return; // a click on the wire or the network sets the cursor itself
    const int network = document().networkOf(ids.front());
    std::vector<quint64> inNetwork;
    for (quint64 id : ids)
        if (document().networkOf(id) == network)
            inNetwork.push_back(id);
    m_cursor = {LdCursor::Kind::Element, std::max(0, network), inNetwork, {}};
    delete m_wireCursor;
    m_wireCursor = nullptr;
    updateActionStates();
}

void LdEditor::sceneRefreshed()
{
    m_wireCursor = nullptr; // a rebuild deleted it with the other items
    m_cursor = validCursor(document(), m_cursor);
    applyCursor();
}

void LdEditor::navigate(Qt::Key key)
{
    const int dx = key == Qt::Key_Left ? -1 : key == Qt::Key_Right ? 1 : 0;
    const int dy = key == Qt::Key_Up ? -1 : key == Qt::Key_Down ? 1 : 0;
    setCursor(moveCursor(document(), ldPolicy().layout(), m_cursor, dx, dy));
}

void LdEditor::extendSelection(quint64 localId)
{
    // Shift-click: a range of elements of one network, for a parallel contact around them.
    const int network = document().networkOf(localId);
    if (m_cursor.kind != LdCursor::Kind::Element || network != m_cursor.network) {
        setCursor(LdCursor::atElement(network, localId));
        return;
    }
    LdCursor range = m_cursor;
    if (std::ranges::find(range.elements, localId) == range.elements.end())
        range.elements.push_back(localId);
    setCursor(range);
}

// A click on the wire between elements puts the cursor there; on a network's number, on the
// network. Clicks on elements select them (the scene does that).
void LdEditor::clickAt(QPointF scenePos)
{
    const std::vector<NetworkGeometry> &layout = ldPolicy().layout();
    for (std::size_t n = 0; n < layout.size(); ++n) {
        const NetworkGeometry &g = layout[n];
        if (scenePos.y() < g.top || scenePos.y() >= g.top + g.height)
            continue;
        const WirePoint *best = nullptr;
        double bestDistance = 12;
        for (const WirePoint &point : g.wirePoints) {
            const double d = QLineF(point.position, scenePos).length();
            if (d < bestDistance) {
                best = &point;
                bestDistance = d;
            }
        }
        setCursor(best ? LdCursor::atWire(int(n), *best) : LdCursor::atNetwork(int(n)));
        return;
    }
}

bool LdEditor::dropPou(const QString &typeName, QPointF scenePos)
{
    // The cursor goes where a click there puts it (the element, else the wire point or the
    // network; below the last network, the last one), and the box is inserted as with F.
    QGraphicsItem *hit = scene()->itemAt(scenePos, QTransform());
    DiagramItem *item = hit ? diagramItemOf(hit) : nullptr;
    const std::vector<NetworkGeometry> &layout = ldPolicy().layout();
    if (item && item->flags().testFlag(QGraphicsItem::ItemIsSelectable))
        setCursor(LdCursor::atElement(document().networkOf(item->localId()), item->localId()));
    else if (!layout.empty() && scenePos.y() >= layout.back().top + layout.back().height)
        setCursor(LdCursor::atNetwork(int(layout.size()) - 1));
    else
        clickAt(scenePos);
    return insertBox(typeName, false);
}

bool LdEditor::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == scene() && event->type() == QEvent::GraphicsSceneMousePress) {
        auto *mouse = static_cast<QGraphicsSceneMouseEvent *>(event);
        QGraphicsItem *hit = scene()->itemAt(mouse->scenePos(), QTransform());
        const bool onElement = hit && diagramItemOf(hit) && diagramItemOf(hit)->flags().testFlag(QGraphicsItem::ItemIsSelectable);
        if (mouse->button() == Qt::LeftButton && !onElement && !(mouse->modifiers() & Qt::ShiftModifier)) {
            clickAt(mouse->scenePos());
            return false;
        }
    }
    return DiagramEditor::eventFilter(watched, event);
}

// ---- typing names

void LdEditor::startTyping(quint64 localId)
{
    const Element *e = document().element(localId);
    const int network = document().networkOf(localId);
    if (!e || network < 0 || network >= int(ldPolicy().layout().size()))
        return;
    const auto &rects = ldPolicy().layout()[std::size_t(network)].rects;
    const auto it = rects.find(localId);
    if (it == rects.end())
        return;
    // The field covers the name: above a contact or coil, over a box's instance name, on a
    // variable itself.
    QRectF where = it->second;
    if (std::holds_alternative<Contact>(*e) || std::holds_alternative<Coil>(*e) || std::holds_alternative<Block>(*e))
        where = QRectF(where.left() - 40, where.top() - 20, where.width() + 80, 18);
    editTextInPlace(where, elementText(document(), localId), InPlaceEditor::Completion::Names, [this, localId](const QString &text) {
        if (text.isEmpty() || text == elementText(document(), localId))
            return;
        if (setElementText(localId, text))
            offerDeclaration(localId);
    });
}

// An undeclared variable typed on a contact, coil or box instance: the app offers to declare it.
bool LdEditor::offerDeclaration(quint64 localId)
{
    const CompletionProvider *names = completionProvider();
    const Element *e = document().element(localId);
    if (!names || !e)
        return false;
    const QString text = elementText(document(), localId).trimmed();
    if (!isIdentifierPath(text) || text == kPlaceholder)
        return false;
    const QString head = text.section(QLatin1Char('.'), 0, 0);
    const bool variableLike = std::holds_alternative<Contact>(*e) || std::holds_alternative<Coil>(*e)
        || std::holds_alternative<InVariable>(*e) || std::holds_alternative<OutVariable>(*e)
        || (std::holds_alternative<Block>(*e) && std::get<Block>(*e).instanceName);
    if (!variableLike || !names->typeOf(head).isEmpty())
        return false;
    for (const CompletionItem &item : names->variables())
        if (item.text.compare(head, Qt::CaseInsensitive) == 0)
            return false;
    Q_EMIT declareVariableRequested(bodyRef(), head);
    return true;
}

// ---- online

void LdEditor::activateElement(quint64 localId, QPointF)
{
    if (isOnline()) {
        prepareToggle(localId);
        return;
    }
    startTyping(localId);
}

void LdEditor::prepareToggle(quint64 localId)
{
    const QString name = m_overlay->variableName(localId, onlineInstance());
    if (name.isEmpty())
        return;
    const Element *e = document().element(localId);
    if (!e || !(std::holds_alternative<Contact>(*e) || std::holds_alternative<Coil>(*e)))
        return;
    // A contact or coil is BOOL: prepare the opposite of what it is now.
    const bool now = m_overlay->value(name).compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0;
    announcePrepared(name, now ? QStringLiteral("FALSE") : QStringLiteral("TRUE"));
}

// ---- commands

bool LdEditor::insertNetwork(bool after)
{
    return edit(tr("Insert network"), [after](LadderDocument &d, const LdCursor &c) { return ld::insertNetwork(d, c, after); });
}

bool LdEditor::insertContact()
{
    if (!edit(tr("Insert contact"), [](LadderDocument &d, const LdCursor &c) { return ld::insertContact(d, c); }))
        return false;
    startTyping(m_cursor.element());
    return true;
}

bool LdEditor::insertParallelContact(bool below)
{
    if (!edit(tr("Insert parallel contact"), [below](LadderDocument &d, const LdCursor &c) { return ld::insertParallelContact(d, c, below); }))
        return false;
    startTyping(m_cursor.element());
    return true;
}

bool LdEditor::insertCoil()
{
    if (!edit(tr("Insert coil"), [](LadderDocument &d, const LdCursor &c) { return ld::insertCoil(d, c); }))
        return false;
    startTyping(m_cursor.element());
    return true;
}

bool LdEditor::insertBox(const QString &typeName, bool withEn)
{
    QString error;
    const std::optional<BoxSpec> spec = boxSpecFor(projectModel().project(), typeName, withEn, &error);
    if (!spec) {
        showError(error);
        return false;
    }
    if (!edit(tr("Insert box %1").arg(spec->typeName), [&](LadderDocument &d, const LdCursor &c) { return ld::insertBox(d, c, *spec); }))
        return false;
    if (spec->functionBlock)
        startTyping(m_cursor.element());
    return true;
}

bool LdEditor::insertJump(const QString &label)
{
    return edit(tr("Insert jump"), [&](LadderDocument &d, const LdCursor &c) { return ld::insertJump(d, c, label); });
}

bool LdEditor::insertReturn()
{
    return edit(tr("Insert return"), [](LadderDocument &d, const LdCursor &c) { return ld::insertReturn(d, c); });
}

bool LdEditor::insertBoxInput()
{
    return edit(tr("Insert input"), [](LadderDocument &d, const LdCursor &c) { return ld::insertBoxInput(d, c); });
}

bool LdEditor::insertBoxAssignment()
{
    if (!edit(tr("Insert assignment"), [](LadderDocument &d, const LdCursor &c) { return ld::insertBoxAssignment(d, c); }))
        return false;
    startTyping(m_cursor.element());
    return true;
}

bool LdEditor::insertOperatorAtInput(const QString &typeName)
{
    QString error;
    const std::optional<BoxSpec> spec = boxSpecFor(projectModel().project(), typeName, false, &error);
    if (!spec) {
        showError(error);
        return false;
    }
    return edit(tr("Insert operator"), [&](LadderDocument &d, const LdCursor &c) { return ld::insertOperatorAtInput(d, c, *spec); });
}

bool LdEditor::setNetworkLabel(const QString &label)
{
    return edit(tr("Change label"), [&](LadderDocument &d, const LdCursor &c) { return ld::setNetworkLabel(d, c.network, label); });
}

bool LdEditor::setNetworkComment(const QString &comment)
{
    return edit(tr("Change comment"), [&](LadderDocument &d, const LdCursor &c) { return ld::setNetworkComment(d, c.network, comment); });
}

bool LdEditor::toggleNegation()
{
    return edit(tr("Negate"), [](LadderDocument &d, const LdCursor &c) { return ld::toggleNegation(d, c); });
}

bool LdEditor::cycleSetReset()
{
    return edit(tr("Set/Reset"), [](LadderDocument &d, const LdCursor &c) { return ld::cycleSetReset(d, c); });
}

bool LdEditor::cycleEdge()
{
    return edit(tr("Edge"), [](LadderDocument &d, const LdCursor &c) { return ld::cycleEdge(d, c); });
}

bool LdEditor::setElementText(quint64 localId, const QString &text)
{
    return edit(tr("Rename"), [&](LadderDocument &d, const LdCursor &) { return ld::setElementText(d, localId, text); });
}

bool LdEditor::deleteAtCursor()
{
    return edit(tr("Delete"), [](LadderDocument &d, const LdCursor &c) { return ld::deleteAtCursor(d, c); });
}

bool LdEditor::copy()
{
    QString error;
    const std::vector<Element> fragment = copyAtCursor(document(), m_cursor, &error);
    if (fragment.empty()) {
        showError(error);
        return false;
    }
    copyElementsToClipboard(EditorLanguage::LD, fragment);
    return true;
}

bool LdEditor::cut()
{
    if (refuseWhileOnline())
        return false;
    return copy() && deleteAtCursor();
}

bool LdEditor::paste(PasteMode mode)
{
    PastedElements pasted = elementsFromClipboard(EditorLanguage::LD, 1);
    if (!pasted.ok()) {
        showError(pasted.error);
        return false;
    }
    return edit(tr("Paste"), [&](LadderDocument &d, const LdCursor &c) { return ld::pasteFragment(d, c, pasted.elements, mode); });
}

// ---- dialogs for the commands that need a name

void LdEditor::askBoxType(bool withEn)
{
    if (refuseWhileOnline())
        return;
    // The type is typed where the box goes (completion from the library and the project; F2).
    QRectF where(view()->mapToScene(view()->viewport()->rect().center()), QSizeF(160, 24));
    const std::vector<NetworkGeometry> &layout = ldPolicy().layout();
    if (m_cursor.network < int(layout.size())) {
        const NetworkGeometry &g = layout[std::size_t(m_cursor.network)];
        where = QRectF(geometry::kRailX + 20, g.lineY - 12, 160, 24);
        if (m_cursor.kind == LdCursor::Kind::Wire)
            for (const WirePoint &p : g.wirePoints)
                if (p == m_cursor.wire)
                    where.moveTopLeft(p.position - QPointF(10, 12));
    }
    editTextInPlace(where, withEn ? QStringLiteral("ADD") : QStringLiteral("TON"), InPlaceEditor::Completion::BlockTypes,
        [this, withEn](const QString &text) {
            if (!text.isEmpty())
                insertBox(text, withEn);
        });
}

void LdEditor::askLabel()
{
    if (refuseWhileOnline() || document().networks.empty())
        return;
    const LdNetwork &network = document().networks[std::size_t(std::clamp(m_cursor.network, 0, int(document().networks.size()) - 1))];
    const QString current = network.label ? elementText(document(), network.label) : QString();
    if (const auto label = NetworkDialogs::askLabel(this, m_cursor.network, current))
        setNetworkLabel(*label);
}

void LdEditor::askComment()
{
    if (refuseWhileOnline() || document().networks.empty())
        return;
    const LdNetwork &network = document().networks[std::size_t(std::clamp(m_cursor.network, 0, int(document().networks.size()) - 1))];
    QString current;
    if (network.comment)
        current = std::get<Comment>(*document().element(network.comment)).content.text;
    if (const auto comment = NetworkDialogs::askComment(this, m_cursor.network, current))
        setNetworkComment(*comment);
}

void LdEditor::askJump()
{
    if (refuseWhileOnline())
        return;
    QStringList labels;
    for (const LdNetwork &network : document().networks)
        if (network.label)
            labels << elementText(document(), network.label);
    if (const auto label = NetworkDialogs::askJumpTarget(this, labels))
        insertJump(*label);
}

bool LdEditor::cursorOn(bool (*test)(const Element &)) const
{
    if (m_cursor.kind != LdCursor::Kind::Element)
        return false;
    const Element *e = document().element(m_cursor.element());
    return e && test(*e);
}

// A breakpoint is on the cursor's network: every element of it but its rails, label and comment.
std::vector<quint64> LdEditor::breakpointElementsAtCursor() const
{
    const auto &networks = document().networks;
    if (m_cursor.network < 0 || m_cursor.network >= int(networks.size()))
        return {};
    const auto &n = networks[std::size_t(m_cursor.network)];
    return networkMembersExcept(n, {n.leftRail, n.rightRail, n.label, n.comment, n.title});
}

int LdEditor::networkOfElement(qint64 localId) const
{
    return localId < 0 ? -1 : document().networkOf(quint64(localId));
}

QRectF LdEditor::networkBand(int network) const
{
    return networkBandRect(ldPolicy().networkItems(), network);
}

} // namespace iec::editors::ld
