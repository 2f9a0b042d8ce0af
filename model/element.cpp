#include "model/element.h"

#include "model/body.h"

#include <array>

namespace iec::model {

namespace {

// Same order as the Element variant.
constexpr std::array<const char *, std::variant_size_v<Element>> kTagNames {"comment", "error", "connector",
    "continuation", "actionBlock", "vendorElement", "block", "inVariable", "outVariable", "inOutVariable", "label",
    "jump", "return", "leftPowerRail", "rightPowerRail", "coil", "contact", "step", "macroStep", "jumpStep",
    "transition", "selectionDivergence", "selectionConvergence", "simultaneousDivergence", "simultaneousConvergence"};

template<class Variables, class Point> void collectVariablePoints(Variables &variables, std::vector<Point *> &points)
{
    for (auto &variable : variables) {
        if (variable.connectionPointIn)
            points.push_back(&*variable.connectionPointIn);
    }
}

template<class E, class Point> void collectInputPoints(E &element, std::vector<Point *> &points)
{
    if constexpr (requires { element.connectionPointIn; }) {
        if (element.connectionPointIn)
            points.push_back(&*element.connectionPointIn);
    }
    if constexpr (requires { element.connectionPointIns; }) {
        for (auto &point : element.connectionPointIns)
            points.push_back(&point);
    }
    if constexpr (requires { element.typeName; }) { // block
        collectVariablePoints(element.inputVariables, points);
        collectVariablePoints(element.inOutVariables, points);
    }
    if constexpr (requires { element.alternativeText; }) { // vendorElement
        if (element.inputVariables)
            collectVariablePoints(*element.inputVariables, points);
        if (element.inOutVariables)
            collectVariablePoints(*element.inOutVariables, points);
    }
    if constexpr (requires { element.condition; }) {
        if (element.condition) {
            if (auto *point = std::get_if<ConnectionPointIn>(&element.condition->kind))
                points.push_back(point);
        }
    }
}

} // namespace

const char *elementTagName(std::size_t variantIndex)
{
    return variantIndex < kTagNames.size() ? kTagNames[variantIndex] : "";
}

const char *elementTagName(const Element &element)
{
    return elementTagName(element.index());
}

std::vector<ConnectionPointIn *> inputPoints(Element &element)
{
    std::vector<ConnectionPointIn *> points;
    std::visit([&](auto &e) { collectInputPoints(e, points); }, element);
    return points;
}

std::vector<const ConnectionPointIn *> inputPoints(const Element &element)
{
    std::vector<const ConnectionPointIn *> points;
    std::visit([&](const auto &e) { collectInputPoints(e, points); }, element);
    return points;
}

} // namespace iec::model
