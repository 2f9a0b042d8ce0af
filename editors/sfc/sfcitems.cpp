#include "editors/sfc/sfcitems.h"

#include "editors/sfc/sfcgeometry.h"
#include "model/body.h"
#include "model/sfcoptions.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QPainter>

namespace iec::editors::sfc {

using namespace model;

namespace {

const QColor kInk(0x20, 0x20, 0x20);
const QColor kActiveFill(0x1f, 0x4f, 0xd8); // CODESYS online blue
const QColor kTrueColor(0x12, 0x9b, 0x2e);
const QColor kSelection(0x30, 0x80, 0xff);
const QColor kMissing(0xc0, 0x20, 0x20);

QPen inkPen(double width = 1.2)
{
    return QPen(kInk, width, Qt::SolidLine, Qt::SquareCap, Qt::MiterJoin);
}

QString documentationOf(const Element &element)
{
    const auto &doc = header(element).documentation;
    return doc ? doc->text : QString();
}

} // namespace

QFont chartFont()
{
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setPixelSize(12);
    return font;
}

SfcItem::SfcItem(const Element &element)
    : DiagramItem(header(element).localId)
    , m_element(element)
    , m_frame(elementRect(element))
    , m_bounds(m_frame)
{
}

QRectF SfcItem::boundingRect() const
{
    return m_bounds.adjusted(-3, -3, 3, 3);
}

void SfcItem::setLabelRoom(double width)
{
    prepareGeometryChange();
    m_labelRoom = width;
    const QRectF label = labelRect(m_element);
    m_bounds = m_frame;
    if (!label.isEmpty()) {
        QRectF shown = label;
        if (m_labelRoom >= 0)
            shown.setWidth(std::min(label.width(), m_labelRoom));
        m_bounds = m_bounds.united(shown);
    }
}

QString SfcItem::shownLabel() const
{
    QString label;
    if (const auto *transition = std::get_if<Transition>(&m_element))
        label = transitionLabel(*transition);
    else if (const auto *jump = std::get_if<JumpStep>(&m_element))
        label = jump->targetName;
    if (label.isEmpty() || m_labelRoom < 0 || textWidth(label) <= m_labelRoom)
        return label;
    const QFontMetricsF metrics(chartFont());
    return metrics.elidedText(label, Qt::ElideRight, std::max(m_labelRoom, 0.0));
}

void SfcItem::paintLabel(QPainter *painter) const
{
    const QString label = shownLabel();
    if (label.isEmpty())
        return;
    painter->setFont(chartFont());
    // Drawn unclipped: the room was measured with the same widths the layout uses.
    const QRectF row(m_frame.right() + kLabelGap, m_frame.center().y() - kLabelHeight / 2, 2000, kLabelHeight);
    painter->drawText(row, Qt::AlignLeft | Qt::AlignVCenter, label);
}

void SfcItem::paintSelection(QPainter *painter) const
{
    if (!isSelected())
        return;
    painter->save();
    painter->setPen(QPen(kSelection, 1, Qt::DashLine));
    painter->setBrush(Qt::NoBrush);
    painter->drawRect(m_frame.adjusted(-3, -3, 3, 3));
    painter->restore();
}

// ---- steps

StepItem::StepItem(const Element &element)
    : SfcItem(element)
{
    QString tip;
    if (const auto *step = std::get_if<Step>(&element)) {
        m_options = stepOptions(*step);
        const StepOptions &options = m_options;
        tip = step->initialStep ? QCoreApplication::translate("iec::editors::sfc::SfcItem", "Initial step %1").arg(step->name) : QCoreApplication::translate("iec::editors::sfc::SfcItem", "Step %1").arg(step->name);
        if (!options.entryAction.isEmpty())
            tip += QLatin1Char('\n') + QCoreApplication::translate("iec::editors::sfc::SfcItem", "Entry action: %1").arg(options.entryAction);
        if (!options.exitAction.isEmpty())
            tip += QLatin1Char('\n') + QCoreApplication::translate("iec::editors::sfc::SfcItem", "Exit action: %1").arg(options.exitAction);
        if (!options.activeAction.isEmpty())
            tip += QLatin1Char('\n') + QCoreApplication::translate("iec::editors::sfc::SfcItem", "Active action: %1").arg(options.activeAction);
        if (!options.minTime.isEmpty() || !options.maxTime.isEmpty())
            tip += QLatin1Char('\n') + QCoreApplication::translate("iec::editors::sfc::SfcItem", "Time: minimum %1, maximum %2")
                                          .arg(options.minTime.isEmpty() ? QStringLiteral("-") : options.minTime,
                                              options.maxTime.isEmpty() ? QStringLiteral("-") : options.maxTime);
    } else if (const auto *macro = std::get_if<MacroStep>(&element)) {
        tip = QCoreApplication::translate("iec::editors::sfc::SfcItem", "Macro step %1 (double-click to open)").arg(macro->name.value_or(QString()));
    }
    const QString comment = documentationOf(element);
    if (!comment.isEmpty())
        tip += QLatin1Char('\n') + comment;
    setToolTip(tip);
}

StepItem::Corner StepItem::cornerAt(QPointF p) const
{
    const double size = std::min(14.0, m_frame.height() / 2);
    if (QRectF(m_frame.left(), m_frame.bottom() - size, size, size).contains(p))
        return Corner::Entry;
    if (QRectF(m_frame.right() - size, m_frame.bottom() - size, size, size).contains(p))
        return Corner::Exit;
    if (QRectF(m_frame.right() - size, m_frame.top(), size, size).contains(p))
        return Corner::Active;
    return Corner::None;
}

void StepItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    painter->setFont(chartFont());
    const bool active = isActive();
    painter->setPen(inkPen());
    painter->setBrush(active ? QBrush(kActiveFill) : QBrush(Qt::white));
    painter->drawRect(m_frame);
    QString name;
    const StepOptions &options = m_options;
    bool initial = false;
    bool macro = false;
    if (const auto *step = std::get_if<Step>(&m_element)) {
        name = step->name;
        initial = step->initialStep;
    } else if (const auto *macroStep = std::get_if<MacroStep>(&m_element)) {
        name = macroStep->name.value_or(QString());
        macro = true;
    }
    painter->setBrush(Qt::NoBrush);
    if (initial)
        painter->drawRect(m_frame.adjusted(3, 3, -3, -3));
    if (macro) {
        painter->drawLine(QPointF(m_frame.left(), m_frame.top() + 4), QPointF(m_frame.right(), m_frame.top() + 4));
        painter->drawLine(QPointF(m_frame.left(), m_frame.bottom() - 4), QPointF(m_frame.right(), m_frame.bottom() - 4));
    }
    const QColor text = active ? Qt::white : kInk;
    painter->setPen(text);
    const QString elapsed = onlineText();
    if (elapsed.isEmpty()) {
        painter->drawText(m_frame, Qt::AlignCenter, name);
    } else {
        QRectF top = m_frame;
        top.setBottom(m_frame.center().y() + 2);
        QRectF bottom = m_frame;
        bottom.setTop(m_frame.center().y());
        painter->drawText(top, Qt::AlignCenter, name);
        QFont small = chartFont();
        small.setPixelSize(10);
        painter->setFont(small);
        painter->drawText(bottom, Qt::AlignCenter, elapsed);
        painter->setFont(chartFont());
    }
    QFont marker = chartFont();
    marker.setPixelSize(9);
    marker.setBold(true);
    painter->setFont(marker);
    if (!options.entryAction.isEmpty())
        painter->drawText(QRectF(m_frame.left() + 2, m_frame.bottom() - 12, 10, 11), Qt::AlignCenter, QStringLiteral("E"));
    if (!options.exitAction.isEmpty())
        painter->drawText(QRectF(m_frame.right() - 12, m_frame.bottom() - 12, 10, 11), Qt::AlignCenter, QStringLiteral("X"));
    if (!options.activeAction.isEmpty()) {
        painter->setBrush(text);
        painter->setPen(Qt::NoPen);
        const QPointF corner = m_frame.topRight();
        painter->drawPolygon(QPolygonF({corner, corner + QPointF(-9, 0), corner + QPointF(0, 9)}));
    }
    paintSelection(painter);
}

