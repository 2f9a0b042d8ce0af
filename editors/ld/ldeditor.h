#pragma once

#include "editors/common/diagrameditor.h"
#include "editors/ld/ldedits.h"

#include <QPointer>

namespace iec::editors::ld {

class LdPolicy;
class LdOverlayMapper;
class WireCursorItem;

// The LD editor (seed 002 §1, the RunPro / CoDeSys 2.3 workflow): a body of numbered networks,
// each a rung between its power rails laid out by the editor. A cursor stands on an element, on a
// point of a rung's wire or on a network, moved with the mouse and the arrow keys; every command
// of the right-click menu, the Insert menu and the tool bar acts there and is one undo step. A new
// element's name reads "???", selected for typing with completion and F2. Online, power flow is
// drawn blue and a double-click on a variable prepares the opposite value for Write/Force.
class LdEditor : public DiagramEditor
{
    Q_OBJECT

public:
    LdEditor(model::ProjectModel &model, model::BodyRef ref, QUndoStack *undoStack, QWidget *parent = nullptr);
    ~LdEditor() override;

    // What the editor shows, read from the model.
    [[nodiscard]] const LadderDocument &document() const;
    [[nodiscard]] const LdCursor &cursor() const { return m_cursor; }
    void setCursor(const LdCursor &cursor);
    // The element with that name (a contact's or coil's variable, a box's instance), for tests.
    [[nodiscard]] quint64 elementNamed(const QString &name) const;

    // ---- the commands at the cursor (the action table calls these; tests too)
    bool insertNetwork(bool after);
    bool insertContact();
    bool insertParallelContact(bool below);
    bool insertCoil();
    bool insertBox(const QString &typeName, bool withEn);
    bool insertJump(const QString &label);
    bool insertReturn();
    bool insertBoxInput();
    bool insertBoxAssignment();
    bool insertOperatorAtInput(const QString &typeName = QStringLiteral("AND"));
    bool setNetworkLabel(const QString &label);
    bool setNetworkComment(const QString &comment);
    bool toggleNegation();
    bool cycleSetReset();
    bool cycleEdge();
    bool setElementText(quint64 localId, const QString &text);
    bool deleteAtCursor();
    bool copy();
    bool cut();
    bool paste(PasteMode mode = PasteMode::After);
    // Starts typing the name of the element at the cursor (Enter, double-click; new elements).
    void startTyping(quint64 localId);

protected:
    void navigate(Qt::Key key) override;
    void activateElement(quint64 localId, QPointF scenePos) override;
    void extendSelection(quint64 localId) override;
    void sceneRefreshed() override;
    [[nodiscard]] std::vector<quint64> breakpointElementsAtCursor() const override;
    [[nodiscard]] int networkOfElement(qint64 localId) const override;
    [[nodiscard]] QRectF networkBand(int network) const override;
    [[nodiscard]] bool acceptsPouDrops() const override { return true; }
    bool dropPou(const QString &typeName, QPointF scenePos) override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void createActions();
    [[nodiscard]] LdPolicy &ldPolicy() const;
    // One command: `change` edits a copy of the document at the cursor, which is written back and
    // pushed as one undo step; the cursor goes where the command says.
    bool edit(const QString &undoText, const std::function<LdEditResult(LadderDocument &, const LdCursor &)> &change);
    void applyCursor();
    void cursorFromSelection();
    void clickAt(QPointF scenePos);
    void askBoxType(bool withEn);
    void askLabel();
    void askComment();
    void askJump();
    void prepareToggle(quint64 localId);
    bool offerDeclaration(quint64 localId);
    [[nodiscard]] bool cursorOnElement() const { return m_cursor.kind == LdCursor::Kind::Element; }
    [[nodiscard]] bool cursorOn(bool (*test)(const model::Element &)) const;

    LdCursor m_cursor;
    bool m_applyingCursor = false;
    WireCursorItem *m_wireCursor = nullptr;
    LdOverlayMapper *m_overlay = nullptr; // owned by the base
};

} // namespace iec::editors::ld
