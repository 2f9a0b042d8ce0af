#include "editors/sfc/sfcplacement.h"

#include "editors/sfc/sfcgeometry.h"
#include "editors/sfc/sfclayout.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <unordered_map>
#include <unordered_set>

namespace iec::editors::sfc {

using namespace model;

// ---- placement after an edit: what existed stays, what is new is placed next to it

namespace {

bool isBlock(const Node &node)
{
    return node.kind == NodeKind::Selection || node.kind == NodeKind::Parallel;
}

bool isChainElement(const Element &e)
{
    return isBar(e) || std::holds_alternative<Step>(e) || std::holds_alternative<MacroStep>(e)
        || std::holds_alternative<Transition>(e) || std::holds_alternative<JumpStep>(e)
        || std::holds_alternative<ActionBlock>(e);
}

bool isDivergence(const Element &e)
{
    return std::holds_alternative<SelectionDivergence>(e) || std::holds_alternative<SimultaneousDivergence>(e);
}

quint64 bottomId(const Node &node)
{
    return node.convergenceId != 0 ? node.convergenceId : node.localId;
}

template<class Point> std::optional<double> relX(const std::optional<Point> &point)
{
    if (point && point->relPosition)
        return point->relPosition->x;
    return std::nullopt;
}

// x where the wire enters an element (a divergence: its input pin) or leaves it (a convergence:
// its output pin).
double inX(const Element &e)
{
    if (!isBar(e))
        return inputPoint(e).x();
    std::optional<double> rel;
    if (const auto *d = std::get_if<SelectionDivergence>(&e))
        rel = relX(d->connectionPointIn);
    else if (const auto *p = std::get_if<SimultaneousDivergence>(&e))
        rel = relX(p->connectionPointIn);
    const QRectF rect = elementRect(e);
    return rel ? rect.left() + *rel : rect.center().x();
}

double outX(const Element &e)
{
    if (!isBar(e))
        return outputPoint(e).x();
    std::optional<double> rel;
    if (const auto *c = std::get_if<SelectionConvergence>(&e))
        rel = relX(c->connectionPointOut);
    else if (const auto *p = std::get_if<SimultaneousConvergence>(&e))
        rel = relX(p->connectionPointOut);
    const QRectF rect = elementRect(e);
    return rel ? rect.left() + *rel : rect.center().x();
}

QRectF unite(const QRectF &a, const QRectF &b)
{
    return a.isNull() ? b : b.isNull() ? a : a.united(b);
}

constexpr double kNoClash = 1e9;

// How far the drawings on the right stay right of those on the left, among the pairs that share
// rows (kNoClash when none do): branches may reach under each other where they do not.
double clearance(const std::vector<QRectF> &left, const std::vector<QRectF> &right)
{
    double clear = kNoClash;
    for (const QRectF &a : left)
        for (const QRectF &b : right)
            if (a.top() < b.bottom() && b.top() < a.bottom())
                clear = std::min(clear, b.left() - a.right());
    return clear;
}

// The gap two neighbouring branches must keep: what they had (a chart drawn tighter than ours stays
// so while nothing between them grows); when something grew, at least a readable gap; never more
// than the layout's own gap.
double gapToKeep(double before, double now, double layoutGap)
{
    constexpr double kReadable = 12;
    if (before >= kNoClash)
        return layoutGap;
    if (now >= before - 0.01)
        return std::min(layoutGap, before);
    return std::min(layoutGap, std::max(before, kReadable));
}

// What the node above the next one in a chain says about itself.
struct Above {
    quint64 id = 0;        // the element the next node's wire comes from
    bool existed = false;  // it was there before the edit
    double bottom = 0;     // the bottom of its node's drawing now
    double oldBottom = 0;  // and before the edit
    double shift = 0;      // how far it moved down
    double axis = 0;       // x of the wire leaving it
};

// How far an existing node moves.
struct Move {
    double dy = 0;
    double dx = 0;         // only when a block it was in dissolved: back onto the chain's axis
    bool adjacent = false; // it followed the same node before the edit
};

struct Placer {
    const ChartDocument &before;
    ChartDocument &doc;
    std::unordered_map<quint64, const Element *> old;
    std::unordered_map<quint64, std::vector<quint64>> oldNext; // node bottom → tops that followed it
    std::set<std::pair<quint64, quint64>> oldNeighbours;       // first elements of adjacent branches
    std::unordered_set<quint64> repinned; // sizes or pins changed: their wires are routed again

