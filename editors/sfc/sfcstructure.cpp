#include "editors/sfc/sfcstructure.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace iec::editors::sfc {

using namespace model;

Role roleOf(NodeKind kind)
{
    switch (kind) {
    case NodeKind::Step:
    case NodeKind::MacroStep:
    case NodeKind::Parallel:
        return Role::StepLike;
    case NodeKind::Transition:
    case NodeKind::Selection:
        return Role::TransitionLike;
    case NodeKind::Jump:
        return Role::Jump;
    }
    return Role::StepLike;
}

namespace {

bool isStructural(const Element &e)
{
    return std::holds_alternative<Step>(e) || std::holds_alternative<MacroStep>(e)
        || std::holds_alternative<Transition>(e) || std::holds_alternative<JumpStep>(e)
        || std::holds_alternative<SelectionDivergence>(e) || std::holds_alternative<SelectionConvergence>(e)
        || std::holds_alternative<SimultaneousDivergence>(e) || std::holds_alternative<SimultaneousConvergence>(e);
}

bool isConvergence(const Element &e)
{
    return std::holds_alternative<SelectionConvergence>(e) || std::holds_alternative<SimultaneousConvergence>(e);
}

// The structural inputs of an element (not a transition's wired condition).
std::vector<const ConnectionPointIn *> structuralInputs(const Element &e)
{
    std::vector<const ConnectionPointIn *> points;
    std::visit(
        [&](const auto &x) {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, SelectionConvergence> || std::is_same_v<T, SimultaneousConvergence>) {
                for (const ConnectionPointIn &p : x.connectionPointIns)
                    points.push_back(&p);
            } else if constexpr (std::is_same_v<T, Step> || std::is_same_v<T, MacroStep>
                || std::is_same_v<T, Transition> || std::is_same_v<T, JumpStep>
                || std::is_same_v<T, SelectionDivergence> || std::is_same_v<T, SimultaneousDivergence>) {
                if (x.connectionPointIn)
                    points.push_back(&*x.connectionPointIn);
            }
        },
        e);
    return points;
}

struct Parser {
    const std::vector<Element> &elements;
    std::unordered_map<quint64, std::size_t> indexOf;
    std::unordered_map<quint64, std::vector<quint64>> successors;
    std::unordered_set<quint64> visited;

    explicit Parser(const std::vector<Element> &e)
        : elements(e)
    {
        for (std::size_t i = 0; i < elements.size(); ++i)
            indexOf.emplace(header(elements[i]).localId, i);
        for (const Element &element : elements) {
            if (!isStructural(element))
                continue;
            for (const ConnectionPointIn *point : structuralInputs(element)) {
                for (const Connection &c : point->connections) {
                    const auto source = indexOf.find(c.refLocalId);
                    if (source != indexOf.end() && isStructural(elements[source->second]))
                        successors[c.refLocalId].push_back(header(element).localId);
                }
            }
        }
        // Branches from left to right; equal x (an unplaced chart) keeps the file order.
        for (auto &[id, list] : successors) {
            std::ranges::stable_sort(list, [&](quint64 a, quint64 b) {
                const double xa = header(at(a)).position.x;
                const double xb = header(at(b)).position.x;
                return xa != xb ? xa < xb : indexOf.at(a) < indexOf.at(b);
            });
            list.erase(std::unique(list.begin(), list.end()), list.end());
        }
    }

    const Element &at(quint64 id) const { return elements[indexOf.at(id)]; }

    std::vector<quint64> next(quint64 id) const
    {
        const auto it = successors.find(id);
        return it == successors.end() ? std::vector<quint64> {} : it->second;
    }

    // Parses the chain starting at `id`; returns the convergence it ran into (0: none).
    quint64 parse(std::optional<quint64> start, Sequence &out)
    {
        while (start) {
            const quint64 id = *start;
            const Element &e = at(id);
            if (isConvergence(e))
                return id;
            if (visited.contains(id)) {
                // A wire back to an element already placed: stands for a jump to it.
                Node jump {NodeKind::Jump};
                jump.wired = true;
                jump.wiredTarget = id;
                out.push_back(jump);
                return 0;
            }
            visited.insert(id);
            Node node;
            node.localId = id;
            if (std::holds_alternative<Step>(e))
                node.kind = NodeKind::Step;
            else if (std::holds_alternative<MacroStep>(e))
                node.kind = NodeKind::MacroStep;
            else if (std::holds_alternative<Transition>(e))
                node.kind = NodeKind::Transition;
            else if (std::holds_alternative<JumpStep>(e)) {
                out.push_back({NodeKind::Jump, id});
                return 0;
            } else {
                node.kind = std::holds_alternative<SelectionDivergence>(e) ? NodeKind::Selection : NodeKind::Parallel;
                quint64 convergence = 0;
                for (quint64 branchStart : next(id)) {
                    Sequence branch;
                    const quint64 end = parse(branchStart, branch);
                    if (convergence == 0)
                        convergence = end;
                    node.branches.push_back(std::move(branch));
                }
                node.convergenceId = convergence;
                out.push_back(std::move(node));
                if (convergence == 0 || visited.contains(convergence))
                    return 0;
                visited.insert(convergence);
                const std::vector<quint64> after = next(convergence);
                start = after.empty() ? std::nullopt : std::optional(after.front());
                continue;
            }
            out.push_back(node);
            const std::vector<quint64> after = next(id);
            start = after.empty() ? std::nullopt : std::optional(after.front());
        }
        return 0;
    }
};

