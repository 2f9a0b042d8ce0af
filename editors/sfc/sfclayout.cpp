#include "editors/sfc/sfclayout.h"

#include "editors/sfc/sfcgeometry.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>
#include <unordered_set>

namespace iec::editors::sfc {

using namespace model;

namespace {

struct Layouter {
    ChartDocument &document;

    [[nodiscard]] double barHeight(const Node &node) const
    {
        return node.kind == NodeKind::Parallel ? kParallelBarHeight : kSelectionBarHeight;
    }

    QRectF actionBlockSize(quint64 stepId) const
    {
        const quint64 blockId = document.actionBlockOf(stepId);
        const Element *e = blockId ? document.element(blockId) : nullptr;
        const auto *block = e ? std::get_if<ActionBlock>(e) : nullptr;
        if (!block || block->actions.empty())
            return {};
        return {0, 0, actionBlockColumns(*block).total(), kActionRow * double(block->actions.size())};
    }

    // The element wired into a transition's condition (CODESYS writes conditions that way): its
    // size, drawn left of the transition. Empty when the condition is not wired.
    [[nodiscard]] quint64 conditionSource(quint64 transitionId) const
    {
        const Element *e = document.element(transitionId);
        const auto *transition = e ? std::get_if<Transition>(e) : nullptr;
        if (!transition || !transition->condition)
            return quint64(-1);
        const auto *wire = std::get_if<ConnectionPointIn>(&transition->condition->kind);
        if (!wire || wire->connections.empty())
            return quint64(-1);
        return wire->connections.front().refLocalId;
    }

    [[nodiscard]] QRectF conditionInput(quint64 transitionId) const
    {
        const quint64 source = conditionSource(transitionId);
        const Element *e = source == quint64(-1) ? nullptr : document.element(source);
        if (!e)
            return {};
        const QRectF rect = elementRect(*e);
        return {0, 0, rect.width(), rect.height()};
    }

    Extent measure(const Node &node) const
    {
        switch (node.kind) {
        case NodeKind::Step:
        case NodeKind::MacroStep: {
            const double width = stepWidth(document.stepName(node.localId));
            const QRectF block = actionBlockSize(node.localId);
            return {width / 2, width / 2 + (block.isEmpty() ? 0 : kActionOffset + block.width()),
                std::max(kStepHeight, block.height())};
        }
        case NodeKind::Transition: {
            const Element *e = document.element(node.localId);
            const auto *transition = e ? std::get_if<Transition>(e) : nullptr;
            const QString text = transition ? transitionLabel(*transition) : QString();
            const QRectF input = conditionInput(node.localId);
            return {kTransitionWidth / 2 + (input.isEmpty() ? 0 : 2 * kLabelGap + input.width()),
                kTransitionWidth / 2 + kLabelGap + textWidth(text), std::max(kTransitionHeight, input.height())};
        }
        case NodeKind::Jump: {
            const Element *e = node.wired ? nullptr : document.element(node.localId);
            const QString target = e && std::holds_alternative<JumpStep>(*e) ? std::get<JumpStep>(*e).targetName
                                                                             : document.stepName(node.wiredTarget);
            return {kJumpWidth / 2, kJumpWidth / 2 + kLabelGap + textWidth(target), kJumpHeight};
        }
        case NodeKind::Selection:
        case NodeKind::Parallel:
            break;
        }
        Extent extent;
        double axis = 0;
        double tallest = 0;
        for (std::size_t i = 0; i < node.branches.size(); ++i) {
            const Extent branch = measure(node.branches[i]);
            if (i == 0)
                extent.left = branch.left;
            else
                axis += branch.left;
            extent.right = axis + branch.right;
            axis += branch.right + kBranchGap;
            tallest = std::max(tallest, branch.height);
        }
        extent.height = 2 * barHeight(node) + 2 * kGap + tallest;
        return extent;
    }

    Extent measure(const Sequence &sequence) const
    {
        Extent extent;
        for (std::size_t i = 0; i < sequence.size(); ++i) {
            const Extent node = measure(sequence[i]);
            extent.left = std::max(extent.left, node.left);
            extent.right = std::max(extent.right, node.right);
            extent.height += node.height + (i > 0 ? kGap : 0);
        }
        return extent;
    }

    void setGeometry(quint64 id, double x, double y, double width, double height)
    {
        if (Element *e = document.element(id)) {
            ElementHeader &h = header(*e);
            h.position = {x, y};
            h.width = width;
            h.height = height;
        }
    }

