#include "interpreter/graphical/network.h"

#include "interpreter/graphical/astbuild.h"

#include <QCoreApplication>

#include <algorithm>
#include <limits>
#include <numeric>
#include <tuple>

namespace iec::interp::graphical {

namespace {

template<class... Ts> struct Overloaded : Ts... {
    using Ts::operator()...;
};
// The guide clang 14 needs (it does not deduce an aggregate's arguments without one); the fuzz
// build uses clang.
template<class... Ts> Overloaded(Ts...) -> Overloaded<Ts...>;

NodeKind kindOf(const model::Element &element)
{
    return std::visit(Overloaded {
        [](const model::Comment &) { return NodeKind::Ignored; },
        [](const model::Error &) { return NodeKind::Unsupported; },
        [](const model::Connector &) { return NodeKind::Connector; },
        [](const model::Continuation &) { return NodeKind::Continuation; },
        [](const model::ActionBlock &) { return NodeKind::Foreign; },
        [](const model::VendorElement &v) {
            const bool pins = (v.inputVariables && !v.inputVariables->empty())
                || (v.outputVariables && !v.outputVariables->empty())
                || (v.inOutVariables && !v.inOutVariables->empty());
            return pins ? NodeKind::Unsupported : NodeKind::Ignored;
        },
        [](const model::Block &) { return NodeKind::Block; },
        [](const model::InVariable &) { return NodeKind::InVariable; },
        [](const model::OutVariable &) { return NodeKind::OutVariable; },
        [](const model::InOutVariable &) { return NodeKind::InOutVariable; },
        [](const model::Label &) { return NodeKind::Label; },
        [](const model::Jump &) { return NodeKind::Jump; },
        [](const model::Return &) { return NodeKind::Return; },
        [](const model::LeftPowerRail &) { return NodeKind::LeftRail; },
        [](const model::RightPowerRail &) { return NodeKind::RightRail; },
        [](const model::Coil &) { return NodeKind::Coil; },
        [](const model::Contact &) { return NodeKind::Contact; },
        [](const auto &) { return NodeKind::Foreign; }, // SFC elements
    }, element);
}

bool inNetwork(NodeKind kind)
{
    return kind != NodeKind::Foreign && kind != NodeKind::Ignored && kind != NodeKind::Unsupported;
}

bool isRoot(NodeKind kind)
{
    switch (kind) {
    case NodeKind::Coil:
    case NodeKind::OutVariable:
    case NodeKind::InOutVariable:
    case NodeKind::Block:
    case NodeKind::Jump:
    case NodeKind::Return:
    case NodeKind::Label:
        return true;
    default:
        return false;
    }
}

// Union-find over element indices: the networks (connected groups) of a body.
struct Groups {
    std::vector<std::size_t> parent;
    explicit Groups(std::size_t n)
        : parent(n)
    {
        std::iota(parent.begin(), parent.end(), std::size_t(0));
    }
    std::size_t find(std::size_t i)
    {
        while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
        return i;
    }
    void unite(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

} // namespace

Network::Network(const std::vector<model::Element> &elements, const QString &owner, Diagnostics &diagnostics)
{
    m_nodes.reserve(elements.size());
    for (std::size_t i = 0; i < elements.size(); ++i) {
        Node node;
        node.element = &elements[i];
        node.kind = kindOf(elements[i]);
        node.localId = model::header(elements[i]).localId;
        node.fileIndex = i;
        if (m_index.contains(node.localId)) {
            diagnostics.error(owner, elementLocation(node.localId),
                QCoreApplication::translate("iec::interp::Compiler", "Two elements have the same localId %1.").arg(node.localId),
                QCoreApplication::translate("iec::interp::Compiler", "give every element its own localId"));
            m_ok = false;
        } else {
            m_index.insert(node.localId, i);
        }
        m_nodes.push_back(std::move(node));
    }
    // Connectors by name, for their continuations.
    QHash<QString, std::size_t> connectors;
    for (std::size_t i = 0; i < m_nodes.size(); ++i) {
        if (const auto *connector = std::get_if<model::Connector>(m_nodes[i].element))
            connectors.insert(connector->name.trimmed().toUpper(), i);
    }
    for (std::size_t i = 0; i < m_nodes.size(); ++i) {
        Node &node = m_nodes[i];
        if (!inNetwork(node.kind))
            continue;
        for (const model::ConnectionPointIn *point : model::inputPoints(*node.element)) {
            for (const model::Connection &connection : point->connections) {
                const auto source = indexOf(connection.refLocalId);
                if (!source || !inNetwork(m_nodes[*source].kind))
                    continue;
                node.sources.push_back(*source);
                if (node.kind != NodeKind::RightRail)
                    ++m_readers[{*source, outputKey(*source, connection.formalParameter)}];
            }
        }
        if (const auto *continuation = std::get_if<model::Continuation>(node.element)) {
            const auto connector = connectors.find(continuation->name.trimmed().toUpper());
            if (connector == connectors.end()) {
                diagnostics.error(owner, elementLocation(node.localId),
                    QCoreApplication::translate("iec::interp::Compiler", "There is no connector named '%1' for this continuation.").arg(continuation->name),
                    QCoreApplication::translate("iec::interp::Compiler", "add a connector with that name where the wire starts"));
                m_ok = false;
                continue;
            }
            m_connectorOf[i] = *connector;
            node.sources.push_back(*connector);
            ++m_readers[{*connector, QString()}];
        }
    }
}

std::optional<std::size_t> Network::indexOf(quint64 localId) const
{
    const auto found = m_index.find(localId);
    if (found == m_index.end())
        return std::nullopt;
    return *found;
}

std::optional<std::size_t> Network::connectorOf(std::size_t continuation) const
{
    const auto found = m_connectorOf.find(continuation);
    if (found == m_connectorOf.end())
        return std::nullopt;
    return found->second;
}

QString Network::outputKey(std::size_t source, const std::optional<QString> &formalParameter) const
{
    const auto *block = std::get_if<model::Block>(m_nodes[source].element);
    if (!block)
        return {};
    if (formalParameter && !formalParameter->trimmed().isEmpty())
        return formalParameter->trimmed().toUpper();
    for (const model::BlockVariable &output : block->outputVariables) {
        if (output.formalParameter.compare(QLatin1String("ENO"), Qt::CaseInsensitive) != 0)
            return output.formalParameter.trimmed().toUpper();
    }
    return block->outputVariables.empty() ? QString() : block->outputVariables.front().formalParameter.toUpper();
}

int Network::readers(std::size_t source, const QString &key) const
{
    const auto found = m_readers.find({source, key});
    return found == m_readers.end() ? 0 : found->second;
}

bool Network::isInstanceBlock(std::size_t node) const
{
    const auto *block = std::get_if<model::Block>(m_nodes[node].element);
    return block && block->instanceName && !block->instanceName->trimmed().isEmpty();
}

std::optional<std::vector<std::size_t>> Network::findCycle() const
{
    enum : char { White, Grey, Black };
    std::vector<char> colour(m_nodes.size(), White);
    for (std::size_t start = 0; start < m_nodes.size(); ++start) {
        if (colour[start] != White)
            continue;
        std::vector<std::pair<std::size_t, std::size_t>> stack {{start, 0}};
        colour[start] = Grey;
        while (!stack.empty()) {
            auto &[current, next] = stack.back();
            const std::vector<std::size_t> &sources = m_nodes[current].sources;
            if (next == sources.size()) {
                colour[current] = Black;
                stack.pop_back();
                continue;
            }
            const std::size_t source = sources[next++];
            if (isFeedback(current, source))
                continue;
            if (colour[source] == Grey) {
                std::vector<std::size_t> cycle;
                bool inCycle = false;
                for (const auto &[element, unused] : stack) {
                    inCycle = inCycle || element == source;
                    if (inCycle)
                        cycle.push_back(element);
                }
                return cycle;
            }
            if (colour[source] == White) {
                colour[source] = Grey;
                stack.emplace_back(source, 0);
            }
        }
    }
    return std::nullopt;
}

std::vector<std::size_t>::const_iterator Network::orderedLoopBreak(const std::vector<std::size_t> &cycle) const
{
    const auto orderOf = [&](std::size_t i) { return model::header(*m_nodes[i].element).executionOrderId; };
    const bool ordered = std::ranges::all_of(cycle, [&](std::size_t i) {
        return m_nodes[i].kind != NodeKind::Block || orderOf(i).has_value();
    });
    if (!ordered || std::ranges::none_of(cycle, [&](std::size_t i) { return m_nodes[i].kind == NodeKind::Block; }))
        return cycle.end();
    // cycle[j] is read by cycle[j - 1] (the first by the last). The box whose reader runs before
    // it keeps its output: the reader sees the value of the scan before, as the order says.
    auto fallback = cycle.end();
    for (std::size_t j = 0; j < cycle.size(); ++j) {
        const std::size_t source = cycle[j];
        const std::size_t reader = j == 0 ? cycle.back() : cycle[j - 1];
        if (m_nodes[source].kind != NodeKind::Block)
            continue;
        if (fallback == cycle.end())
            fallback = cycle.begin() + std::ptrdiff_t(j);
        const auto readerOrder = orderOf(reader);
        if (readerOrder && *readerOrder < *orderOf(source))
            return cycle.begin() + std::ptrdiff_t(j);
    }
    return fallback;
}

bool Network::breakLoops(const QString &owner, Diagnostics &diagnostics)
{
    // cycle[i] reads from cycle[i + 1]; the last reads from the first.
    while (const auto cycle = findCycle()) {
        auto variable = std::ranges::find_if(*cycle, [&](std::size_t i) {
            return m_nodes[i].kind == NodeKind::InOutVariable;
        });
        // A function block instance keeps its outputs from one scan to the next, so a loop
        // through one is a feedback path (IEC 61131-3 FBD; Beremiz and CODESYS accept it): the
        // reader gets the output the instance computed in the previous scan.
        if (variable == cycle->end())
            variable = std::ranges::find_if(*cycle, [&](std::size_t i) { return isInstanceBlock(i); });
        if (variable == cycle->end()) {
            variable = orderedLoopBreak(*cycle);
            if (variable != cycle->end())
                m_storedBoxes.insert(*variable);
        }
        if (variable == cycle->end()) {
            const std::size_t first = *std::ranges::min_element(*cycle);
            diagnostics.error(owner, elementLocation(m_nodes[first].localId),
                QCoreApplication::translate("iec::interp::Compiler", "The wires make a loop through %1 elements with no variable to keep the value "
                               "from one scan to the next.")
                    .arg(cycle->size()),
                QCoreApplication::translate("iec::interp::Compiler", "put a feedback variable (an in-out variable) into the loop"));
            return false;
        }
        const std::size_t reader = variable == cycle->begin() ? cycle->back() : *(variable - 1);
        m_feedback.insert({reader, *variable});
    }
    return true;
}

std::vector<std::size_t> Network::rootOrder(bool layoutGenerated) const
{
    Groups groups(m_nodes.size());
    for (std::size_t i = 0; i < m_nodes.size(); ++i) {
        if (!inNetwork(m_nodes[i].kind) || m_nodes[i].kind == NodeKind::RightRail)
            continue;
        for (const std::size_t source : m_nodes[i].sources) {
            if (m_nodes[source].kind != NodeKind::LeftRail)
                groups.unite(i, source);
        }
    }
    // Each network's place: its top-left corner (or its first element in the file).
    using Key = std::tuple<double, double, int, std::size_t>;
    constexpr double kFar = std::numeric_limits<double>::max();
    std::map<std::size_t, Key> groupKey;
    const auto keyOf = [&](std::size_t i) -> Key {
        const model::Position &p = model::header(*m_nodes[i].element).position;
        const int labelFirst = m_nodes[i].kind == NodeKind::Label ? 0 : 1;
        if (layoutGenerated)
            return {double(i), 0, labelFirst, i};
        return {p.y, p.x, labelFirst, i};
    };
    for (std::size_t i = 0; i < m_nodes.size(); ++i) {
        const NodeKind kind = m_nodes[i].kind;
        if (!inNetwork(kind) || kind == NodeKind::LeftRail || kind == NodeKind::RightRail)
            continue;
        const std::size_t group = groups.find(i);
        auto [it, inserted] = groupKey.try_emplace(group, keyOf(i));
        if (!inserted) {
            const Key mine = keyOf(i);
            auto &[y, x, label, file] = it->second;
            y = std::min(y, std::get<0>(mine));
            x = std::min(x, std::get<1>(mine));
            label = std::min(label, std::get<2>(mine));
            file = std::min(file, std::get<3>(mine));
        }
    }
    std::vector<std::size_t> roots;
    for (std::size_t i = 0; i < m_nodes.size(); ++i) {
        if (isRoot(m_nodes[i].kind))
            roots.push_back(i);
    }
    const auto explicitOrder = [&](std::size_t i) {
        const auto &order = model::header(*m_nodes[i].element).executionOrderId;
        return order && *order != 0 ? double(*order) : kFar;
    };
    const auto within = [&](std::size_t i) -> Key {
        const model::Position &p = model::header(*m_nodes[i].element).position;
        if (layoutGenerated)
            return {double(i), 0, 0, i};
        return {p.x, p.y, 0, i};
    };
    std::ranges::stable_sort(roots, [&](std::size_t a, std::size_t b) {
        return std::tuple(explicitOrder(a), groupKey[groups.find(a)], within(a))
            < std::tuple(explicitOrder(b), groupKey[groups.find(b)], within(b));
    });
    return roots;
}

} // namespace iec::interp::graphical
