#pragma once

#include "editors/cfc/cfcedits.h"
#include "editors/common/diagrameditor.h"

namespace iec::editors::cfc {

class CfcPolicy;
class CfcOverlayMapper;

// The CFC editor (seed 002 §6): elements placed anywhere, wires dragged from an output pin to an
// input pin and routed around the elements (red and straight where there is no room), the
// execution-order number in each element's corner and the commands that change it. New elements
// go where the mouse last pressed (or where a library box is dropped) and read "???" until typed
// in place. Every gesture is one undo step; a CODESYS CFC is written back in CODESYS's form.
class CfcEditor : public DiagramEditor
{
    Q_OBJECT

public:
    CfcEditor(model::ProjectModel &model, model::BodyRef ref, QUndoStack *undoStack, QWidget *parent = nullptr);
    ~CfcEditor() override;

    // The elements shown (empty when the body cannot be read; the message line says why).
    [[nodiscard]] const std::vector<model::Element> &elements() const;
    [[nodiscard]] const CfcPolicy &cfcPolicy() const;
    // The element with that text (a variable, an instance, a box type, a label, a mark), for tests.
    [[nodiscard]] quint64 elementNamed(const QString &name) const;
    // Where the next inserted element goes (its top left).
    [[nodiscard]] QPointF insertPosition() const { return m_insertAt; }
    void setInsertPosition(QPointF scenePos);

    // ---- commands (the action table calls these; tests too)
    bool insertBox(const QString &typeName = QStringLiteral("AND"), bool withEn = false);
    bool insertInput();
    bool insertOutput();
    bool insertJump();
    bool insertLabel();
    bool insertReturn();
    bool insertComment(const QString &text);
    bool insertConnector();
    bool insertContinuation();
    bool setElementText(quint64 localId, const QString &text);
    bool changeBoxType(quint64 box, const QString &typeName);
    // Gives the selected box EN/ENO (CODESYS's EN/ENO command), or takes them away.
    bool toggleEnEno();
    bool toggleNegation();
    bool deleteSelection();
    bool copy();
    bool cut();
    bool paste();
    bool orderByDataFlow();
    bool orderByTopology();
    bool moveInOrder(OrderMove move);
    bool setOrderNumber(quint64 localId, int number);
    // Types the selected element's text in place: a variable, a label, a mark, a box's instance (or
    // its type when it has none; `boxType` asks for the type).
    void startTyping(bool boxType = false);
    // A CFC breakpoint is on one element (the selected one): "box 3 (ADD)" by its execution-order
    // number, where LD and FBD name a network.
    [[nodiscard]] QString placeName(qint64 localId) const override;

protected:
    void navigate(Qt::Key key) override;
    void activateElement(quint64 localId, QPointF scenePos) override;
    [[nodiscard]] QUndoCommand *elementsCommand(std::vector<model::Element> after, const QString &undoText) override;
    void moveElements(const QList<quint64> &localIds, const QList<QPointF> &positions) override;
    void connectWire(quint64 source, const QString &formalParameter, quint64 target, int inputIndex) override;
    [[nodiscard]] bool acceptsPouDrops() const override { return true; }
    bool dropPou(const QString &typeName, QPointF scenePos) override;
    [[nodiscard]] bool acceptsInsertDrops() const override { return true; }
    bool dropInsertAction(const QString &actionId, QPointF scenePos) override;
    bool eventFilter(QObject *watched, QEvent *event) override;
    void sceneRefreshed() override;

private:
    void createActions();
    [[nodiscard]] static bool hasEnEno(const model::Block &box);
    bool rebuildBox(quint64 box, const QString &typeName, bool withEn, const QString &undoText);
    bool insert(const QString &undoText, model::Element element, bool typeAfterwards);
    void askComment();
    void askOrderNumber();
    void prepareValue(quint64 localId);
    bool offerDeclaration(quint64 localId);
    [[nodiscard]] const model::Element *element(quint64 localId) const;
    [[nodiscard]] bool selectionRuns() const;

    QPointF m_insertAt {40, 40};
    CfcOverlayMapper *m_overlay = nullptr; // owned by the base
};

} // namespace iec::editors::cfc
