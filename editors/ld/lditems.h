#pragma once

#include "editors/common/networkitems.h"

// The items of a ladder diagram, drawn as CODESYS draws them: contacts | |, |/|, |P|, |N|;
// coils ( ), (/), (S), (R), (P), (N), with the variable's name above; power rails as thick
// lines; jumps as an arrow with the label; returns as <RETURN>; each network with its number on
// the left, its label and comment above the rung. Online, a contact that conducts and a coil
// that is energised are drawn thick and blue.
namespace iec::editors::ld {

// The colour of rails, symbols and unpowered wires.
inline const QColor kInk(0x20, 0x20, 0x20);

class ContactItem : public ElementItem
{
public:
    ContactItem(const model::Element &element, const QRectF &rect);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

protected:
    QRectF extent() const override;
};

class CoilItem : public ElementItem
{
public:
    CoilItem(const model::Element &element, const QRectF &rect);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

protected:
    QRectF extent() const override;
};

class RailItem : public ElementItem
{
public:
    RailItem(const model::Element &element, const QRectF &rect);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
};

// The cursor on a wire point: a small filled square on the wire, as CODESYS marks a
// connection point.
class WireCursorItem : public QGraphicsItem
{
public:
    explicit WireCursorItem(QPointF at);
    QRectF boundingRect() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
};

} // namespace iec::editors::ld
