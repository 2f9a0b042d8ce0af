#pragma once

#include "editors/common/blockitems.h"

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

// Jump (an arrow and the label), return (<RETURN>), and anything else drawn as a labelled frame.
class OutputMarkItem : public ElementItem
{
public:
    OutputMarkItem(const model::Element &element, const QRectF &rect);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
};

class RailItem : public ElementItem
{
public:
    RailItem(const model::Element &element, const QRectF &rect);
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
};

// A network's band: its number (0001, as CODESYS counts), a separator line, its label and
// comment. Clicking the number puts the cursor on the network.
class NetworkItem : public QGraphicsItem
{
public:
    enum { Type = UserType + 0x150 };

    NetworkItem(int number, const QRectF &band, const QString &label, const QRectF &labelRect, const QString &comment,
        const QRectF &commentRect, bool freehand);
    int type() const override { return Type; }
    QRectF boundingRect() const override { return m_band; }
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

    [[nodiscard]] int number() const { return m_number; }
    void setNumber(int number);
    void setCurrent(bool current);
    // Online: a breakpoint or the halt position may colour the number later; kept simple here.
    [[nodiscard]] QRectF numberRect() const;

private:
    int m_number;
    QRectF m_band;
    QString m_label;
    QRectF m_labelRect;
    QString m_comment;
    QRectF m_commentRect;
    bool m_freehand;
    bool m_current = false;
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
