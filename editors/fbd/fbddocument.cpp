#include "editors/fbd/fbddocument.h"

#include <QSet>

#include <algorithm>
#include <numeric>
#include <tuple>
#include <unordered_map>

namespace iec::editors::fbd {

using namespace model;

void FbdDocument::remove(const std::vector<quint64> &localIds)
{
    removeElements(localIds);
    const auto listed = [&](quint64 id) { return std::ranges::find(localIds, id) != localIds.end(); };
    for (FbdNetwork &network : networks) {
        std::erase_if(network.members, listed);
        if (listed(network.label))
            network.label = 0;
        if (listed(network.comment))
            network.comment = 0;
        if (listed(network.root))
            network.root = 0;
    }
    std::erase_if(unshown, listed);
}

int FbdDocument::networkOf(quint64 localId) const
{
    for (std::size_t n = 0; n < networks.size(); ++n)
        if (std::ranges::find(networks[n].members, localId) != networks[n].members.end())
            return int(n);
    return -1;
}

// ---- element kinds

bool isNode(const Element &element)
{
    return std::holds_alternative<Block>(element) || std::holds_alternative<InVariable>(element)
        || std::holds_alternative<InOutVariable>(element);
}

bool isSink(const Element &element)
{
    return std::holds_alternative<OutVariable>(element) || std::holds_alternative<Jump>(element)
        || std::holds_alternative<Return>(element);
}

namespace {

template<typename BlockT>
auto *blockVariable(BlockT &block, int pin)
{
    using Variable = std::conditional_t<std::is_const_v<BlockT>, const BlockVariable, BlockVariable>;
    Variable *variable = nullptr;
    const int inputs = int(block.inputVariables.size());
    if (pin >= 0 && pin < inputs)
        variable = &block.inputVariables[std::size_t(pin)];
    else if (pin >= inputs && pin < inputs + int(block.inOutVariables.size()))
        variable = &block.inOutVariables[std::size_t(pin - inputs)];
    return variable;
}

} // namespace

int inputCount(const Element &element)
{
    if (const auto *block = std::get_if<Block>(&element))
        return int(block->inputVariables.size() + block->inOutVariables.size());
    if (isSink(element) || std::holds_alternative<InOutVariable>(element))
        return 1;
    return 0;
}

const ConnectionPointIn *inputPoint(const Element &element, int pin)
{
    return inputPoint(const_cast<Element &>(element), pin);
}

ConnectionPointIn *inputPoint(Element &element, int pin)
{
    if (auto *block = std::get_if<Block>(&element)) {
        BlockVariable *variable = blockVariable(*block, pin);
        return variable && variable->connectionPointIn ? &*variable->connectionPointIn : nullptr;
    }
    if (pin != 0)
        return nullptr;
    return std::visit(
        [](auto &e) -> ConnectionPointIn * {
            if constexpr (requires { e.connectionPointIn; })
                return e.connectionPointIn ? &*e.connectionPointIn : nullptr;
            else
                return nullptr;
        },
        element);
}

QString inputName(const Element &element, int pin)
{
    if (const auto *block = std::get_if<Block>(&element))
        if (const BlockVariable *variable = blockVariable(*block, pin))
            return variable->formalParameter;
    return {};
}

int outputCount(const Element &element)
{
    if (const auto *block = std::get_if<Block>(&element))
        return int(block->outputVariables.size());
    return std::holds_alternative<InVariable>(element) || std::holds_alternative<InOutVariable>(element) ? 1 : 0;
}

std::optional<Port> sourceOf(const FbdDocument &document, quint64 element, int pin)
{
    const Element *e = document.element(element);
    const ConnectionPointIn *point = e ? inputPoint(*e, pin) : nullptr;
    if (!point || point->connections.empty())
        return std::nullopt;
    const Connection &c = point->connections.front();
    const Element *source = document.element(c.refLocalId);
    if (!source)
        return std::nullopt;
    return Port {c.refLocalId, std::max(0, outputPinIndex(*source, c.formalParameter))};
}

void connectInput(FbdDocument &document, quint64 element, int pin, Port source)
{
    Element *e = document.element(element);
    const Element *from = document.element(source.element);
    if (!e || !from)
        return;
    ConnectionPointIn *point = inputPoint(*e, pin);
    if (!point) {
        // A pin without a connection point (a file that left it out) gets one.
        if (auto *block = std::get_if<Block>(e)) {
            if (BlockVariable *variable = blockVariable(*block, pin))
                point = &variable->connectionPointIn.emplace();
        } else {
            std::visit(
                [&](auto &x) {
                    if constexpr (requires { x.connectionPointIn; })
                        point = &x.connectionPointIn.emplace();
                },
                *e);
        }
    }
    if (!point)
        return;
    Connection c;
    c.refLocalId = source.element;
    if (const auto *block = std::get_if<Block>(from); block && source.pin < int(block->outputVariables.size()))
        c.formalParameter = block->outputVariables[std::size_t(source.pin)].formalParameter;
    point->expression.reset();
    point->connections = {std::move(c)};
}

Readers readersOf(const FbdDocument &document, const FbdNetwork &network, Port output)
{
    Readers readers;
    for (quint64 id : network.members) {
        const Element *e = document.element(id);
        if (!e)
            continue;
        const int pins = inputCount(*e);
        for (int pin = 0; pin < pins; ++pin) {
            if (sourceOf(document, id, pin) != std::optional<Port>(output))
                continue;
            if (isSink(*e))
                readers.sinks.push_back(id);
            else
                readers.nodes.emplace_back(id, pin);
        }
    }
    return readers;
}

int pinReading(const FbdDocument &document, quint64 target, Port output)
{
    const Element *e = document.element(target);
    const int pins = e ? inputCount(*e) : 0;
    for (int pin = 0; pin < pins; ++pin)
        if (sourceOf(document, target, pin) == std::optional<Port>(output))
            return pin;
    return -1;
}

std::vector<quint64> branchOf(const FbdDocument &document, const FbdNetwork &network, quint64 node)
{
    std::vector<quint64> branch;
    std::vector<quint64> pending {node};
    while (!pending.empty() && branch.size() <= network.members.size()) {
        const quint64 id = pending.back();
        pending.pop_back();
        if (std::ranges::find(branch, id) != branch.end())
            continue;
        branch.push_back(id);
        const Element *e = document.element(id);
        if (!e)
            continue;
        for (int pin = 0; pin < inputCount(*e); ++pin)
            if (const auto source = sourceOf(document, id, pin))
                pending.push_back(source->element);
    }
    // The sinks on the branch's outputs, except the ones on the node's own outputs (they stay with
    // whatever the node's place becomes).
    for (quint64 id : network.members) {
        const Element *e = document.element(id);
        if (!e || !isSink(*e))
            continue;
        const auto source = sourceOf(document, id, 0);
        if (source && source->element != node && std::ranges::find(branch, source->element) != branch.end())
            branch.push_back(id);
    }
    std::ranges::sort(branch, [&](quint64 a, quint64 b) { return document.indexOf(a) < document.indexOf(b); });
    return branch;
}

// ---- reading

namespace {

struct Group {
    std::vector<std::size_t> indices; // file order
    double top = 0;
};

// Union-find over element indices.
struct Components {
    std::vector<std::size_t> parent;
    explicit Components(std::size_t n)
        : parent(n)
    {
        std::iota(parent.begin(), parent.end(), std::size_t(0));
    }
    std::size_t find(std::size_t i)
    {
        while (parent[i] != i) {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        return i;
    }
    void join(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

bool drawnOnItsOwn(const Element &e)
{
    return isNode(e) || isSink(e) || std::holds_alternative<Label>(e) || std::holds_alternative<Comment>(e);
}

// Whether the network is a tree the layout can draw, and its root.
void analyze(const FbdDocument &document, FbdNetwork &network)
{
    std::unordered_map<quint64, int> nodeReaders;
    std::vector<quint64> nodes;
    const QSet<quint64> members(network.members.begin(), network.members.end());
    for (quint64 id : network.members) {
        const Element &e = *document.element(id);
        if (std::holds_alternative<Label>(e) || std::holds_alternative<Comment>(e))
            continue;
        if (!isNode(e) && !isSink(e)) {
            network.freehand = true;
            return;
        }
        if (isNode(e))
            nodes.push_back(id);
        for (int pin = 0; pin < inputCount(e); ++pin) {
            const ConnectionPointIn *point = inputPoint(e, pin);
            if (!point || point->connections.empty())
                continue;
            const Element *source = document.element(point->connections.front().refLocalId);
            const int sourcePin = source ? outputPinIndex(*source, point->connections.front().formalParameter) : -1;
            if (point->connections.size() > 1 || !source || !isNode(*source) || sourcePin < 0
                || !members.contains(point->connections.front().refLocalId)) {
                network.freehand = true;
                return;
            }
            // One node feeding two boxes (from one output or from two) is a graph, not a tree.
            if (isNode(e) && ++nodeReaders[point->connections.front().refLocalId] > 1) {
                network.freehand = true;
                return;
            }
        }
    }
    std::vector<quint64> roots;
    for (quint64 id : nodes)
        if (!nodeReaders.contains(id))
            roots.push_back(id);
    if (roots.size() != 1) {
        network.freehand = !nodes.empty() || std::ranges::any_of(network.members, [&](quint64 id) { return isSink(*document.element(id)); });
        return;
    }
    // Deep trees are drawn as they are: the layout recurses along them.
    std::vector<std::pair<quint64, int>> pending {{roots.front(), 1}};
    std::size_t visited = 0;
    while (!pending.empty()) {
        const auto [id, depth] = pending.back();
        pending.pop_back();
        if (depth > kMaxTreeDepth || ++visited > nodes.size()) {
            network.freehand = true;
            return;
        }
        const Element &e = *document.element(id);
        for (int pin = 0; pin < inputCount(e); ++pin)
            if (const auto source = sourceOf(document, id, pin))
                pending.emplace_back(source->element, depth + 1);
    }
    network.root = roots.front();
}

} // namespace

FbdDocument readFbd(std::vector<Element> elements, bool layoutGenerated)
{
    FbdDocument document;
    document.elements = std::move(elements);
    document.reindex();
    const std::size_t count = document.elements.size();
    Components components(count);
    for (std::size_t i = 0; i < count; ++i) {
        for (const ConnectionPointIn *point : inputPoints(document.elements[i]))
            for (const Connection &c : point->connections)
                if (const int j = document.indexOf(c.refLocalId); j >= 0)
                    components.join(i, std::size_t(j));
    }
    std::vector<std::size_t> sizes(count, 0);
    for (std::size_t i = 0; i < count; ++i)
        ++sizes[components.find(i)];
    std::unordered_map<std::size_t, std::size_t> groupOf;
    std::vector<Group> groups;
    for (std::size_t i = 0; i < count; ++i) {
        const Element &e = document.elements[i];
        if (!drawnOnItsOwn(e) && sizes[components.find(i)] == 1) {
            document.unshown.push_back(header(e).localId);
            continue;
        }
        const std::size_t root = components.find(i);
        auto [it, added] = groupOf.try_emplace(root, groups.size());
        if (added)
            groups.push_back({{}, header(e).position.y});
        Group &group = groups[it->second];
        group.indices.push_back(i);
        group.top = std::min(group.top, header(e).position.y);
    }
    std::vector<std::size_t> order(groups.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    if (!layoutGenerated)
        std::ranges::stable_sort(order, [&](std::size_t a, std::size_t b) {
            return std::tuple(groups[a].top, groups[a].indices.front()) < std::tuple(groups[b].top, groups[b].indices.front());
        });
    const auto idAt = [&](std::size_t i) { return header(document.elements[i]).localId; };
    FbdNetwork pending;
    const auto flush = [&] {
        if (!pending.members.empty()) {
            std::ranges::sort(pending.members, [&](quint64 a, quint64 b) { return document.indexOf(a) < document.indexOf(b); });
            document.networks.push_back(std::move(pending));
        }
        pending = {};
    };
    for (std::size_t g : order) {
        const Group &group = groups[g];
        const Element &first = document.elements[group.indices.front()];
        if (group.indices.size() == 1 && std::holds_alternative<Label>(first)) {
            if (pending.label)
                flush();
            pending.label = idAt(group.indices.front());
            pending.members.push_back(pending.label);
            continue;
        }
        if (group.indices.size() == 1 && std::holds_alternative<Comment>(first)) {
            if (pending.comment)
                flush();
            pending.comment = idAt(group.indices.front());
            pending.members.push_back(pending.comment);
            continue;
        }
        for (std::size_t i : group.indices)
            pending.members.push_back(idAt(i));
        flush();
    }
    flush();
    for (FbdNetwork &network : document.networks)
        analyze(document, network);
    return document;
}

} // namespace iec::editors::fbd
