#include "editors/common/textmetrics.h"

#include <algorithm>
#include <cmath>

namespace iec::editors {

double textWidth(const QString &text)
{
    double width = 0;
    for (const QChar c : text)
        width += c.unicode() >= 0x2E80 ? 13 : (c.isUpper() || c.isDigit() ? 7.5 : 6.5);
    return std::ceil(width);
}

double roundUp(double value, double step)
{
    return std::ceil(value / step) * step;
}

double boxWidth(const model::Block &block)
{
    double left = 0;
    double right = 0;
    for (const model::BlockVariable &v : block.inputVariables)
        left = std::max(left, textWidth(v.formalParameter));
    for (const model::BlockVariable &v : block.inOutVariables)
        left = std::max(left, textWidth(v.formalParameter));
    for (const model::BlockVariable &v : block.outputVariables)
        right = std::max(right, textWidth(v.formalParameter));
    return roundUp(std::max({60.0, left + right + 24, textWidth(block.typeName) + 16}), 10);
}

QSizeF sinkOrVariableSize(const model::Element &element)
{
    constexpr double kRow = 20;
    if (const auto *jump = std::get_if<model::Jump>(&element))
        return {roundUp(textWidth(jump->label) + 30, 10), kRow};
    if (std::holds_alternative<model::Return>(element))
        return {roundUp(textWidth(QStringLiteral("RETURN")) + 16, 10), kRow};
    QString text;
    if (const auto *in = std::get_if<model::InVariable>(&element))
        text = in->expression;
    else if (const auto *out = std::get_if<model::OutVariable>(&element))
        text = out->expression;
    else if (const auto *inOut = std::get_if<model::InOutVariable>(&element))
        text = inOut->expression;
    return {roundUp(std::max(40.0, textWidth(text) + 14), 10), kRow};
}

} // namespace iec::editors