// ---- transitions

TransitionItem::TransitionItem(const Element &element)
    : SfcItem(element)
{
    const auto &transition = std::get<Transition>(element);
    setLabelRoom(-1);
    QString tip = QCoreApplication::translate("iec::editors::sfc::SfcItem", "Transition: %1").arg(conditionText(transition));
    if (transition.condition && std::holds_alternative<InlineCondition>(transition.condition->kind)) {
        const QString full = std::get<InlineCondition>(transition.condition->kind).body->text();
        if (full.contains(QLatin1Char('\n')))
            tip += QLatin1Char('\n') + full;
    }
    setToolTip(tip);
}

QPainterPath TransitionItem::shape() const
{
    QPainterPath path;
    path.addRect(m_bounds.adjusted(-4, -6, 0, 6));
    return path;
}

void TransitionItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    const bool conditionTrue = isActive();
    const QColor colour = conditionTrue ? kTrueColor : kInk;
    painter->setPen(Qt::NoPen);
    painter->setBrush(colour);
    painter->drawRect(m_frame);
    painter->setPen(colour);
    paintLabel(painter);
    paintSelection(painter);
}

// ---- jumps

JumpItem::JumpItem(const Element &element, bool targetExists)
    : SfcItem(element)
    , m_targetExists(targetExists)
{
    const QString target = std::get<JumpStep>(element).targetName;
    setLabelRoom(-1);
    setToolTip(targetExists ? QCoreApplication::translate("iec::editors::sfc::SfcItem", "Jump to step %1").arg(target)
                            : QCoreApplication::translate("iec::editors::sfc::SfcItem", "Jump to step %1, which does not exist").arg(target));
}

void JumpItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    const QColor colour = m_targetExists ? kInk : kMissing;
    painter->setPen(Qt::NoPen);
    painter->setBrush(colour);
    const QRectF f = m_frame;
    painter->drawPolygon(QPolygonF({QPointF(f.left() + 2, f.top()), QPointF(f.right() - 2, f.top()), QPointF(f.center().x(), f.bottom())}));
    painter->setPen(colour);
    paintLabel(painter);
    paintSelection(painter);
}

// ---- divergence and convergence bars

BarItem::BarItem(const Element &element)
    : SfcItem(element)
{
    const bool parallel = std::holds_alternative<SimultaneousDivergence>(element)
        || std::holds_alternative<SimultaneousConvergence>(element);
    const bool divergence = std::holds_alternative<SelectionDivergence>(element)
        || std::holds_alternative<SimultaneousDivergence>(element);
    setToolTip(parallel ? (divergence ? QCoreApplication::translate("iec::editors::sfc::SfcItem", "Parallel branch (start)") : QCoreApplication::translate("iec::editors::sfc::SfcItem", "Parallel branch (end)"))
                        : (divergence ? QCoreApplication::translate("iec::editors::sfc::SfcItem", "Alternative branch (start)") : QCoreApplication::translate("iec::editors::sfc::SfcItem", "Alternative branch (end)")));
    m_bounds = m_frame.adjusted(-4, -3, 4, 3);
}

QPainterPath BarItem::shape() const
{
    QPainterPath path;
    path.addRect(m_frame.adjusted(-4, -4, 4, 4));
    return path;
}

void BarItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    const bool parallel = std::holds_alternative<SimultaneousDivergence>(m_element)
        || std::holds_alternative<SimultaneousConvergence>(m_element);
    painter->setPen(inkPen(1.2));
    const double left = m_frame.left() - (parallel ? 6 : 0);
    const double right = m_frame.right() + (parallel ? 6 : 0);
    if (parallel) {
        painter->drawLine(QPointF(left, m_frame.top()), QPointF(right, m_frame.top()));
        painter->drawLine(QPointF(left, m_frame.bottom()), QPointF(right, m_frame.bottom()));
    } else {
        painter->drawLine(QPointF(left, m_frame.top()), QPointF(right, m_frame.top()));
    }
    paintSelection(painter);
}