template<class F> void forEachSequence(Sequence &sequence, const F &f)
{
    f(sequence);
    for (Node &node : sequence)
        for (Sequence &branch : node.branches)
            forEachSequence(branch, f);
}

} // namespace

Chart parseChart(const std::vector<Element> &elements)
{
    Parser parser(elements);
    Chart chart;
    std::optional<quint64> start;
    for (const Element &e : elements) {
        if (const auto *step = std::get_if<Step>(&e); step && step->initialStep) {
            start = step->localId;
            break;
        }
    }
    auto hasInput = [&](const Element &e) {
        const auto points = structuralInputs(e);
        return std::ranges::any_of(points, [&](const ConnectionPointIn *p) {
            return std::ranges::any_of(p->connections, [&](const Connection &c) { return parser.indexOf.contains(c.refLocalId); });
        });
    };
    if (!start) {
        for (const Element &e : elements) {
            if ((std::holds_alternative<Step>(e) || std::holds_alternative<MacroStep>(e)) && !hasInput(e)) {
                start = header(e).localId;
                break;
            }
        }
    }
    if (start)
        parser.parse(*start, chart.main);
    // What is left: chains that start without an input first, then anything still unvisited.
    for (int pass = 0; pass < 2; ++pass) {
        for (const Element &e : elements) {
            const quint64 id = header(e).localId;
            if (!isStructural(e) || isConvergence(e) || parser.visited.contains(id) || (pass == 0 && hasInput(e)))
                continue;
            Sequence chain;
            parser.parse(id, chain);
            if (!chain.empty())
                chart.loose.push_back(std::move(chain));
        }
    }
    return chart;
}

ChartDocument readChart(std::vector<Element> elements)
{
    ChartDocument document {std::move(elements), {}, 0};
    document.chart = parseChart(document.elements);
    for (const Element &e : document.elements)
        document.idFloor = std::max(document.idFloor, header(e).localId);
    return document;
}

const Element *ChartDocument::element(quint64 localId) const
{
    const auto it = std::ranges::find_if(elements, [&](const Element &e) { return header(e).localId == localId; });
    return it == elements.end() ? nullptr : &*it;
}

Element *ChartDocument::element(quint64 localId)
{
    const auto it = std::ranges::find_if(elements, [&](const Element &e) { return header(e).localId == localId; });
    return it == elements.end() ? nullptr : &*it;
}

quint64 ChartDocument::allocateId()
{
    quint64 largest = idFloor;
    for (const Element &e : elements)
        largest = std::max(largest, header(e).localId);
    idFloor = largest + 1;
    return largest + 1;
}

quint64 ChartDocument::add(Element e)
{
    const quint64 id = allocateId();
    header(e).localId = id;
    elements.push_back(std::move(e));
    return id;
}

void ChartDocument::remove(const std::vector<quint64> &localIds)
{
    const std::unordered_set<quint64> gone(localIds.begin(), localIds.end());
    std::erase_if(elements, [&](const Element &e) { return gone.contains(header(e).localId); });
    for (Element &e : elements) {
        for (ConnectionPointIn *point : inputPoints(e))
            std::erase_if(point->connections, [&](const Connection &c) { return gone.contains(c.refLocalId); });
    }
}

quint64 ChartDocument::actionBlockOf(quint64 stepId) const
{
    for (const Element &e : elements) {
        if (const auto *block = std::get_if<ActionBlock>(&e); block && block->connectionPointIn) {
            for (const Connection &c : block->connectionPointIn->connections)
                if (c.refLocalId == stepId)
                    return block->localId;
        }
    }
    return 0;
}

