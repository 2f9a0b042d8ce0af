#include "editors/common/networkitems.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QPainter>

namespace iec::editors {

using namespace model;

namespace {

const QColor kInk(0x20, 0x20, 0x20);
const QColor kComment(0x20, 0x80, 0x20);
const QColor kBand(0xf4, 0xf6, 0xfa);

QPen symbolPen(bool powered)
{
    return powered ? QPen(kPowerBlue, 2.5) : QPen(kInk, 1.4);
}

} // namespace

// ---- outputs

OutputMarkItem::OutputMarkItem(const Element &element, const QRectF &rect)
    : ElementItem(element, rect)
{
}

void OutputMarkItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const double h = m_size.height();
    painter->setPen(symbolPen(isActive()));
    if (const auto *jump = std::get_if<Jump>(&m_element)) {
        // An arrow, then the label it jumps to.
        painter->drawLine(QPointF(0, h / 2), QPointF(14, h / 2));
        painter->setBrush(isActive() ? kPowerBlue : kInk);
        painter->drawPolygon(QPolygonF {QPointF(10, h / 2 - 5), QPointF(18, h / 2), QPointF(10, h / 2 + 5)});
        paintName(painter, jump->label, QRectF(22, 0, m_size.width() - 22, h), Qt::AlignLeft);
    } else {
        painter->setBrush(Qt::white);
        painter->drawRect(localFrame().adjusted(0, 2, 0, -2));
        paintName(painter, std::holds_alternative<Return>(m_element) ? QStringLiteral("RETURN") : QString(), localFrame(), Qt::AlignHCenter);
    }
    paintDecorations(painter);
}

// ---- networks

NetworkItem::NetworkItem(int number, const QRectF &band, const QString &label, const QRectF &labelRect,
    const QString &comment, const QRectF &commentRect, bool freehand)
    : m_number(number)
    , m_band(band)
    , m_label(label)
    , m_labelRect(labelRect)
    , m_comment(comment)
    , m_commentRect(commentRect)
    , m_freehand(freehand)
{
    setZValue(-2);
    if (!comment.isEmpty())
        setToolTip(comment);
}

void NetworkItem::setNumber(int number)
{
    if (m_number == number)
        return;
    m_number = number;
    update();
}

QRectF NetworkItem::numberRect() const
{
    return QRectF(m_band.left(), m_band.top(), 44, 20);
}

void NetworkItem::setCurrent(bool current)
{
    if (m_current == current)
        return;
    m_current = current;
    update();
}

void NetworkItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    if (m_current)
        painter->fillRect(m_band, kBand);
    painter->setPen(QPen(QColor(0xc8, 0xcc, 0xd4), 1));
    painter->drawLine(m_band.bottomLeft(), m_band.bottomRight());
    QFont font = blockFont();
    painter->setFont(font);
    painter->setPen(m_current ? kSelectionColor : QColor(0x70, 0x70, 0x70));
    painter->drawText(numberRect().adjusted(4, 2, 0, 0), Qt::AlignLeft | Qt::AlignTop, QStringLiteral("%1").arg(m_number, 4, 10, QLatin1Char('0')));
    if (m_current) {
        painter->setPen(QPen(kSelectionColor, 1, Qt::DashLine));
        painter->drawRect(numberRect().adjusted(1, 1, -1, -1));
    }
    if (!m_label.isEmpty()) {
        font.setBold(true);
        painter->setFont(font);
        painter->setPen(kInk);
        painter->drawText(m_labelRect, Qt::AlignLeft | Qt::AlignVCenter, m_label + QLatin1Char(':'));
        font.setBold(false);
    }
    if (!m_comment.isEmpty()) {
        font.setItalic(true);
        painter->setFont(font);
        painter->setPen(kComment);
        // A line longer than the network ends in "…" (the whole comment is the tool tip).
        const QFontMetricsF metrics(font);
        QStringList lines = m_comment.split(QLatin1Char('\n'));
        for (QString &line : lines)
            line = metrics.elidedText(line, Qt::ElideRight, m_commentRect.width());
        painter->drawText(m_commentRect, Qt::AlignLeft | Qt::AlignTop, lines.join(QLatin1Char('\n')));
    }
    if (m_freehand) {
        font.setItalic(true);
        painter->setFont(font);
        painter->setPen(QColor(0x90, 0x90, 0x90));
        painter->drawText(QRectF(m_band.left() + 4, m_band.bottom() - 16, 40, 14), Qt::AlignLeft,
            QCoreApplication::translate("iec::editors::ld::LdEditor", "free"));
    }
}

} // namespace iec::editors