    Placer(const ChartDocument &b, ChartDocument &d)
        : before(b)
        , doc(d)
    {
        for (const Element &e : before.elements)
            old.emplace(header(e).localId, &e);
        linkOld(before.chart.main, std::nullopt);
        for (const Sequence &chain : before.chart.loose)
            linkOld(chain, std::nullopt);
    }

    void linkOld(const Sequence &seq, std::optional<quint64> into)
    {
        for (std::size_t i = 0; i < seq.size(); ++i) {
            const Node &node = seq[i];
            if (node.wired)
                continue;
            if (isBlock(node)) {
                const std::optional<quint64> convergence = node.convergenceId ? std::optional(node.convergenceId) : std::nullopt;
                for (std::size_t k = 0; k < node.branches.size(); ++k) {
                    const Sequence &branch = node.branches[k];
                    if (!branch.empty() && !branch.front().wired)
                        oldNext[node.localId].push_back(branch.front().localId);
                    if (k > 0 && !branch.empty() && !node.branches[k - 1].empty())
                        oldNeighbours.insert({node.branches[k - 1].front().localId, branch.front().localId});
                    linkOld(branch, convergence);
                }
            }
            if (i + 1 < seq.size()) {
                if (!seq[i + 1].wired)
                    oldNext[bottomId(node)].push_back(seq[i + 1].localId);
            } else if (into && node.kind != NodeKind::Jump)
                oldNext[bottomId(node)].push_back(*into);
        }
    }

    [[nodiscard]] bool existed(quint64 id) const { return old.contains(id); }

    // Every element a node stands for, with the network wired into its transitions' conditions
    // (variables, blocks, contacts: whatever feeds the condition, which moves with it).
    [[nodiscard]] std::vector<quint64> idsOf(const Node &node) const
    {
        std::vector<quint64> ids = elementsOf(doc, node);
        const std::size_t chainIds = ids.size();
        for (std::size_t i = 0; i < chainIds; ++i) {
            const std::vector<quint64> network = conditionNetwork(doc, ids[i]);
            ids.insert(ids.end(), network.begin(), network.end());
        }
        return ids;
    }

    [[nodiscard]] std::vector<quint64> idsOf(const Sequence &seq) const
    {
        std::vector<quint64> ids;
        for (const Node &node : seq) {
            const std::vector<quint64> more = idsOf(node);
            ids.insert(ids.end(), more.begin(), more.end());
        }
        return ids;
    }

    [[nodiscard]] bool allFresh(const std::vector<quint64> &ids) const
    {
        return std::ranges::none_of(ids, [&](quint64 id) { return existed(id); });
    }

    // The frames of the elements now / before the edit (those that existed), or with their texts.
    [[nodiscard]] QRectF rectNow(const std::vector<quint64> &ids, bool withTexts = false) const
    {
        QRectF rect;
        for (quint64 id : ids)
            if (const Element *e = doc.element(id))
                rect = unite(rect, withTexts ? drawnRect(*e) : elementRect(*e));
        return rect;
    }

    [[nodiscard]] QRectF rectBefore(const std::vector<quint64> &ids, bool withTexts = false) const
    {
        QRectF rect;
        for (quint64 id : ids)
            if (const auto it = old.find(id); it != old.end())
                rect = unite(rect, withTexts ? drawnRect(*it->second) : elementRect(*it->second));
        return rect;
    }

