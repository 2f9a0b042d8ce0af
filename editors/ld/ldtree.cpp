#include "editors/ld/ldtree.h"

namespace iec::editors::ld::tree {

RungNode *nodeAt(RungNode &root, const std::vector<int> &path)
{
    RungNode *node = &root;
    for (int index : path) {
        if (index < 0 || index >= int(node->children.size()))
            return nullptr;
        node = &node->children[std::size_t(index)];
    }
    return node;
}

const RungNode *nodeAt(const RungNode &root, const std::vector<int> &path)
{
    return nodeAt(const_cast<RungNode &>(root), path);
}

namespace {

void normalizeNode(RungNode &node)
{
    if (node.isElement())
        return;
    std::vector<RungNode> children;
    for (RungNode &child : node.children) {
        normalizeNode(child);
        const bool emptyBranch = child.kind == RungNode::Kind::Series && child.children.empty();
        const bool emptyParallel = child.kind == RungNode::Kind::Parallel && child.children.empty();
        if ((node.kind == RungNode::Kind::Parallel && emptyBranch) || emptyParallel)
            continue;
        // A parallel of one branch is that branch; in a series it is spliced in.
        if (child.kind == RungNode::Kind::Parallel && child.children.size() == 1) {
            RungNode only = std::move(child.children.front());
            child = std::move(only);
        }
        if (child.kind == node.kind) {
            for (RungNode &grandchild : child.children)
                children.push_back(std::move(grandchild));
        } else if (node.kind == RungNode::Kind::Parallel && child.kind != RungNode::Kind::Series) {
            children.push_back(RungNode::series({std::move(child)})); // branches are series
        } else
            children.push_back(std::move(child));
    }
    node.children = std::move(children);
}

bool find(const RungNode &node, quint64 id, std::vector<int> &path)
{
    if (node.isElement())
        return node.localId == id;
    for (std::size_t i = 0; i < node.children.size(); ++i) {
        path.push_back(int(i));
        if (find(node.children[i], id, path))
            return true;
        path.pop_back();
    }
    return false;
}

} // namespace

void normalize(RungNode &rung)
{
    normalizeNode(rung);
    if (rung.kind != RungNode::Kind::Series)
        rung = RungNode::series({std::move(rung)});
    // Parallel branches whose series was flattened into a parallel sibling must stay series.
    std::vector<RungNode *> stack {&rung};
    while (!stack.empty()) {
        RungNode *node = stack.back();
        stack.pop_back();
        for (RungNode &child : node->children) {
            if (node->kind == RungNode::Kind::Parallel && child.kind != RungNode::Kind::Series)
                child = RungNode::series({std::move(child)});
            stack.push_back(&child);
        }
    }
}

std::optional<Place> placeOf(const RungNode &rung, quint64 localId)
{
    std::vector<int> path;
    if (!find(rung, localId, path) || path.empty())
        return std::nullopt;
    const int index = path.back();
    path.pop_back();
    return Place {path, index};
}

bool endsInOutput(const LadderDocument &document, const RungNode &node)
{
    switch (node.kind) {
    case RungNode::Kind::Element: {
        const model::Element *e = document.element(node.localId);
        return e && isOutput(*e);
    }
    case RungNode::Kind::Series:
        return !node.children.empty() && endsInOutput(document, node.children.back());
    case RungNode::Kind::Parallel:
        return std::ranges::all_of(node.children, [&](const RungNode &b) { return endsInOutput(document, b); });
    }
    return false;
}

int outputTail(const LadderDocument &document, const RungNode &rung)
{
    int tail = int(rung.children.size());
    while (tail > 0 && endsInOutput(document, rung.children[std::size_t(tail - 1)]))
        --tail;
    return tail;
}

} // namespace iec::editors::ld::tree