QString ChartDocument::stepName(quint64 localId) const
{
    const Element *e = element(localId);
    if (const auto *step = e ? std::get_if<Step>(e) : nullptr)
        return step->name;
    if (const auto *macro = e ? std::get_if<MacroStep>(e) : nullptr)
        return macro->name.value_or(QString());
    return {};
}

std::optional<quint64> ChartDocument::stepNamed(const QString &name) const
{
    for (const Element &e : elements) {
        if (const auto *step = std::get_if<Step>(&e); step && step->name.compare(name, Qt::CaseInsensitive) == 0)
            return step->localId;
        if (const auto *macro = std::get_if<MacroStep>(&e);
            macro && macro->name && macro->name->compare(name, Qt::CaseInsensitive) == 0)
            return macro->localId;
    }
    return std::nullopt;
}

namespace {

Connection wireFrom(quint64 source)
{
    Connection c;
    c.refLocalId = source;
    return c;
}

ConnectionPointIn inputFrom(const std::vector<quint64> &sources, const std::optional<ConnectionPointIn> &old)
{
    ConnectionPointIn point = old.value_or(ConnectionPointIn {});
    point.connections.clear();
    point.expression.reset();
    for (quint64 source : sources)
        point.connections.push_back(wireFrom(source));
    return point;
}

struct Wirer {
    ChartDocument &document;
    // Elements that feed the one after them keep (or get) an output; the others lose it at the
    // end. Decided at the end so that an output that stays keeps its pin position.
    std::unordered_set<quint64> feeding;
    std::vector<quint64> chainElements;

    void dropUnusedOutputs()
    {
        for (quint64 id : chainElements)
            if (!feeding.contains(id))
                ensureOutput(id, false);
    }

    void setInput(quint64 id, const std::vector<quint64> &sources)
    {
        Element *e = document.element(id);
        if (!e)
            return;
        std::visit(
            [&](auto &x) {
                using T = std::decay_t<decltype(x)>;
                if constexpr (std::is_same_v<T, Step> || std::is_same_v<T, MacroStep> || std::is_same_v<T, Transition>
                    || std::is_same_v<T, JumpStep> || std::is_same_v<T, SelectionDivergence>
                    || std::is_same_v<T, SimultaneousDivergence>) {
                    if (sources.empty() && !x.connectionPointIn)
                        return;
                    x.connectionPointIn = inputFrom(sources, x.connectionPointIn);
                }
            },
            *e);
    }

    void ensureOutput(quint64 id, bool present)
    {
        Element *e = document.element(id);
        if (!e)
            return;
        std::visit(
            [&](auto &x) {
                using T = std::decay_t<decltype(x)>;
                if constexpr (std::is_same_v<T, Step> || std::is_same_v<T, MacroStep> || std::is_same_v<T, Transition>) {
                    if (present && !x.connectionPointOut)
                        x.connectionPointOut = ConnectionPointOut {};
                    else if (!present)
                        x.connectionPointOut.reset();
                }
            },
            *e);
    }

    // Wires a chain fed by `feeds`; returns what feeds the element after it.
    std::vector<quint64> sequence(Sequence &seq, std::vector<quint64> feeds)
    {
        for (Node &node : seq) {
            if (node.kind == NodeKind::Jump && node.wired) {
                JumpStep jump;
                jump.targetName = document.stepName(node.wiredTarget);
                node.localId = document.add(jump);
                node.wired = false;
                node.wiredTarget = 0;
            }
            for (quint64 feed : feeds) {
                ensureOutput(feed, true);
                feeding.insert(feed);
            }
            if (node.kind == NodeKind::Selection || node.kind == NodeKind::Parallel)
                feeds = block(node, feeds);
            else {
                setInput(node.localId, feeds);
                chainElements.push_back(node.localId);
                feeds = node.kind == NodeKind::Jump ? std::vector<quint64> {} : std::vector<quint64> {node.localId};
            }
        }
        return feeds;
    }