    // The drawings (frames with their texts) of the elements now, or before the edit.
    [[nodiscard]] std::vector<QRectF> drawings(const std::vector<quint64> &ids, bool now) const
    {
        std::vector<QRectF> rects;
        for (quint64 id : ids) {
            if (now) {
                if (const Element *e = doc.element(id))
                    rects.push_back(drawnRect(*e));
            } else if (const auto it = old.find(id); it != old.end())
                rects.push_back(drawnRect(*it->second));
        }
        return rects;
    }

    void moveExisting(const std::vector<quint64> &ids, double dx, double dy)
    {
        if (dx == 0 && dy == 0)
            return;
        for (quint64 id : ids) {
            if (!existed(id))
                continue;
            if (Element *e = doc.element(id)) {
                header(*e).position.x += dx;
                header(*e).position.y += dy;
            }
        }
    }

    void moveAll(const std::vector<quint64> &ids, double dx)
    {
        for (quint64 id : ids)
            if (Element *e = doc.element(id))
                header(*e).position.x += dx;
    }

    // Where an existing node goes, from the node above it: it keeps its distance to a node it
    // followed before (unless that one grew), it takes the place of what followed the node above
    // and was deleted (closing the gap), and it makes room below anything new.
    [[nodiscard]] Move moveFor(quint64 top, const std::optional<Above> &above, double carried) const
    {
        const double oldTop = elementRect(*old.at(top)).top();
        if (!above)
            return {carried, 0, true};
        const auto next = oldNext.find(above->id);
        const std::vector<quint64> followers = next == oldNext.end() ? std::vector<quint64> {} : next->second;
        if (above->existed && std::ranges::find(followers, top) != followers.end()) {
            const double gap = std::min(kGap, oldTop - above->oldBottom);
            return {std::max(above->shift, above->bottom + gap - oldTop), 0, true};
        }
        if (above->existed) {
            for (quint64 follower : followers) {
                const auto gone = old.find(follower);
                if (doc.element(follower) || gone == old.end())
                    continue;
                Move move {above->bottom + elementRect(*gone->second).top() - above->oldBottom - oldTop, 0, false};
                if (isDivergence(*gone->second))
                    move.dx = above->axis - inX(*doc.element(top));
                return move;
            }
        }
        return {std::max(carried, above->bottom + kGap - oldTop), 0, false};
    }

    // Walks a chain top-down: existing nodes move (down to make room, up to close a gap left by a
    // deletion), new ones are placed below the node above them on `axis`. Returns the last node.
    std::optional<Above> walk(Sequence &seq, double axis, std::optional<Above> above, double carried, double startTop)
    {
        double runDx = 0;
        for (Node &node : seq) {
            const std::vector<quint64> ids = idsOf(node);
            if (allFresh(ids)) {
                const double top = above ? above->bottom + kGap : startTop;
                placeFresh(node, axis, top);
                above = Above {bottomId(node), false, rectNow(ids).bottom(), 0, carried, axis};
                continue;
            }
            if (!existed(node.localId)) { // a new block around existing nodes
                above = walkBlock(node, axis, above, carried, std::nullopt);
                carried = above->shift;
                axis = above->axis;
                runDx = 0;
                continue;
            }
            const Move move = moveFor(node.localId, above, carried);
            if (!move.adjacent)
                runDx = move.dx;
            moveExisting(ids, runDx, 0);
            if (isBlock(node)) {
                above = walkBlock(node, axis + runDx, above, carried, move.dy);
            } else {
                moveExisting(ids, 0, move.dy);
                refit(node);
                const Element &e = *doc.element(node.localId);
                const std::vector<quint64> kept = idsOf(node);
                above = Above {node.localId, true, rectNow(kept).bottom(), rectBefore(kept).bottom(), move.dy, outX(e)};
            }
            carried = above->shift;
            axis = above->axis;
        }
        return above;
    }

