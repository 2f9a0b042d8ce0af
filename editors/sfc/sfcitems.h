#pragma once

#include "model/sfcoptions.h"

#include "editors/common/diagramitem.h"
#include "model/element.h"

#include <QSet>

// The items of an SFC chart, drawn as CODESYS draws them: steps as boxes (a double border for the
// initial step, "E"/"X" in the bottom corners for entry/exit actions, a triangle for the active
// action of a simplified step), transitions as short bars with their condition to the right,
// alternative branches between single lines, parallel branches between double lines, jumps as
// arrows with their target, action blocks as a table of qualifier | action | indicator.
// Online, active steps and actions are filled blue and true transitions are green.
namespace iec::editors::sfc {

QFont chartFont();

class SfcItem : public DiagramItem
{
public:
    SfcItem(const model::Element &element);

    QRectF boundingRect() const override;
    [[nodiscard]] const model::Element &element() const { return m_element; }
    [[nodiscard]] QRectF frame() const override { return m_frame; } // the element's own rectangle

    // The width the text beside the element (a transition's condition, a jump's target) may
    // take before it would run into the next drawing on its right: it is cut with "…" there and
    // the tooltip shows it whole. Negative: no limit.
    void setLabelRoom(double width);
    [[nodiscard]] double labelRoom() const { return m_labelRoom; }
    // The label as drawn (cut to the room), empty when the element has none.
    [[nodiscard]] QString shownLabel() const;

protected:
    void paintSelection(QPainter *painter) const;
    void paintLabel(QPainter *painter) const;
    model::Element m_element;
    QRectF m_frame;  // in scene coordinates (items sit at 0,0)
    QRectF m_bounds; // with the texts beside it
    double m_labelRoom = -1;
};

class StepItem : public SfcItem
{
public:
    explicit StepItem(const model::Element &element);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
    // Which corner a point is in: the entry corner (bottom left), the exit corner (bottom
    // right), the active-action corner (top right), or none.
    enum class Corner { None, Entry, Exit, Active };
    [[nodiscard]] Corner cornerAt(QPointF scenePoint) const;

private:
    // Read once from the step's addData (an XML parse); items are rebuilt when the model changes.
    model::StepOptions m_options;
};

class TransitionItem : public SfcItem
{
public:
    explicit TransitionItem(const model::Element &element);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
    QPainterPath shape() const override;
};

class JumpItem : public SfcItem
{
public:
    JumpItem(const model::Element &element, bool targetExists);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

private:
    bool m_targetExists;
};

class BarItem : public SfcItem
{
public:
    explicit BarItem(const model::Element &element);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
    QPainterPath shape() const override;
};

class ActionBlockItem : public SfcItem
{
public:
    explicit ActionBlockItem(const model::Element &element);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
    // The row (action index) at a scene point, -1 outside.
    [[nodiscard]] int rowAt(QPointF scenePoint) const;
    void setActiveActions(const QSet<QString> &names); // lower-case action names
    [[nodiscard]] bool isActionActive(int row) const;

private:
    QSet<QString> m_activeActions;
};

// Anything else of the body (comments, the variables of a wired condition, ...): a labelled box.
class OtherItem : public SfcItem
{
public:
    explicit OtherItem(const model::Element &element);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
};

} // namespace iec::editors::sfc