// ---- action blocks

ActionBlockItem::ActionBlockItem(const Element &element)
    : SfcItem(element)
{
    const auto &block = std::get<ActionBlock>(element);
    QStringList lines;
    for (const ActionBlockAction &action : block.actions) {
        QString line = qualifierText(action) + QStringLiteral(" | ") + actionName(action);
        if (action.indicator)
            line += QStringLiteral(" | ") + *action.indicator;
        lines << line;
    }
    setToolTip(lines.join(QLatin1Char('\n')));
}

int ActionBlockItem::rowAt(QPointF p) const
{
    if (!m_frame.contains(p))
        return -1;
    const auto &block = std::get<ActionBlock>(m_element);
    const int row = int((p.y() - m_frame.top()) / kActionRow);
    return row >= 0 && std::size_t(row) < block.actions.size() ? row : -1;
}

void ActionBlockItem::setActiveActions(const QSet<QString> &names)
{
    if (m_activeActions == names)
        return;
    m_activeActions = names;
    update();
}

bool ActionBlockItem::isActionActive(int row) const
{
    const auto &block = std::get<ActionBlock>(m_element);
    if (row < 0 || std::size_t(row) >= block.actions.size())
        return false;
    return m_activeActions.contains(actionName(block.actions[std::size_t(row)]).toLower());
}

void ActionBlockItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    const auto &block = std::get<ActionBlock>(m_element);
    const ActionBlockColumns columns = actionBlockColumns(block);
    painter->setFont(chartFont());
    for (std::size_t i = 0; i < block.actions.size(); ++i) {
        const ActionBlockAction &action = block.actions[i];
        const QRectF row(m_frame.left(), m_frame.top() + kActionRow * double(i), m_frame.width(), kActionRow);
        const bool active = isActionActive(int(i));
        painter->setPen(inkPen(1));
        painter->setBrush(active ? QBrush(kActiveFill) : QBrush(Qt::white));
        painter->drawRect(row);
        const QRectF qualifier(row.left(), row.top(), columns.qualifier, row.height());
        const QRectF name(qualifier.right(), row.top(), columns.name, row.height());
        painter->drawLine(qualifier.topRight(), qualifier.bottomRight());
        painter->setPen(active ? Qt::white : kInk);
        painter->drawText(qualifier, Qt::AlignCenter, qualifierText(action));
        painter->drawText(name.adjusted(6, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter, actionName(action));
        if (columns.indicator > 0) {
            const QRectF indicator(name.right(), row.top(), columns.indicator, row.height());
            painter->setPen(inkPen(1));
            painter->drawLine(indicator.topLeft(), indicator.bottomLeft());
            painter->setPen(active ? Qt::white : kInk);
            painter->drawText(indicator.adjusted(6, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter, action.indicator.value_or(QString()));
        }
    }
    paintSelection(painter);
}

// ---- everything else

OtherItem::OtherItem(const Element &element)
    : SfcItem(element)
{
    const auto *variable = std::get_if<InVariable>(&element);
    setToolTip(variable ? variable->expression : QString::fromLatin1(elementTagName(element)));
}

void OtherItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    // A variable feeding a condition is drawn as FBD draws it: a plain box with its name.
    const bool variable = std::holds_alternative<InVariable>(m_element);
    painter->setPen(QPen(kInk, 1, variable ? Qt::SolidLine : Qt::DotLine));
    painter->setBrush(Qt::NoBrush);
    painter->drawRect(m_frame);
    painter->setFont(chartFont());
    QString text = documentationOf(m_element);
    if (const auto *comment = std::get_if<Comment>(&m_element))
        text = comment->content.text;
    else if (const auto *variable = std::get_if<InVariable>(&m_element))
        text = variable->expression;
    if (text.isEmpty())
        text = QString::fromLatin1(elementTagName(m_element));
    painter->drawText(m_frame.adjusted(4, 2, -4, -2),
        variable ? int(Qt::AlignCenter) : int(Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap), text);
    paintSelection(painter);
}

} // namespace iec::editors::sfc