    // A new node as the layout places it; a condition network pasted with one of its transitions
    // keeps its shape and moves along with the transition.
    void placeFresh(Node &node, double axis, double top)
    {
        struct Carried {
            quint64 id;
            Position offset; // from the transition
        };
        std::vector<Carried> carried;
        for (quint64 id : elementsOf(doc, node)) {
            const Position at = header(*doc.element(id)).position;
            for (quint64 member : conditionNetwork(doc, id)) {
                const Position p = header(*doc.element(member)).position;
                carried.push_back({member, {p.x - at.x, p.y - at.y}});
            }
        }
        // The transition each carried element belongs to, in the same order as above.
        std::vector<quint64> owners;
        for (quint64 id : elementsOf(doc, node))
            for (std::size_t i = 0, n = conditionNetwork(doc, id).size(); i < n; ++i)
                owners.push_back(id);
        placeNode(doc, node, axis, top);
        for (std::size_t i = 0; i < carried.size(); ++i) {
            const Position at = header(*doc.element(owners[i])).position;
            header(*doc.element(carried[i].id)).position = {at.x + carried[i].offset.x, at.y + carried[i].offset.y};
        }
    }

    [[nodiscard]] std::optional<double> firstPlacedInX(const Sequence &seq) const
    {
        for (const Node &node : seq)
            if (existed(node.localId))
                return inX(*doc.element(node.localId));
        return std::nullopt;
    }

    // A divergence or convergence drawn across `axes` (and `through`, where the chain enters or
    // leaves it); the pins at the axes. Returns whether anything changed.
    bool fitBar(quint64 id, const std::vector<double> &axes, double through)
    {
        Element *e = doc.element(id);
        if (!e)
            return false;
        double left = through;
        double right = through;
        for (double x : axes) {
            left = std::min(left, x);
            right = std::max(right, x);
        }
        const Element before = *e;
        ElementHeader &h = header(*e);
        h.position.x = left;
        h.width = std::max(right - left, 1.0);
        const double bar = elementRect(*e).height();
        auto divergence = [&](auto &d) {
            if (d.connectionPointIn)
                d.connectionPointIn->relPosition = Position {through - left, 0};
            for (std::size_t i = 0; i < d.connectionPointOuts.size() && i < axes.size(); ++i)
                d.connectionPointOuts[i].relPosition = Position {axes[i] - left, bar};
        };
        auto convergence = [&](auto &c) {
            for (std::size_t i = 0; i < c.connectionPointIns.size() && i < axes.size(); ++i)
                c.connectionPointIns[i].relPosition = Position {axes[i] - left, 0};
            if (c.connectionPointOut)
                c.connectionPointOut->relPosition = Position {through - left, bar};
        };
        if (auto *s = std::get_if<SelectionDivergence>(e))
            divergence(*s);
        else if (auto *p = std::get_if<SimultaneousDivergence>(e))
            divergence(*p);
        else if (auto *c = std::get_if<SelectionConvergence>(e))
            convergence(*c);
        else if (auto *q = std::get_if<SimultaneousConvergence>(e))
            convergence(*q);
        if (*e == before)
            return false;
        repinned.insert(id);
        return true;
    }

    // Whether a bar's pins still sit at the axes of its branches.
    [[nodiscard]] bool barFits(quint64 id, const std::vector<double> &axes, bool divergence) const
    {
        const Element *e = doc.element(id);
        if (!e || !existed(id))
            return false;
        const double left = elementRect(*e).left();
        std::vector<std::optional<Position>> pins;
        auto outs = [&](const auto &d) {
            for (const ConnectionPointOut &p : d.connectionPointOuts)
                pins.push_back(p.relPosition);
        };
        auto ins = [&](const auto &c) {
            for (const ConnectionPointIn &p : c.connectionPointIns)
                pins.push_back(p.relPosition);
        };
        if (const auto *s = std::get_if<SelectionDivergence>(e); s && divergence)
            outs(*s);
        else if (const auto *p = std::get_if<SimultaneousDivergence>(e); p && divergence)
            outs(*p);
        else if (const auto *c = std::get_if<SelectionConvergence>(e); c && !divergence)
            ins(*c);
        else if (const auto *q = std::get_if<SimultaneousConvergence>(e); q && !divergence)
            ins(*q);
        if (pins.size() != axes.size())
            return false;
        for (std::size_t i = 0; i < axes.size(); ++i)
            if (!pins[i] || std::abs(pins[i]->x + left - axes[i]) > 0.5)
                return false;
        return true;
    }

