#pragma once

#include "editors/common/diagrameditor.h"
#include "editors/fbd/fbdedits.h"

class QGraphicsRectItem;

namespace iec::editors::fbd {

class FbdPolicy;
class FbdOverlayMapper;

// The FBD editor (seed 002 §2, the RunPro / CoDeSys 2.3 workflow): a body of numbered networks,
// each a tree of boxes laid out by the editor. A dotted rectangle marks the cursor at one of the
// positions of the seed's table 1 (a text, an input, a box, an output, the crossing in front of
// an assignment, the end of the network, or the network itself), moved with the mouse and the
// arrow keys; every command of the right-click menu, the Insert menu and the tool bar acts there
// and is one undo step. New elements read "???", typed in place with completion and F2. Online,
// values stand at the variables and pins, TRUE lines are blue, and a double-click on a variable
// prepares a value for Write/Force.
class FbdEditor : public DiagramEditor
{
    Q_OBJECT

public:
    FbdEditor(model::ProjectModel &model, model::BodyRef ref, QUndoStack *undoStack, QWidget *parent = nullptr);
    ~FbdEditor() override;

    [[nodiscard]] const FbdDocument &document() const;
    [[nodiscard]] const std::vector<FbdGeometry> &layout() const;
    [[nodiscard]] const FbdCursor &cursor() const { return m_cursor; }
    void setCursor(const FbdCursor &cursor);
    // The element with that text (a variable, an assignment, an instance, a jump label), for tests.
    [[nodiscard]] quint64 elementNamed(const QString &name) const;

    // ---- the commands at the cursor (the action table calls these; tests too)
    bool insertNetwork(bool after);
    bool insertOperator(const QString &typeName = QStringLiteral("AND"), bool withEn = false);
    bool insertInput();
    bool insertOutput();
    bool insertAssignment();
    bool insertJump(const QString &label);
    bool insertReturn();
    bool setNetworkLabel(const QString &label);
    bool setNetworkComment(const QString &comment);
    bool toggleNegation();
    bool cycleSetReset();
    bool cycleEdge();
    bool setElementText(quint64 localId, const QString &text);
    // Changes the type of the box (typed over its keyword, or from F2): its wires stay.
    bool changeBoxType(quint64 box, const QString &typeName);
    bool deleteAtCursor();
    bool copy();
    bool cut();
    bool paste();
    // Starts typing at the cursor: a variable's name, a box's type or instance name, a label.
    void startTyping();

protected:
    void navigate(Qt::Key key) override;
    void activateElement(quint64 localId, QPointF scenePos) override;
    void sceneRefreshed() override;
    [[nodiscard]] std::vector<quint64> breakpointElementsAtCursor() const override;
    [[nodiscard]] int networkOfElement(qint64 localId) const override;
    [[nodiscard]] QRectF networkBand(int network) const override;
    [[nodiscard]] bool acceptsPouDrops() const override { return true; }
    bool dropPou(const QString &typeName, QPointF scenePos) override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void createActions();
    [[nodiscard]] FbdPolicy &fbdPolicy() const;
    bool edit(const QString &undoText, const std::function<FbdEditResult(FbdDocument &, const FbdCursor &)> &change);
    void applyCursor();
    void askLabel();
    void askComment();
    void askJump();
    void askBoxWithEn();
    void prepareValue(quint64 localId);
    bool offerDeclaration(quint64 localId);
    [[nodiscard]] bool cursorIs(std::initializer_list<FbdCursor::Kind> kinds) const;
    [[nodiscard]] const model::Element *cursorElement() const;

    FbdCursor m_cursor;
    bool m_applyingCursor = false;
    QGraphicsRectItem *m_cursorFrame = nullptr;
    FbdOverlayMapper *m_overlay = nullptr; // owned by the base
};

} // namespace iec::editors::fbd
