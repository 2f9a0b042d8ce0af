#pragma once

#include "editors/common/diagramitem.h"
#include "model/body.h"
#include "model/element.h"

#include <QFont>
#include <QHash>
#include <QPointF>
#include <QRectF>

// The items the data-flow languages share (LD, FBD, CFC; also FBD elements in SFC bodies): boxes
// for function and function block calls, variables, and wires, drawn as CODESYS draws them. An
// item sits at its element's position and draws in its own coordinates, so a whole network moves
// by moving its items. Online, an item shows values beside its pins and a powered (TRUE) state in
// blue; it never touches the model.
namespace iec::editors {

// The font of LD/FBD/CFC drawings.
QFont blockFont();

inline const QColor kPowerBlue(0x10, 0x50, 0xe0);
inline const QColor kPlaceholderRed(0xc0, 0x20, 0x20);
inline const QColor kSelectionColor(0x20, 0x60, 0xd0);
inline const QColor kForcedMark(0xe0, 0x80, 0x00);

// An element drawn in `rect` (its position and size in the body).
class ElementItem : public DiagramItem
{
public:
    ElementItem(const model::Element &element, const QRectF &rect);

    [[nodiscard]] const model::Element &element() const { return m_element; }
    [[nodiscard]] QRectF localFrame() const { return QRectF(QPointF(0, 0), m_size); }
    QRectF frame() const override { return QRectF(pos(), m_size); }
    QRectF boundingRect() const override;
    // An input pin on the left middle, an output pin on the right middle (when the element has
    // them); boxes have one per variable.
    QList<Pin> pins() const override;

    // Online: the value is held by a force.
    void setForced(bool forced);

protected:
    // Extra room the item draws outside its frame (names above, values beside).
    virtual QRectF extent() const { return localFrame(); }
    void paintDecorations(QPainter *painter) const; // selection, forced marker
    void paintName(QPainter *painter, const QString &text, const QRectF &row, Qt::Alignment alignment) const;

    model::Element m_element;
    QSizeF m_size;
    bool m_forced = false;
};

// A function or function block call: type name in the title row, instance name above, pin names
// inside along the edges, negated pins as small circles, edge pins with a triangle. Online, the
// values of the pins are drawn beside them.
class BoxItem : public ElementItem
{
public:
    // `inputRows`/`outputRows` say on which row each pin sits (a rung's pins come first in LD).
    BoxItem(const model::Element &element, const QRectF &rect, std::vector<int> inputRows, std::vector<int> outputRows);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

    // Online values by pin name (upper case), drawn outside the box next to the pin.
    void setPinValues(const QHash<QString, QString> &values);
    [[nodiscard]] QPointF inputPin(int pin) const;  // local
    [[nodiscard]] QPointF outputPin(int pin) const; // local
    QList<Pin> pins() const override;

protected:
    QRectF extent() const override;

private:
    std::vector<int> m_inputRows;
    std::vector<int> m_outputRows;
    QHash<QString, QString> m_pinValues;
};

// A box as another tool drew it: its pins on the rows their relPositions say (the pin pitch from
// below the title row), or one after the other where the file gives none.
BoxItem *boxItemAsDrawn(const model::Element &element, const QRectF &rect);

// A variable or constant (an input of a box, an assignment of an output): its text, right-aligned
// when it feeds a pin on its right, left-aligned when a pin feeds it. "???" is red until typed.
// Online, the value follows the name.
class VariableItem : public ElementItem
{
public:
    VariableItem(const model::Element &element, const QRectF &rect, bool framed);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
    [[nodiscard]] QString text() const;

protected:
    QRectF extent() const override;

private:
    bool m_framed;
};

// A wire along orthogonal points (scene coordinates). Online, a powered wire is blue and thick.
// `broken`: there is no room for it (CFC draws such wires straight and red).
class WireItem : public QGraphicsItem
{
public:
    enum { Type = UserType + 0x140 };

    WireItem(quint64 source, quint64 target, const QList<QPointF> &points);
    int type() const override { return Type; }
    QRectF boundingRect() const override;
    QPainterPath shape() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

    [[nodiscard]] quint64 source() const { return m_source; }
    [[nodiscard]] quint64 target() const { return m_target; }
    [[nodiscard]] const QList<QPointF> &points() const { return m_points; }
    void setPoints(const QList<QPointF> &points); // re-routed (CFC, while a box is dragged)
    void setPowered(bool powered);
    [[nodiscard]] bool isPowered() const { return m_powered; }
    void setBroken(bool broken);
    [[nodiscard]] bool isBroken() const { return m_broken; }

private:
    quint64 m_source;
    quint64 m_target;
    QList<QPointF> m_points;
    QPainterPath m_path;
    bool m_powered = false;
    bool m_broken = false;
};

} // namespace iec::editors
