#include "editors/common/blockitems.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPathStroker>

#include <cmath>

namespace iec::editors {

using namespace model;

namespace {

constexpr double kTitleRow = 20;
constexpr double kPinPitch = 20;

const QColor kInk(0x20, 0x20, 0x20);
const QColor kValue(0x00, 0x70, 0x30);

bool isPlaceholder(const QString &text)
{
    return text.trimmed() == QLatin1String("???");
}

} // namespace

QFont blockFont()
{
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setPixelSize(11);
    return font;
}

// ---- ElementItem

ElementItem::ElementItem(const Element &element, const QRectF &rect)
    : DiagramItem(header(element).localId)
    , m_element(element)
    , m_size(rect.size())
{
    setPos(rect.topLeft());
}

QRectF ElementItem::boundingRect() const
{
    return extent().adjusted(-4, -4, 4, 4);
}

QList<Pin> ElementItem::pins() const
{
    QList<Pin> pins;
    const double middle = m_size.height() / 2;
    if (!inputPoints(m_element).empty())
        pins << Pin {Pin::Direction::In, mapToScene(QPointF(0, middle)), 0, {}, {}};
    const bool hasOutput = std::visit([](const auto &e) {
        if constexpr (requires { e.connectionPointOut; })
            return true;
        else
            return false;
    }, m_element);
    if (hasOutput)
        pins << Pin {Pin::Direction::Out, mapToScene(QPointF(m_size.width(), middle)), -1, {}, {}};
    return pins;
}

void ElementItem::setForced(bool forced)
{
    if (m_forced == forced)
        return;
    m_forced = forced;
    update();
}

void ElementItem::paintDecorations(QPainter *painter) const
{
    painter->save();
    painter->setBrush(Qt::NoBrush);
    if (isSelected()) {
        painter->setPen(QPen(kSelectionColor, 1, Qt::DashLine));
        painter->drawRect(extent().adjusted(-3, -3, 3, 3));
    }
    if (m_forced) {
        // CODESYS marks forced values with a small "F" on an orange ground.
        const QRectF mark(localFrame().right() - 2, localFrame().top() - 10, 10, 10);
        painter->setPen(Qt::NoPen);
        painter->setBrush(kForcedMark);
        painter->drawRect(mark);
        painter->setPen(Qt::white);
        QFont font = blockFont();
        font.setPixelSize(8);
        font.setBold(true);
        painter->setFont(font);
        painter->drawText(mark, Qt::AlignCenter, QStringLiteral("F"));
    }
    painter->restore();
}

void ElementItem::paintName(QPainter *painter, const QString &text, const QRectF &row, Qt::Alignment alignment) const
{
    painter->save();
    painter->setFont(blockFont());
    painter->setPen(isPlaceholder(text) ? kPlaceholderRed : kInk);
    painter->drawText(row, alignment | Qt::AlignVCenter | Qt::TextDontClip, text);
    painter->restore();
}

// ---- BoxItem

BoxItem::BoxItem(const Element &element, const QRectF &rect, std::vector<int> inputRows, std::vector<int> outputRows)
    : ElementItem(element, rect)
    , m_inputRows(std::move(inputRows))
    , m_outputRows(std::move(outputRows))
{
}

QPointF BoxItem::inputPin(int pin) const
{
    const int row = pin < int(m_inputRows.size()) ? m_inputRows[std::size_t(pin)] : pin;
    return {0, kTitleRow + row * kPinPitch + kPinPitch / 2};
}

QPointF BoxItem::outputPin(int pin) const
{
    const int row = pin < int(m_outputRows.size()) ? m_outputRows[std::size_t(pin)] : pin;
    return {m_size.width(), kTitleRow + row * kPinPitch + kPinPitch / 2};
}

QList<Pin> BoxItem::pins() const
{
    // Inputs are numbered as model::inputPoints numbers them: the variables that have a
    // connection point, inputs before in-outs.
    QList<Pin> pins;
    const auto &block = std::get<Block>(m_element);
    int index = 0;
    int pin = 0;
    for (const auto *list : {&block.inputVariables, &block.inOutVariables}) {
        for (const BlockVariable &variable : *list) {
            if (variable.connectionPointIn)
                pins << Pin {Pin::Direction::In, mapToScene(inputPin(pin)), index++, {}, variable.formalParameter};
            ++pin;
        }
    }
    for (std::size_t p = 0; p < block.outputVariables.size(); ++p) {
        const QString &name = block.outputVariables[p].formalParameter;
        pins << Pin {Pin::Direction::Out, mapToScene(outputPin(int(p))), -1, block.outputVariables.size() == 1 ? QString() : name, name};
    }
    return pins;
}

QRectF BoxItem::extent() const
{
    // The instance name above, values beside the pins.
    return localFrame().adjusted(m_pinValues.isEmpty() ? 0 : -70, -16, m_pinValues.isEmpty() ? 0 : 70, 0);
}

void BoxItem::setPinValues(const QHash<QString, QString> &values)
{
    if (values == m_pinValues)
        return;
    prepareGeometryChange();
    m_pinValues = values;
    update();
}

void BoxItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    const auto &block = std::get<Block>(m_element);
    painter->setRenderHint(QPainter::Antialiasing);
    painter->setPen(QPen(kInk, 1.2));
    painter->setBrush(QColor(0xfb, 0xfb, 0xf4));
    painter->drawRect(localFrame());
    QFont bold = blockFont();
    bold.setBold(true);
    painter->setFont(bold);
    painter->setPen(isPlaceholder(block.typeName) ? kPlaceholderRed : kInk);
    painter->drawText(QRectF(0, 0, m_size.width(), kTitleRow), Qt::AlignCenter, block.typeName);
    if (block.instanceName)
        paintName(painter, *block.instanceName, QRectF(-30, -16, m_size.width() + 60, 14), Qt::AlignHCenter);
    painter->setFont(blockFont());
    const auto pinLabel = [&](const BlockVariable &variable, QPointF at, bool input) {
        const QRectF row = input ? QRectF(at.x() + 4, at.y() - 8, m_size.width() / 2, 16)
                                 : QRectF(at.x() - 4 - m_size.width() / 2, at.y() - 8, m_size.width() / 2, 16);
        painter->setPen(kInk);
        painter->drawText(row, (input ? Qt::AlignLeft : Qt::AlignRight) | Qt::AlignVCenter, variable.formalParameter);
        if (variable.negated) {
            painter->setBrush(Qt::white);
            painter->drawEllipse(QPointF(at.x() + (input ? -4 : 4), at.y()), 4, 4);
        }
        if (variable.edge != EdgeModifier::None && input) {
            QPolygonF edge {QPointF(0, at.y() - 5), QPointF(6, at.y()), QPointF(0, at.y() + 5)};
            painter->drawPolyline(edge);
        }
        const QString value = m_pinValues.value(variable.formalParameter.toUpper());
        if (!value.isEmpty()) {
            painter->setPen(kValue);
            const QRectF outside = input ? QRectF(at.x() - 70, at.y() - 17, 66, 14) : QRectF(at.x() + 4, at.y() - 17, 66, 14);
            painter->drawText(outside, (input ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignVCenter, value);
        }
    };
    int pin = 0;
    for (const auto *list : {&block.inputVariables, &block.inOutVariables})
        for (const BlockVariable &variable : *list)
            pinLabel(variable, inputPin(pin++), true);
    for (std::size_t p = 0; p < block.outputVariables.size(); ++p) {
        const BlockVariable &variable = block.outputVariables[p];
        pinLabel(variable, outputPin(int(p)), false);
        // CODESYS writes an output's assignment into the pin itself (no outVariable).
        if (variable.connectionPointOut && variable.connectionPointOut->expression)
            paintName(painter, *variable.connectionPointOut->expression,
                QRectF(m_size.width() + 6, outputPin(int(p)).y() - 8, 200, 16), Qt::AlignLeft);
    }
    paintDecorations(painter);
}

namespace {

std::vector<int> rowsFromFile(const std::vector<BlockVariable> &pins, bool inputs)
{
    std::vector<int> rows;
    for (std::size_t p = 0; p < pins.size(); ++p) {
        const auto &rel = inputs ? (pins[p].connectionPointIn ? pins[p].connectionPointIn->relPosition : std::nullopt)
                                 : (pins[p].connectionPointOut ? pins[p].connectionPointOut->relPosition : std::nullopt);
        rows.push_back(rel ? std::max(0, int(std::lround((rel->y - kTitleRow - kPinPitch / 2) / kPinPitch))) : int(p));
    }
    return rows;
}

} // namespace

BoxItem *boxItemAsDrawn(const Element &element, const QRectF &rect)
{
    const auto &block = std::get<Block>(element);
    std::vector<BlockVariable> inputs = block.inputVariables;
    inputs.insert(inputs.end(), block.inOutVariables.begin(), block.inOutVariables.end());
    return new BoxItem(element, rect, rowsFromFile(inputs, true), rowsFromFile(block.outputVariables, false));
}

// ---- VariableItem

VariableItem::VariableItem(const Element &element, const QRectF &rect, bool framed)
    : ElementItem(element, rect)
    , m_framed(framed)
{
}

QString VariableItem::text() const
{
    if (const auto *in = std::get_if<InVariable>(&m_element))
        return in->expression;
    if (const auto *out = std::get_if<OutVariable>(&m_element))
        return out->expression;
    if (const auto *inOut = std::get_if<InOutVariable>(&m_element))
        return inOut->expression;
    return {};
}

QRectF VariableItem::extent() const
{
    if (onlineText().isEmpty())
        return localFrame();
    if (m_framed)
        return localFrame().adjusted(0, -14, 60, 0);
    return std::holds_alternative<InVariable>(m_element) ? localFrame().adjusted(-74, 0, 0, 0) : localFrame().adjusted(0, 0, 74, 0);
}

void VariableItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    painter->setRenderHint(QPainter::Antialiasing);
    const bool feedsRight = std::holds_alternative<InVariable>(m_element);
    if (m_framed) {
        painter->setPen(QPen(kInk, 1));
        painter->setBrush(Qt::white);
        painter->drawRect(localFrame());
    }
    const QRectF inner = localFrame().adjusted(4, 0, -4, 0);
    paintName(painter, text(), inner, feedsRight ? Qt::AlignRight : Qt::AlignLeft);
    if (!onlineText().isEmpty()) {
        painter->setFont(blockFont());
        painter->setPen(isActive() ? kPowerBlue : kValue);
        // A framed variable (on a wire) carries its value above it; a plain one beside its name,
        // on its own row, so that variables stacked row by row (a box's inputs) keep apart.
        const double nameWidth = QFontMetricsF(blockFont()).horizontalAdvance(text());
        if (m_framed)
            painter->drawText(QRectF(0, -14, m_size.width() + 60, 14), Qt::AlignLeft | Qt::AlignVCenter, onlineText());
        else if (feedsRight)
            painter->drawText(QRectF(inner.right() - nameWidth - 74, 0, 70, m_size.height()), Qt::AlignRight | Qt::AlignVCenter, onlineText());
        else
            painter->drawText(QRectF(inner.left() + nameWidth + 6, 0, 70, m_size.height()), Qt::AlignLeft | Qt::AlignVCenter, onlineText());
    }
    paintDecorations(painter);
}