    // A block: its divergence (new below the node above, or moved like any node by `divMove`),
    // its branches side by side (a new branch right of the widest drawing of the one before,
    // later branches pushed right when they would overlap), its convergence below the longest
    // branch (moved down only as far as needed).
    Above walkBlock(Node &node, double axis, const std::optional<Above> &above, double carried, std::optional<double> divMove)
    {
        const bool parallel = node.kind == NodeKind::Parallel;
        const double barHeight = parallel ? kParallelBarHeight : kSelectionBarHeight;
        Element *div = doc.element(node.localId);
        const double incoming = above ? above->axis : axis;
        Above fromDivergence;
        if (!divMove) {
            // Where the first node it wraps was (that node and what follows move down), at least
            // below the node above.
            double top = above ? above->bottom + kGap : kMargin;
            if (!node.branches.empty() && !node.branches.front().empty() && existed(node.branches.front().front().localId))
                top = std::max(top, elementRect(*old.at(node.branches.front().front().localId)).top());
            ElementHeader &h = header(*div);
            h.position = {axis, top};
            h.width = 1;
            h.height = barHeight;
            fromDivergence = Above {node.localId, false, top + barHeight, 0, carried, axis};
        } else {
            moveExisting({node.localId}, 0, *divMove);
            fromDivergence = Above {node.localId, true, elementRect(*div).bottom(),
                elementRect(*old.at(node.localId)).bottom(), *divMove, axis};
        }
        const double entryShift = divMove.value_or(carried);
        double pushed = 0;
        QRectF previous;
        std::vector<quint64> leftIds; // every element of the branches so far
        quint64 previousFirst = 0;
        std::vector<double> inAxes;
        std::vector<double> outAxes;
        std::optional<double> firstTop;
        for (Sequence &branch : node.branches) {
            const std::vector<quint64> ids = idsOf(branch);
            moveExisting(ids, pushed, 0);
            double branchAxis = axis;
            if (const std::optional<double> x = firstPlacedInX(branch))
                branchAxis = *x;
            else if (!previous.isNull())
                branchAxis = previous.right() + kBranchGap + measureSequence(doc, branch).left;
            Above start = fromDivergence;
            start.axis = branchAxis;
            // A new branch starts level with the first one (parallel steps side by side).
            if (!branch.empty() && allFresh(idsOf(branch.front())) && firstTop)
                start.bottom = std::max(start.bottom, *firstTop - kGap);
            walk(branch, branchAxis, start, entryShift, fromDivergence.bottom + kGap);
            if (!firstTop && !branch.empty())
                firstTop = elementRect(*doc.element(branch.front().localId)).top();
            QRectF extent = rectNow(ids, true);
            const quint64 first = branch.empty() ? 0 : branch.front().localId;
            // Right of the branches before it where they share rows, by the gap it had from them
            // (a branch drawn closer by another tool stays as close), or by the branch gap.
            const double clear = clearance(drawings(leftIds, true), drawings(ids, true));
            if (clear < kNoClash) {
                const double gap = oldNeighbours.contains({previousFirst, first})
                    ? gapToKeep(clearance(drawings(leftIds, false), drawings(ids, false)), clear, kBranchGap)
                    : kBranchGap;
                const double need = gap - clear;
                if (need > 0.01) {
                    moveAll(ids, need);
                    pushed += need;
                    extent.translate(need, 0);
                }
            }
            leftIds.insert(leftIds.end(), ids.begin(), ids.end());
            if (!branch.empty()) {
                inAxes.push_back(inX(*doc.element(branch.front().localId)));
                if (branch.back().kind != NodeKind::Jump)
                    outAxes.push_back(outX(*doc.element(bottomId(branch.back()))));
            } else
                inAxes.push_back(branchAxis);
            previous = extent.isNull() ? previous : extent;
            previousFirst = first;
        }
        if (!divMove || !barFits(node.localId, inAxes, true))
            fitBar(node.localId, inAxes, incoming);
        if (node.convergenceId == 0) {
            const std::vector<quint64> all = idsOf(node);
            return Above {node.localId, divMove.has_value(), rectNow(all).bottom(), rectBefore(all).bottom(), entryShift, axis};
        }
        const quint64 convergenceId = node.convergenceId;
        Element *convergence = doc.element(convergenceId);
        double dy = entryShift;
        if (!existed(convergenceId)) {
            double bottom = fromDivergence.bottom;
            for (const Sequence &branch : node.branches)
                bottom = std::max(bottom, rectNow(idsOf(branch)).bottom());
            ElementHeader &h = header(*convergence);
            h.position = {axis, bottom + kGap};
            h.width = 1;
            h.height = barHeight;
        } else {
            const double oldTop = elementRect(*old.at(convergenceId)).top();
            for (const Sequence &branch : node.branches) {
                const std::vector<quint64> ids = idsOf(branch);
                const QRectF now = rectNow(ids);
                if (now.isNull())
                    continue;
                const QRectF was = rectBefore(ids);
                const double gap = was.isNull() ? kGap : std::min(kGap, oldTop - was.bottom());
                dy = std::max(dy, now.bottom() + gap - oldTop);
            }
            moveExisting({convergenceId}, 0, dy);
        }
        const double outgoing = existed(convergenceId) ? outX(*convergence) : incoming;
        if (!barFits(convergenceId, outAxes, false))
            fitBar(convergenceId, outAxes, outgoing);
        const QRectF rect = elementRect(*convergence);
        const double oldBottom = existed(convergenceId) ? elementRect(*old.at(convergenceId)).bottom() : 0;
        return Above {convergenceId, existed(convergenceId), rect.bottom(), oldBottom, dy, outX(*convergence)};
    }