    std::vector<quint64> block(Node &node, const std::vector<quint64> &feeds)
    {
        const bool parallel = node.kind == NodeKind::Parallel;
        setInput(node.localId, feeds);
        std::vector<std::vector<quint64>> ends;
        for (Sequence &branch : node.branches)
            ends.push_back(sequence(branch, {node.localId}));
        if (Element *e = document.element(node.localId)) {
            auto setOuts = [&](auto &divergence) {
                divergence.connectionPointOuts.resize(node.branches.size());
            };
            if (auto *s = std::get_if<SelectionDivergence>(e))
                setOuts(*s);
            else if (auto *p = std::get_if<SimultaneousDivergence>(e))
                setOuts(*p);
        }
        std::vector<std::vector<quint64>> open;
        for (const auto &end : ends)
            if (!end.empty())
                open.push_back(end);
        // A convergence joins two branches or more: when every other branch of an alternative
        // ends in a jump, the one left open simply goes on (IEC 61131-3 has no one-branch join,
        // and the compiler would warn about it).
        if (open.empty() || (!parallel && open.size() == 1)) {
            if (node.convergenceId != 0)
                document.remove({node.convergenceId});
            node.convergenceId = 0;
            return open.empty() ? std::vector<quint64> {} : open.front();
        }
        if (node.convergenceId == 0 || !document.element(node.convergenceId)) {
            node.convergenceId = parallel ? document.add(SimultaneousConvergence {}) : document.add(SelectionConvergence {});
        }
        Element *conv = document.element(node.convergenceId);
        auto setIns = [&](auto &convergence) {
            std::vector<ConnectionPointIn> ins;
            for (std::size_t i = 0; i < open.size(); ++i) {
                ins.push_back(inputFrom(open[i],
                    i < convergence.connectionPointIns.size() ? std::optional(convergence.connectionPointIns[i]) : std::nullopt));
            }
            convergence.connectionPointIns = std::move(ins);
            if (!convergence.connectionPointOut)
                convergence.connectionPointOut = ConnectionPointOut {};
        };
        if (auto *s = std::get_if<SelectionConvergence>(conv))
            setIns(*s);
        else if (auto *p = std::get_if<SimultaneousConvergence>(conv))
            setIns(*p);
        for (const auto &end : open)
            for (quint64 id : end) {
                ensureOutput(id, true);
                feeding.insert(id);
            }
        return {node.convergenceId};
    }
};

void collect(const ChartDocument &document, const Node &node, std::vector<quint64> &ids)
{
    if (!node.wired)
        ids.push_back(node.localId);
    if (node.convergenceId != 0)
        ids.push_back(node.convergenceId);
    if (node.kind == NodeKind::Step || node.kind == NodeKind::MacroStep) {
        if (const quint64 block = document.actionBlockOf(node.localId))
            ids.push_back(block);
    }
    for (const Sequence &branch : node.branches)
        for (const Node &inner : branch)
            collect(document, inner, ids);
}

std::optional<NodePlace> search(Sequence &seq, Node *parent, bool isMain, quint64 id)
{
    for (std::size_t i = 0; i < seq.size(); ++i) {
        Node &node = seq[i];
        if (node.localId == id && !node.wired)
            return NodePlace {&seq, i, parent, isMain};
        for (Sequence &branch : node.branches)
            if (auto found = search(branch, &node, false, id))
                return found;
    }
    return std::nullopt;
}

} // namespace

void wireChart(ChartDocument &document)
{
    Wirer wirer {document, {}, {}};
    wirer.sequence(document.chart.main, {});
    for (Sequence &chain : document.chart.loose)
        wirer.sequence(chain, {});
    wirer.dropUnusedOutputs();
}

std::vector<quint64> elementsOf(const ChartDocument &document, const Node &node)
{
    std::vector<quint64> ids;
    collect(document, node, ids);
    return ids;
}

std::vector<quint64> conditionNetwork(const ChartDocument &document, quint64 transitionId)
{
    const Element *e = document.element(transitionId);
    const auto *transition = e ? std::get_if<Transition>(e) : nullptr;
    const auto *wire = transition && transition->condition ? std::get_if<ConnectionPointIn>(&transition->condition->kind) : nullptr;
    if (!wire)
        return {};
    std::vector<quint64> network;
    std::unordered_set<quint64> seen;
    std::vector<quint64> pending;
    for (const Connection &c : wire->connections)
        pending.push_back(c.refLocalId);
    while (!pending.empty()) {
        const quint64 id = pending.back();
        pending.pop_back();
        const Element *source = document.element(id);
        if (!source || seen.contains(id) || isStructural(*source) || std::holds_alternative<ActionBlock>(*source))
            continue;
        seen.insert(id);
        network.push_back(id);
        for (const ConnectionPointIn *point : inputPoints(*source))
            for (const Connection &c : point->connections)
                pending.push_back(c.refLocalId);
    }
    return network;
}

std::optional<NodePlace> findNode(Chart &chart, quint64 localId)
{
    if (auto found = search(chart.main, nullptr, true, localId))
        return found;
    for (Sequence &chain : chart.loose)
        if (auto found = search(chain, nullptr, false, localId))
            return found;
    return std::nullopt;
}

} // namespace iec::editors::sfc