// ---- WireItem

WireItem::WireItem(quint64 source, quint64 target, const QList<QPointF> &points)
    : m_source(source)
    , m_target(target)
{
    setPoints(points);
    setZValue(-1);
}

void WireItem::setPoints(const QList<QPointF> &points)
{
    prepareGeometryChange();
    m_points = points;
    m_path = QPainterPath();
    if (!points.isEmpty()) {
        m_path.moveTo(points.front());
        for (qsizetype i = 1; i < points.size(); ++i)
            m_path.lineTo(points[i]);
    }
}

QRectF WireItem::boundingRect() const
{
    return m_path.boundingRect().adjusted(-3, -3, 3, 3);
}

QPainterPath WireItem::shape() const
{
    QPainterPathStroker stroker;
    stroker.setWidth(6);
    return stroker.createStroke(m_path);
}

void WireItem::setPowered(bool powered)
{
    if (m_powered == powered)
        return;
    m_powered = powered;
    update();
}

void WireItem::setBroken(bool broken)
{
    if (m_broken == broken)
        return;
    m_broken = broken;
    // A wire without room runs straight across whatever is in the way: drawn over the elements,
    // so that the red line is seen.
    setZValue(broken ? 1 : -1);
    update();
}

void WireItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    painter->setRenderHint(QPainter::Antialiasing, m_broken);
    if (m_broken) {
        painter->setPen(QPen(kPlaceholderRed, 1.2));
        if (m_points.size() >= 2)
            painter->drawLine(m_points.front(), m_points.back());
        return;
    }
    painter->setPen(m_powered ? QPen(kPowerBlue, 3) : QPen(kInk, 1.2));
    painter->setBrush(Qt::NoBrush);
    painter->drawPath(m_path);
}

} // namespace iec::editors