    // An existing step after the edit: a new name may widen it (around its axis), a new action
    // block goes right of it, a changed one is sized for its actions.
    void refit(const Node &node)
    {
        Element *e = doc.element(node.localId);
        const Element *was = old.at(node.localId);
        if (!e || !(std::holds_alternative<Step>(*e) || std::holds_alternative<MacroStep>(*e)))
            return;
        const QString name = doc.stepName(node.localId);
        const QString oldName = before.stepName(node.localId);
        const QRectF oldFrame = elementRect(*was);
        const QRectF moved = elementRect(*e);
        QRectF frame = moved;
        if (name != oldName) {
            // A box of our own size follows its name; one drawn by another tool only grows.
            const double width = qFuzzyCompare(oldFrame.width(), stepWidth(oldName)) ? stepWidth(name)
                                                                                     : std::max(oldFrame.width(), stepWidth(name));
            if (!qFuzzyCompare(width, frame.width())) {
                ElementHeader &h = header(*e);
                h.position.x = frame.center().x() - width / 2;
                h.width = width;
                auto pins = [&](auto &step) {
                    if (step.connectionPointIn)
                        step.connectionPointIn->relPosition = Position {width / 2, 0};
                    if (step.connectionPointOut)
                        step.connectionPointOut->relPosition = Position {width / 2, frame.height()};
                    if constexpr (requires { step.connectionPointOutAction; }) {
                        if (step.connectionPointOutAction)
                            step.connectionPointOutAction->relPosition = Position {width, frame.height() / 2};
                    }
                };
                if (auto *step = std::get_if<Step>(e))
                    pins(*step);
                else if (auto *macro = std::get_if<MacroStep>(e))
                    pins(*macro);
                repinned.insert(node.localId);
                frame = elementRect(*e);
            }
        }
        const quint64 blockId = doc.actionBlockOf(node.localId);
        auto *step = std::get_if<Step>(e);
        if (!blockId) {
            if (step && before.actionBlockOf(node.localId))
                step->connectionPointOutAction.reset();
            return;
        }
        if (step && !step->connectionPointOutAction) {
            step->connectionPointOutAction = ConnectionPointOut {Position {frame.width(), frame.height() / 2}, {}, {}, {}, {}, {}};
            repinned.insert(node.localId);
        }
        if (!existed(blockId)) {
            placeActionBlock(doc, node.localId, QPointF(frame.right() + kActionOffset, frame.top()));
            return;
        }
        Element *block = doc.element(blockId);
        header(*block).position.x += frame.right() - moved.right(); // stays beside a widened step
        const auto &actions = std::get<ActionBlock>(*block).actions;
        const auto &oldActions = std::get<ActionBlock>(*old.at(blockId)).actions;
        if (actions == oldActions)
            return;
        const QRectF oldBlock = elementRect(*block);
        placeActionBlock(doc, node.localId, oldBlock.topLeft());
        ElementHeader &h = header(*doc.element(blockId));
        h.width = std::max(h.width.value_or(0), oldBlock.width());
        repinned.insert(blockId);
    }

