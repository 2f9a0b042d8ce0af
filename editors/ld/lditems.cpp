#include "editors/ld/lditems.h"

#include <QFontMetricsF>
#include <QPainter>

namespace iec::editors::ld {

using namespace model;

namespace {


QString variableOf(const Element &e)
{
    if (const auto *contact = std::get_if<Contact>(&e))
        return contact->variable;
    if (const auto *coil = std::get_if<Coil>(&e))
        return coil->variable;
    return {};
}

// The letter inside a contact or coil: / for negated, P or N for edges, S or R for storage.
QString modifierOf(const Element &e)
{
    const auto letters = [](bool negated, EdgeModifier edge, StorageModifier storage) {
        if (storage == StorageModifier::Set)
            return QStringLiteral("S");
        if (storage == StorageModifier::Reset)
            return QStringLiteral("R");
        if (edge == EdgeModifier::Rising)
            return QStringLiteral("P");
        if (edge == EdgeModifier::Falling)
            return QStringLiteral("N");
        return negated ? QStringLiteral("/") : QString();
    };
    if (const auto *contact = std::get_if<Contact>(&e))
        return letters(contact->negated, contact->edge, contact->storage);
    if (const auto *coil = std::get_if<Coil>(&e))
        return letters(coil->negated, coil->edge, coil->storage);
    return {};
}

QPen symbolPen(bool powered)
{
    return powered ? QPen(kPowerBlue, 2.5) : QPen(kInk, 1.4);
}

// The name above a contact or coil (with its online value after it): centred on the symbol, or
// ending at its right edge when `endAtRight` (a coil's long name; the layout keeps room on the
// left). Tight, so that a click beside the name does not hit the element.
QRectF nameRect(const QString &text, const QSizeF &size, bool endAtRight)
{
    const double width = QFontMetricsF(blockFont()).horizontalAdvance(text) + 2;
    if (endAtRight && width > size.width() + 12)
        return QRectF(size.width() + 6 - width, -17, width, 14);
    return QRectF((size.width() - width) / 2, -17, width, 14);
}

QString nameWithValue(const Element &e, const QString &online)
{
    return variableOf(e) + (online.isEmpty() ? QString() : QStringLiteral(" = ") + online);
}

} // namespace

// ---- contacts

ContactItem::ContactItem(const Element &element, const QRectF &rect)
    : ElementItem(element, rect)
{
}

QRectF ContactItem::extent() const
{
    return localFrame().united(nameRect(nameWithValue(m_element, onlineText()), m_size, false));
}

void ContactItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const double w = m_size.width();
    const double h = m_size.height();
    const double mid = h / 2;
    painter->setPen(symbolPen(isActive()));
    painter->drawLine(QPointF(0, mid), QPointF(w * 0.3, mid));
    painter->drawLine(QPointF(w * 0.7, mid), QPointF(w, mid));
    painter->drawLine(QPointF(w * 0.3, 0), QPointF(w * 0.3, h));
    painter->drawLine(QPointF(w * 0.7, 0), QPointF(w * 0.7, h));
    const QString modifier = modifierOf(m_element);
    if (modifier == QLatin1String("/"))
        painter->drawLine(QPointF(w * 0.38, h - 2), QPointF(w * 0.62, 2));
    else if (!modifier.isEmpty()) {
        QFont font = blockFont();
        font.setBold(true);
        painter->setFont(font);
        painter->drawText(QRectF(w * 0.3, 0, w * 0.4, h), Qt::AlignCenter, modifier);
    }
    const QString name = nameWithValue(m_element, onlineText());
    paintName(painter, name, nameRect(name, m_size, false), Qt::AlignHCenter);
    paintDecorations(painter);
}

// ---- coils

CoilItem::CoilItem(const Element &element, const QRectF &rect)
    : ElementItem(element, rect)
{
}

QRectF CoilItem::extent() const
{
    return localFrame().united(nameRect(nameWithValue(m_element, onlineText()), m_size, true));
}

void CoilItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const double w = m_size.width();
    const double h = m_size.height();
    const double mid = h / 2;
    painter->setPen(symbolPen(isActive()));
    painter->drawLine(QPointF(0, mid), QPointF(w * 0.25, mid));
    painter->drawLine(QPointF(w * 0.75, mid), QPointF(w, mid));
    // The two arcs of ( ).
    const QRectF left(w * 0.25, 1, w * 0.3, h - 2);
    const QRectF right(w * 0.45, 1, w * 0.3, h - 2);
    painter->drawArc(left, 100 * 16, 160 * 16);
    painter->drawArc(right, -80 * 16, 160 * 16);
    const QString modifier = modifierOf(m_element);
    if (modifier == QLatin1String("/"))
        painter->drawLine(QPointF(w * 0.4, h - 3), QPointF(w * 0.6, 3));
    else if (!modifier.isEmpty()) {
        QFont font = blockFont();
        font.setBold(true);
        painter->setFont(font);
        painter->drawText(QRectF(w * 0.25, 0, w * 0.5, h), Qt::AlignCenter, modifier);
    }
    const QString name = nameWithValue(m_element, onlineText());
    paintName(painter, name, nameRect(name, m_size, true), Qt::AlignHCenter);
    paintDecorations(painter);
}

// ---- jumps and returns

// ---- rails

RailItem::RailItem(const Element &element, const QRectF &rect)
    : ElementItem(element, rect)
{
    setFlag(ItemIsSelectable, false);
}

void RailItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    painter->fillRect(localFrame(), isActive() ? kPowerBlue : kInk);
}

// ---- wire cursor

WireCursorItem::WireCursorItem(QPointF at)
{
    setPos(at);
    setZValue(5);
}

QRectF WireCursorItem::boundingRect() const
{
    return QRectF(-6, -6, 12, 12);
}

void WireCursorItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    painter->setPen(QPen(kSelectionColor, 1));
    painter->setBrush(kSelectionColor);
    painter->drawRect(QRectF(-3.5, -3.5, 7, 7));
    painter->setBrush(Qt::NoBrush);
    painter->setPen(QPen(kSelectionColor, 1, Qt::DashLine));
    painter->drawRect(QRectF(-5.5, -5.5, 11, 11));
}

} // namespace iec::editors::ld
