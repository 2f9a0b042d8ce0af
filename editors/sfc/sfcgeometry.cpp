#include "editors/sfc/sfcgeometry.h"

#include "model/body.h"

#include <algorithm>
#include <cmath>

namespace iec::editors::sfc {

using namespace model;

namespace {

// Advance widths of the chart font (DejaVu Sans, 12 px) for the printable ASCII characters, from
// the font's metrics table, so labels are measured as drawn without a QGuiApplication.
constexpr double kAdvance[95] = {
    3.81, 4.81, 5.52, 10.05, 7.63, 11.4, 9.36, 3.3, 4.68, 4.68, 6.0, 10.05, 3.81, 4.33, 3.81, 4.04, //  !"#$%&'()*+,-./
    7.63, 7.63, 7.63, 7.63, 7.63, 7.63, 7.63, 7.63, 7.63, 7.63, 4.04, 4.04, 10.05, 10.05, 10.05, 6.37, // 0-9:;<=>?
    12.0, 8.21, 8.23, 8.38, 9.24, 7.58, 6.9, 9.3, 9.02, 3.54, 3.54, 7.87, 6.69, 10.35, 8.98, 9.45, // @A-O
    7.24, 9.45, 8.34, 7.62, 7.33, 8.78, 8.21, 11.87, 8.22, 7.33, 8.22, 4.68, 4.04, 4.68, 10.05, 6.0, // P-Z[\]^_
    6.0, 7.35, 7.62, 6.6, 7.62, 7.38, 4.22, 7.62, 7.61, 3.33, 3.33, 6.95, 3.33, 11.69, 7.61, 7.34, // `a-o
    7.62, 7.62, 4.93, 6.25, 4.71, 7.61, 7.1, 9.81, 7.1, 7.1, 6.3, 7.63, 4.04, 7.63, 10.05}; // p-z{|}~

} // namespace

double textWidth(const QString &text)
{
    double width = 0;
    for (const QChar c : text) {
        const char16_t code = c.unicode();
        // Anything else (umlauts, CJK in comments) is counted as wide as the widest letter.
        width += code >= 32 && code < 127 ? kAdvance[code - 32] : 12.0;
    }
    return std::ceil(width);
}

double stepWidth(const QString &name)
{
    return std::max(kStepMinWidth, 10.0 * std::ceil((textWidth(name) + 20) / 10.0));
}

QString conditionText(const Transition &transition)
{
    if (!transition.condition)
        return {};
    const Condition &condition = *transition.condition;
    QString text;
    if (const auto *reference = std::get_if<Reference>(&condition.kind))
        text = reference->name;
    else if (const auto *inlined = std::get_if<InlineCondition>(&condition.kind)) {
        text = inlined->body->text().trimmed();
        if (text.endsWith(QLatin1Char(';')))
            text.chop(1);
        const qsizetype newline = text.indexOf(QLatin1Char('\n'));
        if (newline >= 0)
            text = text.left(newline).trimmed() + QStringLiteral(" …");
    } else
        return {};
    return condition.negated ? QStringLiteral("NOT ") + text : text;
}

QString transitionLabel(const Transition &transition)
{
    const QString text = conditionText(transition);
    return transition.priority ? QStringLiteral("(%1) ").arg(*transition.priority) + text : text;
}

QRectF labelRect(const Element &element)
{
    const QRectF frame = elementRect(element);
    if (const auto *transition = std::get_if<Transition>(&element)) {
        const QString label = transitionLabel(*transition);
        if (label.isEmpty())
            return {};
        return {frame.right() + kLabelGap, frame.center().y() - kLabelHeight / 2, textWidth(label), kLabelHeight};
    }
    if (const auto *jump = std::get_if<JumpStep>(&element))
        return {frame.right() + kLabelGap, frame.center().y() - kLabelHeight / 2, textWidth(jump->targetName), kLabelHeight};
    return {};
}

QRectF drawnRect(const Element &element)
{
    const QRectF label = labelRect(element);
    return label.isEmpty() ? elementRect(element) : elementRect(element).united(label);
}

double labelRoom(const QRectF &label, const QList<QRectF> &obstacles)
{
    constexpr double kClearance = 4;
    double room = -1;
    for (const QRectF &obstacle : obstacles) {
        const bool sameRow = obstacle.bottom() >= label.top() && obstacle.top() <= label.bottom();
        if (!sameRow || obstacle.right() <= label.left() + 1)
            continue;
        const double width = std::max(0.0, std::max(obstacle.left(), label.left()) - label.left() - kClearance);
        room = room < 0 ? width : std::min(room, width);
    }
    return room;
}

QString qualifierText(const ActionBlockAction &action)
{
    QString text = action.qualifier.value_or(QStringLiteral("N"));
    if (action.duration && !action.duration->isEmpty())
        text += QLatin1Char(' ') + *action.duration;
    return text;
}

QString actionName(const ActionBlockAction &action)
{
    if (action.reference)
        return action.reference->name;
    if (action.inlineBody) {
        QString text = (*action.inlineBody)->text().simplified();
        return text.isEmpty() ? QStringLiteral("(inline)") : text.left(24);
    }
    return {};
}

ActionBlockColumns actionBlockColumns(const ActionBlock &block)
{
    ActionBlockColumns columns;
    for (const ActionBlockAction &action : block.actions) {
        columns.qualifier = std::max(columns.qualifier, textWidth(qualifierText(action)) + 10);
        columns.name = std::max(columns.name, textWidth(actionName(action)) + 12);
        if (action.indicator && !action.indicator->isEmpty())
            columns.indicator = std::max(columns.indicator, textWidth(*action.indicator) + 12);
    }
    return columns;
}

bool isBar(const Element &e)
{
    return std::holds_alternative<SelectionDivergence>(e) || std::holds_alternative<SelectionConvergence>(e)
        || std::holds_alternative<SimultaneousDivergence>(e) || std::holds_alternative<SimultaneousConvergence>(e);
}

namespace {

QSizeF defaultSize(const Element &e)
{
    if (const auto *step = std::get_if<Step>(&e))
        return {stepWidth(step->name), kStepHeight};
    if (const auto *macro = std::get_if<MacroStep>(&e))
        return {stepWidth(macro->name.value_or(QString())), kStepHeight};
    if (std::holds_alternative<Transition>(e))
        return {kTransitionWidth, kTransitionHeight};
    if (std::holds_alternative<JumpStep>(e))
        return {kJumpWidth, kJumpHeight};
    if (std::holds_alternative<SimultaneousDivergence>(e) || std::holds_alternative<SimultaneousConvergence>(e))
        return {1, kParallelBarHeight};
    if (isBar(e))
        return {1, kSelectionBarHeight};
    if (const auto *variable = std::get_if<InVariable>(&e))
        return {std::max(40.0, textWidth(variable->expression) + 12), 20};
    if (const auto *block = std::get_if<ActionBlock>(&e))
        return {actionBlockColumns(*block).total(), kActionRow * double(std::max<std::size_t>(1, block->actions.size()))};
    return {60, 20};
}

template<class T> std::optional<Position> relIn(const T &x)
{
    if constexpr (requires { x.connectionPointIn; }) {
        if (x.connectionPointIn && x.connectionPointIn->relPosition)
            return x.connectionPointIn->relPosition;
    }
    return std::nullopt;
}

template<class T> std::optional<Position> relOut(const T &x)
{
    if constexpr (requires { x.connectionPointOut; }) {
        if constexpr (requires { x.connectionPointOut->relPosition; }) {
            if (x.connectionPointOut && x.connectionPointOut->relPosition)
                return x.connectionPointOut->relPosition;
        }
    }
    return std::nullopt;
}

} // namespace

QRectF elementRect(const Element &e)
{
    const ElementHeader &h = header(e);
    const QSizeF fallback = defaultSize(e);
    double width = h.width.value_or(fallback.width());
    double height = h.height.value_or(fallback.height());
    // Our own steps grow with their names; a file's sizes are kept.
    if (std::holds_alternative<Step>(e) || std::holds_alternative<MacroStep>(e))
        width = std::max(width, 20.0);
    return {h.position.x, h.position.y, std::max(width, 1.0), std::max(height, 1.0)};
}

QPointF inputPoint(const Element &e)
{
    const QRectF rect = elementRect(e);
    const std::optional<Position> rel = std::visit([](const auto &x) { return relIn(x); }, e);
    if (rel && !isBar(e))
        return rect.topLeft() + QPointF(rel->x, rel->y);
    return {rect.center().x(), rect.top()};
}

QPointF outputPoint(const Element &e)
{
    const QRectF rect = elementRect(e);
    const std::optional<Position> rel = std::visit([](const auto &x) { return relOut(x); }, e);
    if (rel && !isBar(e))
        return rect.topLeft() + QPointF(rel->x, rel->y);
    return {rect.center().x(), rect.bottom()};
}

QList<QPointF> wirePolyline(const Element &source, const Element &target)
{
    QPointF from = outputPoint(source);
    QPointF to = inputPoint(target);
    if (isBar(source) && isBar(target)) {
        // Straight down where both bars are (a convergence on a divergence: their left ends).
        const QRectF upper = elementRect(source);
        const QRectF lower = elementRect(target);
        from = {std::clamp(lower.left(), upper.left(), upper.right()), upper.bottom()};
        to = {std::clamp(from.x(), lower.left(), lower.right()), lower.top()};
    } else if (isBar(source)) {
        const QRectF bar = elementRect(source);
        from = {std::clamp(to.x(), bar.left(), bar.right()), bar.bottom()};
    } else if (isBar(target)) {
        const QRectF bar = elementRect(target);
        to = {std::clamp(from.x(), bar.left(), bar.right()), bar.top()};
    }
    if (qFuzzyCompare(from.x() + 1, to.x() + 1))
        return {from, to};
    const double middle = to.y() > from.y() ? (from.y() + to.y()) / 2 : from.y() + kGap / 2;
    return {from, {from.x(), middle}, {to.x(), middle}, to};
}

} // namespace iec::editors::sfc