    // Chains side by side: a chain that grew pushes the chains right of it (those beside it).
    void separateChains()
    {
        std::vector<Sequence *> chains {&doc.chart.main};
        for (Sequence &chain : doc.chart.loose)
            chains.push_back(&chain);
        struct Column {
            std::vector<quint64> ids;
            QRectF now;
            QRectF was;
        };
        std::vector<Column> columns;
        for (Sequence *chain : chains) {
            if (chain->empty())
                continue;
            Column column {idsOf(*chain), {}, {}};
            column.now = rectNow(column.ids, true);
            column.was = rectBefore(column.ids, true);
            columns.push_back(std::move(column));
        }
        std::ranges::stable_sort(columns, [](const Column &a, const Column &b) {
            const double xa = a.was.isNull() ? a.now.left() : a.was.left();
            const double xb = b.was.isNull() ? b.now.left() : b.was.left();
            return xa < xb;
        });
        for (std::size_t j = 1; j < columns.size(); ++j) {
            double need = 0;
            for (std::size_t i = 0; i < j; ++i) {
                const double clear = clearance(drawings(columns[i].ids, true), drawings(columns[j].ids, true));
                if (clear >= kNoClash)
                    continue;
                const double gap = gapToKeep(clearance(drawings(columns[i].ids, false), drawings(columns[j].ids, false)), clear, 2 * kBranchGap);
                need = std::max(need, gap - clear);
            }
            if (need > 0.01)
                moveAll(columns[j].ids, need);
        }
    }

    void placeChains()
    {
        double freshLeft = kMargin;
        for (const Element &e : doc.elements)
            if (existed(header(e).localId))
                freshLeft = std::max(freshLeft, drawnRect(e).right() + 2 * kBranchGap);
        auto placeChain = [&](Sequence &chain) {
            std::optional<double> axis = firstPlacedInX(chain);
            double top = kMargin;
            for (const Node &node : chain)
                if (existed(node.localId)) {
                    top = elementRect(*old.at(node.localId)).top();
                    break;
                }
            if (!axis)
                axis = freshLeft + measureSequence(doc, chain).left;
            walk(chain, *axis, std::nullopt, 0, top);
        };
        placeChain(doc.chart.main);
        for (Sequence &chain : doc.chart.loose)
            placeChain(chain);
        separateChains();
    }

    // Wires: one whose ends kept their places (or moved together) keeps its corners (moved
    // along); any other is routed again.
    void routeWires()
    {
        for (Element &e : doc.elements) {
            const auto was = old.find(header(e).localId);
            auto *transition = std::get_if<Transition>(&e);
            for (ConnectionPointIn *point : inputPoints(e)) {
                const bool condition = transition && !(transition->connectionPointIn && point == &*transition->connectionPointIn);
                for (Connection &c : point->connections) {
                    const Element *source = doc.element(c.refLocalId);
                    if (!source)
                        continue;
                    if (const std::optional<std::vector<Position>> kept = keptWaypoints(e, was == old.end() ? nullptr : was->second, c))
                        c.waypoints = *kept;
                    else if (isChainElement(e) && (condition || isChainElement(*source)))
                        c.waypoints = route(e, *source, condition);
                    // Wires inside a condition's network are another language's: they keep theirs.
                }
            }
        }
    }

