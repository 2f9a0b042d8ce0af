#include "editors/cfc/cfcitems.h"

#include "editors/common/textmetrics.h"

#include <QPainter>

namespace iec::editors::cfc {

using namespace model;

namespace {

const QColor kInk(0x20, 0x20, 0x20);
const QColor kCommentInk(0x20, 0x70, 0x20);
const QColor kCommentGround(0xfb, 0xfa, 0xe8);
const QColor kOrderGround(0xe6, 0xec, 0xf6);

} // namespace

CfcMarkItem::CfcMarkItem(const Element &element, const QRectF &rect)
    : ElementItem(element, rect)
{
}

void CfcMarkItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const QRectF frame = localFrame();
    const double h = frame.height();
    if (const auto *comment = std::get_if<Comment>(&m_element)) {
        painter->setPen(QPen(QColor(0xc8, 0xc4, 0x98), 1));
        painter->setBrush(kCommentGround);
        painter->drawRect(frame);
        painter->setFont(blockFont());
        painter->setPen(kCommentInk);
        painter->drawText(frame.adjusted(6, 4, -4, -4), Qt::AlignLeft | Qt::AlignTop | Qt::TextDontClip, comment->content.text);
    } else if (const auto *vendor = std::get_if<VendorElement>(&m_element)) {
        painter->setPen(QPen(kInk, 1.2, Qt::DashLine));
        painter->setBrush(Qt::white);
        painter->drawRect(frame);
        paintName(painter, vendor->alternativeText.text.simplified(), frame, Qt::AlignHCenter);
    } else if (const auto *label = std::get_if<Label>(&m_element)) {
        paintName(painter, label->label + QLatin1Char(':'), frame.adjusted(4, 0, 0, 0), Qt::AlignLeft);
    } else {
        // A connection mark: a frame with a point on the side where the wire leaves it or
        // enters the element it stands for.
        const bool connector = std::holds_alternative<Connector>(m_element);
        const QString name = connector ? std::get<Connector>(m_element).name : std::get<Continuation>(m_element).name;
        const double w = frame.width();
        QPolygonF outline;
        if (connector)
            outline << QPointF(0, 2) << QPointF(w - 10, 2) << QPointF(w, h / 2) << QPointF(w - 10, h - 2) << QPointF(0, h - 2);
        else
            outline << QPointF(0, h / 2) << QPointF(10, 2) << QPointF(w, 2) << QPointF(w, h - 2) << QPointF(10, h - 2);
        painter->setPen(QPen(isActive() ? kPowerBlue : kInk, 1.2));
        painter->setBrush(Qt::white);
        painter->drawPolygon(outline);
        paintName(painter, name, connector ? frame.adjusted(4, 0, -10, 0) : frame.adjusted(12, 0, -4, 0), Qt::AlignHCenter);
    }
    paintDecorations(painter);
}

OrderNumberItem::OrderNumberItem(int number, ElementItem *parent)
    : QGraphicsItem(parent)
    , m_number(number)
{
    // Above the top right corner, clear of a box's instance name in the middle.
    const double width = roundUp(textWidth(QString::number(number)) + 6, 2);
    m_rect = QRectF(parent->localFrame().right() - width, -13, width, 12);
    setAcceptedMouseButtons(Qt::NoButton);
}

QRectF OrderNumberItem::boundingRect() const
{
    return m_rect.adjusted(-1, -1, 1, 1);
}

void OrderNumberItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    painter->setPen(QPen(QColor(0x60, 0x70, 0x90), 1));
    painter->setBrush(kOrderGround);
    painter->drawRect(m_rect);
    QFont font = blockFont();
    font.setPixelSize(9);
    painter->setFont(font);
    painter->setPen(kInk);
    painter->drawText(m_rect, Qt::AlignCenter, QString::number(m_number));
}

} // namespace iec::editors::cfc