    void placeStep(const Node &node, double axis, double y)
    {
        const double width = stepWidth(document.stepName(node.localId));
        setGeometry(node.localId, axis - width / 2, y, width, kStepHeight);
        Element *e = document.element(node.localId);
        const quint64 blockId = document.actionBlockOf(node.localId);
        auto pins = [&](auto &step) {
            if (step.connectionPointIn)
                step.connectionPointIn->relPosition = Position {width / 2, 0};
            if (step.connectionPointOut)
                step.connectionPointOut->relPosition = Position {width / 2, kStepHeight};
            if constexpr (requires { step.connectionPointOutAction; }) {
                if (blockId)
                    step.connectionPointOutAction = ConnectionPointOut {Position {width, kStepHeight / 2}, {}, {}, {}, {}, {}};
                else
                    step.connectionPointOutAction.reset();
            }
        };
        if (auto *step = std::get_if<Step>(e))
            pins(*step);
        else if (auto *macro = std::get_if<MacroStep>(e))
            pins(*macro);
        if (blockId)
            placeActionBlock(node.localId, QPointF(axis + width / 2 + kActionOffset, y));
    }

    // The step's action block with its top left corner at `at`, sized for its actions, wired
    // straight from the step's right border.
    void placeActionBlock(quint64 stepId, QPointF at)
    {
        const quint64 blockId = document.actionBlockOf(stepId);
        const Element *stepElement = document.element(stepId);
        auto *block = blockId ? std::get_if<ActionBlock>(document.element(blockId)) : nullptr;
        if (!block || !stepElement)
            return;
        const QRectF step = elementRect(*stepElement);
        const QRectF size = actionBlockSize(stepId);
        const double pinY = step.top() + kStepHeight / 2;
        setGeometry(blockId, at.x(), at.y(), std::max(size.width(), 1.0), std::max(size.height(), kActionRow));
        block = std::get_if<ActionBlock>(document.element(blockId));
        if (block->connectionPointIn) {
            block->connectionPointIn->relPosition = Position {0, pinY - at.y()};
            for (Connection &c : block->connectionPointIn->connections)
                c.waypoints = {{at.x(), pinY}, {step.right(), pinY}};
        }
        for (std::size_t i = 0; i < block->actions.size(); ++i) {
            block->actions[i].relPosition = {0, kActionRow * double(i)};
            block->actions[i].width = size.width();
            block->actions[i].height = kActionRow;
        }
    }

    void place(Node &node, double axis, double y)
    {
        switch (node.kind) {
        case NodeKind::Step:
        case NodeKind::MacroStep:
            placeStep(node, axis, y);
            return;
        case NodeKind::Transition: {
            const double height = std::max(kTransitionHeight, conditionInput(node.localId).height());
            const double top = y + (height - kTransitionHeight) / 2;
            setGeometry(node.localId, axis - kTransitionWidth / 2, top, kTransitionWidth, kTransitionHeight);
            if (const QRectF input = conditionInput(node.localId); !input.isEmpty()) {
                const quint64 source = conditionSource(node.localId);
                const double inputX = axis - kTransitionWidth / 2 - kLabelGap - input.width();
                setGeometry(source, inputX, top + kTransitionHeight / 2 - input.height() / 2, input.width(), input.height());
                if (auto *t = std::get_if<Transition>(document.element(node.localId))) {
                    for (Connection &c : std::get<ConnectionPointIn>(t->condition->kind).connections)
                        c.waypoints = {{axis - kTransitionWidth / 2, top + kTransitionHeight / 2},
                            {inputX + input.width(), top + kTransitionHeight / 2}};
                }
            }
            if (auto *t = std::get_if<Transition>(document.element(node.localId))) {
                if (t->connectionPointIn)
                    t->connectionPointIn->relPosition = Position {kTransitionWidth / 2, 0};
                if (t->connectionPointOut)
                    t->connectionPointOut->relPosition = Position {kTransitionWidth / 2, kTransitionHeight};
            }
            return;
        }
        case NodeKind::Jump:
            if (node.wired)
                return;
            setGeometry(node.localId, axis - kJumpWidth / 2, y, kJumpWidth, kJumpHeight);
            if (auto *j = std::get_if<JumpStep>(document.element(node.localId)); j && j->connectionPointIn)
                j->connectionPointIn->relPosition = Position {kJumpWidth / 2, 0};
            return;
        case NodeKind::Selection:
        case NodeKind::Parallel:
            placeBlock(node, axis, y);
            return;
        }
    }

