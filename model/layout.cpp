#include "model/layout.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace iec::model {

namespace {

constexpr double kColumnWidth = 160;
constexpr double kRowHeight = 80;
constexpr double kSfcColumnWidth = 260;
constexpr double kSfcSideOffset = 120; // action blocks to the right, condition inputs to the left
constexpr double kSfcRowHeight = 70;
constexpr double kMargin = 20;

bool isUnplaced(const std::vector<Element> &elements)
{
    return !elements.empty() && std::ranges::all_of(elements, [](const Element &element) {
        const Position &p = header(element).position;
        return p.x == 0 && p.y == 0;
    });
}

// The wires as index pairs (source, target), looked up through localIds.
struct Graph {
    std::vector<std::vector<std::size_t>> predecessors;
    std::vector<std::vector<std::size_t>> successors;
};

Graph buildGraph(const std::vector<Element> &elements)
{
    std::unordered_map<quint64, std::size_t> indexOf;
    for (std::size_t i = 0; i < elements.size(); ++i)
        indexOf.emplace(header(elements[i]).localId, i);
    Graph graph {
        std::vector<std::vector<std::size_t>>(elements.size()), std::vector<std::vector<std::size_t>>(elements.size())};
    for (std::size_t target = 0; target < elements.size(); ++target) {
        for (const ConnectionPointIn *point : inputPoints(elements[target])) {
            for (const Connection &connection : point->connections) {
                const auto source = indexOf.find(connection.refLocalId);
                if (source == indexOf.end() || source->second == target)
                    continue;
                graph.predecessors[target].push_back(source->second);
                graph.successors[source->second].push_back(target);
            }
        }
    }
    return graph;
}

// Longest distance from a source, following wires forward; back edges (loops in SFC, feedback in
// FBD) are ignored by visiting every element once in a depth-first order.
std::vector<int> levels(const Graph &graph, const std::vector<std::size_t> &roots)
{
    const std::size_t count = graph.successors.size();
    std::vector<int> level(count, -1);
    std::vector<int> state(count, 0); // 0 new, 1 on the stack, 2 done
    std::vector<std::size_t> order; // reverse post-order = topological order without back edges
    auto visit = [&](std::size_t root) {
        if (state[root] != 0)
            return;
        std::vector<std::pair<std::size_t, std::size_t>> stack {{root, 0}};
        state[root] = 1;
        while (!stack.empty()) {
            auto &[node, next] = stack.back();
            if (next < graph.successors[node].size()) {
                const std::size_t successor = graph.successors[node][next++];
                if (state[successor] == 0) {
                    state[successor] = 1;
                    stack.emplace_back(successor, 0);
                }
            } else {
                state[node] = 2;
                order.push_back(node);
                stack.pop_back();
            }
        }
    };
    for (std::size_t root : roots)
        visit(root);
    for (std::size_t i = 0; i < count; ++i)
        visit(i);
    std::ranges::reverse(order);
    std::vector<std::size_t> rank(count);
    for (std::size_t i = 0; i < order.size(); ++i)
        rank[order[i]] = i;
    for (std::size_t node : order) {
        int best = 0;
        for (std::size_t predecessor : graph.predecessors[node]) {
            if (rank[predecessor] < rank[node]) // a forward edge
                best = std::max(best, level[predecessor] + 1);
        }
        level[node] = best;
    }
    return level;
}

// Connected groups of elements (networks), each in file order, ordered by their first element.
std::vector<std::vector<std::size_t>> components(const Graph &graph)
{
    const std::size_t count = graph.successors.size();
    std::vector<std::size_t> parent(count);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](std::size_t i) {
        while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
        return i;
    };
    for (std::size_t i = 0; i < count; ++i) {
        for (std::size_t successor : graph.successors[i])
            parent[find(i)] = find(successor);
    }
    std::vector<std::vector<std::size_t>> groups;
    std::unordered_map<std::size_t, std::size_t> groupOf;
    for (std::size_t i = 0; i < count; ++i) {
        const auto [it, added] = groupOf.emplace(find(i), groups.size());
        if (added)
            groups.emplace_back();
        groups[it->second].push_back(i);
    }
    return groups;
}

bool isActionBlock(const Element &element)
{
    return std::holds_alternative<ActionBlock>(element);
}

// An element that only feeds a transition's condition or an action block: drawn beside, not below.
bool isSideInput(
    const Element &element, const std::vector<std::size_t> &successors, const std::vector<Element> &elements)
{
    if (isActionBlock(element))
        return true;
    return !successors.empty() && std::ranges::all_of(successors, [&](std::size_t s) {
        return std::holds_alternative<Transition>(elements[s]) && !std::holds_alternative<Step>(element)
            && !std::holds_alternative<SelectionDivergence>(element)
            && !std::holds_alternative<SimultaneousDivergence>(element)
            && !std::holds_alternative<SelectionConvergence>(element)
            && !std::holds_alternative<SimultaneousConvergence>(element);
    });
}