    [[nodiscard]] std::optional<std::vector<Position>> keptWaypoints(const Element &e, const Element *was, const Connection &c) const
    {
        const auto sourceWas = old.find(c.refLocalId);
        if (!was || sourceWas == old.end() || repinned.contains(header(e).localId) || repinned.contains(c.refLocalId))
            return std::nullopt;
        const Connection *oldWire = nullptr;
        for (const ConnectionPointIn *point : inputPoints(*was))
            for (const Connection &o : point->connections)
                if (o.refLocalId == c.refLocalId)
                    oldWire = &o;
        const Element *source = doc.element(c.refLocalId);
        const QRectF a = elementRect(e);
        const QRectF a0 = elementRect(*was);
        const QRectF b = elementRect(*source);
        const QRectF b0 = elementRect(*sourceWas->second);
        const QPointF delta = a.topLeft() - a0.topLeft();
        if (!oldWire || a.size() != a0.size() || b.size() != b0.size() || b.topLeft() - b0.topLeft() != delta)
            return std::nullopt;
        std::vector<Position> points = oldWire->waypoints;
        for (Position &p : points) {
            p.x += delta.x();
            p.y += delta.y();
        }
        return points;
    }

    [[nodiscard]] static std::vector<Position> route(const Element &target, const Element &source, bool condition)
    {
        const QRectF to = elementRect(target);
        const QRectF from = elementRect(source);
        auto sideways = [](QPointF start, QPointF end) {
            if (qFuzzyCompare(start.y() + 1, end.y() + 1))
                return std::vector<Position> {{start.x(), start.y()}, {end.x(), end.y()}};
            const double middle = (start.x() + end.x()) / 2;
            return std::vector<Position> {{start.x(), start.y()}, {middle, start.y()}, {middle, end.y()}, {end.x(), end.y()}};
        };
        if (const auto *block = std::get_if<ActionBlock>(&target)) {
            const auto *step = std::get_if<Step>(&source);
            const QPointF pin = step && step->connectionPointOutAction && step->connectionPointOutAction->relPosition
                ? from.topLeft() + QPointF(step->connectionPointOutAction->relPosition->x, step->connectionPointOutAction->relPosition->y)
                : QPointF(from.right(), from.top() + kStepHeight / 2);
            const QPointF in = block->connectionPointIn && block->connectionPointIn->relPosition
                ? to.topLeft() + QPointF(block->connectionPointIn->relPosition->x, block->connectionPointIn->relPosition->y)
                : QPointF(to.left(), pin.y());
            return sideways(in, pin);
        }
        if (condition)
            return sideways(QPointF(to.left(), to.center().y()), QPointF(from.right(), from.center().y()));
        if (!(isBar(source) || std::holds_alternative<Step>(source) || std::holds_alternative<MacroStep>(source)
                || std::holds_alternative<Transition>(source)))
            return {};
        const QList<QPointF> line = wirePolyline(source, target);
        std::vector<Position> points;
        for (auto it = line.rbegin(); it != line.rend(); ++it)
            points.push_back({it->x(), it->y()});
        return points;
    }
};

} // namespace

bool isUnplaced(const std::vector<Element> &elements)
{
    return std::ranges::all_of(elements, [](const Element &e) { return header(e).position == Position {}; });
}

void placeEdit(const ChartDocument &before, ChartDocument &after)
{
    if (before.chart.isEmpty() || isUnplaced(before.elements)) {
        layoutChart(after);
        return;
    }
    Placer placer(before, after);
    placer.placeChains();
    placer.routeWires();
}

} // namespace iec::editors::sfc