    void placeBlock(Node &node, double axis, double y)
    {
        const double bar = barHeight(node);
        std::vector<double> axes;
        double offset = 0;
        double tallest = 0;
        for (std::size_t i = 0; i < node.branches.size(); ++i) {
            const Extent branch = measure(node.branches[i]);
            if (i > 0)
                offset += branch.left;
            axes.push_back(axis + offset);
            offset += branch.right + kBranchGap;
            tallest = std::max(tallest, branch.height);
        }
        const double width = std::max(axes.empty() ? 1.0 : axes.back() - axis, 1.0);
        setGeometry(node.localId, axis, y, width, bar);
        const double branchTop = y + bar + kGap;
        for (std::size_t i = 0; i < node.branches.size(); ++i)
            place(node.branches[i], axes[i], branchTop);
        auto setDivergencePins = [&](auto &d) {
            if (d.connectionPointIn)
                d.connectionPointIn->relPosition = Position {0, 0};
            for (std::size_t i = 0; i < d.connectionPointOuts.size() && i < axes.size(); ++i)
                d.connectionPointOuts[i].relPosition = Position {axes[i] - axis, bar};
        };
        if (Element *e = document.element(node.localId)) {
            if (auto *s = std::get_if<SelectionDivergence>(e))
                setDivergencePins(*s);
            else if (auto *p = std::get_if<SimultaneousDivergence>(e))
                setDivergencePins(*p);
        }
        if (node.convergenceId == 0)
            return;
        setGeometry(node.convergenceId, axis, branchTop + tallest + kGap, width, bar);
        std::vector<double> openAxes;
        for (std::size_t i = 0; i < node.branches.size(); ++i) {
            if (!node.branches[i].empty() && node.branches[i].back().kind != NodeKind::Jump)
                openAxes.push_back(axes[i]);
        }
        auto setConvergencePins = [&](auto &c) {
            for (std::size_t i = 0; i < c.connectionPointIns.size() && i < openAxes.size(); ++i)
                c.connectionPointIns[i].relPosition = Position {openAxes[i] - axis, 0};
            if (c.connectionPointOut)
                c.connectionPointOut->relPosition = Position {0, bar};
        };
        if (Element *e = document.element(node.convergenceId)) {
            if (auto *s = std::get_if<SelectionConvergence>(e))
                setConvergencePins(*s);
            else if (auto *p = std::get_if<SimultaneousConvergence>(e))
                setConvergencePins(*p);
        }
    }

    void place(Sequence &sequence, double axis, double y)
    {
        for (Node &node : sequence) {
            place(node, axis, y);
            y += measure(node).height + kGap;
        }
    }

    // Waypoints as TC6 tools write them: from the input back to the source's output.
    void routeWires()
    {
        for (Element &e : document.elements) {
            if (std::holds_alternative<ActionBlock>(e))
                continue;
            std::vector<ConnectionPointIn *> points = inputPoints(e);
            if (auto *t = std::get_if<Transition>(&e)) // its wired condition is a side input
                points = t->connectionPointIn ? std::vector<ConnectionPointIn *> {&*t->connectionPointIn}
                                              : std::vector<ConnectionPointIn *> {};
            for (ConnectionPointIn *point : points) {
                for (Connection &c : point->connections) {
                    const Element *source = document.element(c.refLocalId);
                    if (!source || !(isBar(*source) || std::holds_alternative<Step>(*source)
                            || std::holds_alternative<MacroStep>(*source) || std::holds_alternative<Transition>(*source)))
                        continue;
                    QList<QPointF> line = wirePolyline(*source, e);
                    c.waypoints.clear();
                    for (auto it = line.rbegin(); it != line.rend(); ++it)
                        c.waypoints.push_back({it->x(), it->y()});
                }
            }
        }
    }
};

} // namespace

Extent measureNode(const ChartDocument &document, const Node &node)
{
    Layouter layouter {const_cast<ChartDocument &>(document)}; // measuring only reads
    return layouter.measure(node);
}

Extent measureSequence(const ChartDocument &document, const Sequence &sequence)
{
    Layouter layouter {const_cast<ChartDocument &>(document)};
    return layouter.measure(sequence);
}

void placeNode(ChartDocument &document, Node &node, double axis, double top)
{
    Layouter {document}.place(node, axis, top);
}

void placeActionBlock(ChartDocument &document, quint64 stepId, QPointF topLeft)
{
    Layouter {document}.placeActionBlock(stepId, topLeft);
}

void layoutChart(ChartDocument &document)
{
    Layouter layouter {document};
    double left = kMargin;
    auto placeChain = [&](Sequence &chain) {
        const Extent extent = layouter.measure(chain);
        layouter.place(chain, left + extent.left, kMargin);
        left += extent.left + extent.right + 2 * kBranchGap;
    };
    placeChain(document.chart.main);
    for (Sequence &chain : document.chart.loose)
        placeChain(chain);
    layouter.routeWires();
}

} // namespace iec::editors::sfc