bool isDivergence(const Element &element)
{
    return std::holds_alternative<SelectionDivergence>(element)
        || std::holds_alternative<SimultaneousDivergence>(element);
}

// Each element stays in the column of the element before it; the branches of a divergence take
// the columns to its right. An element whose column is taken in its row moves further right.
std::vector<int> sfcColumns(const std::vector<Element> &elements, const Graph &spine, const std::vector<int> &level,
    const std::vector<bool> &side)
{
    std::vector<std::size_t> order(elements.size());
    std::iota(order.begin(), order.end(), 0);
    std::ranges::stable_sort(order, {}, [&](std::size_t i) { return level[i]; });
    std::vector<int> column(elements.size(), -1);
    std::unordered_map<int, std::vector<bool>> taken; // row -> columns in use
    for (std::size_t i : order) {
        if (side[i])
            continue;
        int desired = 0;
        int leftmost = -1;
        for (std::size_t predecessor : spine.predecessors[i]) {
            if (column[predecessor] >= 0 && (leftmost < 0 || column[predecessor] < column[leftmost]))
                leftmost = int(predecessor);
        }
        if (leftmost >= 0) {
            desired = column[std::size_t(leftmost)];
            if (isDivergence(elements[std::size_t(leftmost)])) {
                const auto &branches = spine.successors[std::size_t(leftmost)];
                desired += int(std::ranges::find(branches, i) - branches.begin());
            }
        }
        std::vector<bool> &row = taken[level[i]];
        while (std::size_t(desired) < row.size() && row[std::size_t(desired)])
            ++desired;
        if (std::size_t(desired) >= row.size())
            row.resize(std::size_t(desired) + 1);
        row[std::size_t(desired)] = true;
        column[i] = desired;
    }
    return column;
}

void layoutSfc(std::vector<Element> &elements)
{
    const Graph graph = buildGraph(elements);
    std::vector<std::size_t> roots;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        if (const auto *step = std::get_if<Step>(&elements[i]); step && step->initialStep)
            roots.push_back(i);
    }
    // The chart's spine ignores side inputs: they are placed next to what they feed.
    Graph spine = graph;
    std::vector<bool> side(elements.size());
    for (std::size_t i = 0; i < elements.size(); ++i)
        side[i] = isSideInput(elements[i], graph.successors[i], elements);
    for (std::size_t i = 0; i < elements.size(); ++i) {
        std::erase_if(spine.predecessors[i], [&](std::size_t p) { return side[p]; });
        if (side[i])
            spine.successors[i].clear();
    }
    const std::vector<int> level = levels(spine, roots);
    const std::vector<int> column = sfcColumns(elements, spine, level, side);
    for (std::size_t i = 0; i < elements.size(); ++i) {
        if (!side[i])
            header(elements[i]).position
                = {kMargin + kSfcSideOffset + kSfcColumnWidth * column[i], kMargin + kSfcRowHeight * level[i]};
    }
    for (std::size_t i = 0; i < elements.size(); ++i) {
        if (!side[i] || (graph.successors[i].empty() && graph.predecessors[i].empty()))
            continue;
        const bool right = isActionBlock(elements[i]);
        const std::size_t anchor
            = right && !graph.predecessors[i].empty() ? graph.predecessors[i].front() : graph.successors[i].front();
        const Position at = header(elements[anchor]).position;
        header(elements[i]).position = {right ? at.x + kSfcSideOffset : at.x - kSfcSideOffset, at.y};
    }
    // Whatever is not wired at all goes in a row below the chart.
    double bottom = 0;
    for (const Element &element : elements)
        bottom = std::max(bottom, header(element).position.y);
    int loose = 0;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        if (side[i] && graph.successors[i].empty() && graph.predecessors[i].empty())
            header(elements[i]).position = {kMargin + kSfcColumnWidth * loose++, bottom + kSfcRowHeight};
    }
}

void layoutDataFlow(std::vector<Element> &elements)
{
    const Graph graph = buildGraph(elements);
    const std::vector<int> level = levels(graph, {});
    double top = kMargin;
    for (const std::vector<std::size_t> &network : components(graph)) {
        std::unordered_map<int, int> usedInColumn;
        int rows = 1;
        for (std::size_t i : network) {
            const int row = usedInColumn[level[i]]++;
            rows = std::max(rows, row + 1);
            header(elements[i]).position = {kMargin + kColumnWidth * level[i], top + kRowHeight * row};
        }
        top += kRowHeight * rows;
    }
}

} // namespace

bool generateLayoutIfUnplaced(Body &body)
{
    std::vector<Element> *elements = body.elements();
    if (!elements || !isUnplaced(*elements) || elements->size() < 2)
        return false;
    if (body.language() == BodyLanguage::SFC)
        layoutSfc(*elements);
    else
        layoutDataFlow(*elements);
    body.layoutGenerated = true;
    return true;
}

} // namespace iec::model
