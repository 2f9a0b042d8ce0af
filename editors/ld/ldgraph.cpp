#include "editors/ld/ldgraph.h"

#include <algorithm>
#include <limits>

namespace iec::editors::ld {

using namespace model;

namespace {

// Calls `visit(pin, point)` for every input point of an element, numbered as LdGraph says.
template<class Visit> void forEachInput(const Element &element, Visit visit)
{
    if (const auto *block = std::get_if<Block>(&element)) {
        int pin = 0;
        for (const auto *list : {&block->inputVariables, &block->inOutVariables}) {
            for (const BlockVariable &variable : *list) {
                if (variable.connectionPointIn)
                    visit(pin, *variable.connectionPointIn);
                ++pin;
            }
        }
        return;
    }
    for (const ConnectionPointIn *point : inputPoints(element))
        visit(0, *point);
}

} // namespace

LdGraph::LdGraph(const std::vector<Element> &elements)
    : m_elements(elements)
    , m_inputs(elements.size())
    , m_readers(elements.size())
{
    std::unordered_map<quint64, std::size_t> index;
    index.reserve(elements.size());
    for (std::size_t i = 0; i < elements.size(); ++i)
        index.emplace(header(elements[i]).localId, i);
    for (std::size_t i = 0; i < elements.size(); ++i) {
        forEachInput(elements[i], [&](int pin, const ConnectionPointIn &point) {
            for (const Connection &c : point.connections) {
                const auto source = index.find(c.refLocalId);
                if (source == index.end())
                    continue;
                const int sourcePin = outputPinIndex(elements[source->second], c.formalParameter);
                m_inputs[i].push_back(Wire {pin, source->second, sourcePin});
                m_readers[source->second].push_back(Reader {i, pin, sourcePin});
            }
        });
    }
}

bool LdGraph::isRail(std::size_t i) const
{
    return std::holds_alternative<LeftPowerRail>(m_elements[i]) || std::holds_alternative<RightPowerRail>(m_elements[i]);
}

double LdGraph::top(const std::vector<std::size_t> &indices) const
{
    double top = std::numeric_limits<double>::max();
    for (std::size_t i : indices)
        top = std::min(top, position(i).y);
    return indices.empty() ? 0 : top;
}

double LdGraph::bottom(const std::vector<std::size_t> &indices) const
{
    double bottom = std::numeric_limits<double>::lowest();
    for (std::size_t i : indices)
        bottom = std::max(bottom, position(i).y + header(m_elements[i]).height.value_or(0));
    return indices.empty() ? 0 : bottom;
}

} // namespace iec::editors::ld
