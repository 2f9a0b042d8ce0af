#pragma once

#include "editors/common/blockitems.h"

// The items only CFC draws: labels, connection marks and comments placed freely, and the
// execution-order number in an element's corner.
namespace iec::editors::cfc {

// A label ("Name:"), a connection mark (a connector: the name in a frame with a point to the
// right, where a wire goes in; a continuation: the same pointing into the element, where a wire
// comes out), a comment (its lines on a pale ground) or another tool's element (its text in a
// dashed frame).
class CfcMarkItem : public ElementItem
{
public:
    CfcMarkItem(const model::Element &element, const QRectF &rect);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
};

// The execution-order number of an element, in a small frame above its top right corner (a child
// of the element's item: it moves with it).
class OrderNumberItem : public QGraphicsItem
{
public:
    OrderNumberItem(int number, ElementItem *parent);
    QRectF boundingRect() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
    [[nodiscard]] int number() const { return m_number; }

private:
    int m_number;
    QRectF m_rect;
};

} // namespace iec::editors::cfc
