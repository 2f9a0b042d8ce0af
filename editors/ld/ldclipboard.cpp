// Copy and paste of networks and of ranges of rung elements (seed 002 §1: "cut, copy and paste of
// elements and of whole networks"; CoDeSys 2.3: paste after, below or above the cursor).
#include "editors/common/diagramclipboard.h"
#include "editors/ld/ldedits.h"
#include "editors/ld/ldgraph.h"
#include "editors/ld/ldtree.h"

#include <QCoreApplication>

#include <algorithm>
#include <set>
#include <unordered_map>

namespace iec::editors::ld {

using namespace model;

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("iec::editors::ld::LdEdits", text);
}

// Marks the left rail of a copied range of elements: pasted, it goes into a rung; without it the
// fragment is whole networks.
const QString kRangeMarker = QStringLiteral("https://iec-studio.org/ld-range");

bool isLadderElement(const Element &e)
{
    return std::holds_alternative<Contact>(e) || std::holds_alternative<Coil>(e) || std::holds_alternative<Block>(e)
        || std::holds_alternative<InVariable>(e) || std::holds_alternative<OutVariable>(e)
        || std::holds_alternative<InOutVariable>(e) || std::holds_alternative<LeftPowerRail>(e)
        || std::holds_alternative<RightPowerRail>(e) || std::holds_alternative<Label>(e) || std::holds_alternative<Jump>(e)
        || std::holds_alternative<Return>(e) || std::holds_alternative<Comment>(e)
        || std::holds_alternative<VendorElement>(e) || std::holds_alternative<Connector>(e)
        || std::holds_alternative<Continuation>(e);
}

bool isRangeFragment(const std::vector<Element> &fragment)
{
    return std::ranges::any_of(fragment, [](const Element &e) {
        const auto *rail = std::get_if<LeftPowerRail>(&e);
        return rail && std::ranges::any_of(rail->addData, [](const AddDataEntry &d) { return d.name == kRangeMarker; });
    });
}

// The elements of a rung node that power leaves from (its right end).
void endsOf(const RungNode &node, std::vector<quint64> &ends)
{
    switch (node.kind) {
    case RungNode::Kind::Element: ends.push_back(node.localId); break;
    case RungNode::Kind::Series:
        if (!node.children.empty())
            endsOf(node.children.back(), ends);
        break;
    case RungNode::Kind::Parallel:
        for (const RungNode &branch : node.children)
            endsOf(branch, ends);
        break;
    }
}

void startsOf(const RungNode &node, std::vector<quint64> &starts)
{
    switch (node.kind) {
    case RungNode::Kind::Element: starts.push_back(node.localId); break;
    case RungNode::Kind::Series:
        if (!node.children.empty())
            startsOf(node.children.front(), starts);
        break;
    case RungNode::Kind::Parallel:
        for (const RungNode &branch : node.children)
            startsOf(branch, starts);
        break;
    }
}

// Gives the pasted elements the document's next free localIds (the shared clipboard's
// renumbering: wires between them follow, wires to anything else are dropped).
std::unordered_map<quint64, quint64> renumberInto(LadderDocument &document, std::vector<Element> &elements)
{
    const quint64 first = document.idFloor + 1;
    std::unordered_map<quint64, quint64> map = renumberElements(elements, first);
    document.idFloor += elements.size();
    return map;
}

quint64 mapped(const std::unordered_map<quint64, quint64> &map, quint64 id)
{
    const auto it = map.find(id);
    return it == map.end() ? 0 : it->second;
}

void renumberNode(RungNode &node, const std::unordered_map<quint64, quint64> &map)
{
    if (node.isElement())
        node.localId = mapped(map, node.localId);
    for (RungNode &child : node.children)
        renumberNode(child, map);
}

// The index in the file after every element of networks [0, network].
int fileIndexAfter(const LadderDocument &document, int network)
{
    int index = 0;
    for (int n = 0; n <= network && n < int(document.networks.size()); ++n)
        for (quint64 id : document.networks[std::size_t(n)].members)
            index = std::max(index, document.indexOf(id) + 1);
    return index;
}

LdEditResult pasteNetworks(LadderDocument &document, const LdCursor &cursor, LadderDocument pasted)
{
    const int after = document.networks.empty() ? -1 : std::clamp(cursor.network, 0, int(document.networks.size()) - 1);
    const std::unordered_map<quint64, quint64> map = renumberInto(document, pasted.elements);
    const int firstIndex = fileIndexAfter(document, after);
    document.elements.insert(document.elements.begin() + firstIndex, std::make_move_iterator(pasted.elements.begin()),
        std::make_move_iterator(pasted.elements.end()));
    document.reindexFrom(std::size_t(firstIndex));
    int at = after + 1;
    for (LdNetwork network : pasted.networks) {
        for (quint64 &id : network.members)
            id = mapped(map, id);
        for (quint64 *id : {&network.leftRail, &network.rightRail, &network.label, &network.comment, &network.title})
            *id = mapped(map, *id);
        renumberNode(network.rung, map);
        document.networks.insert(document.networks.begin() + at++, std::move(network));
    }
    for (const auto &[box, pins] : pasted.boxPins)
        document.boxPins[mapped(map, box)] = pins;
    return {{}, LdCursor::atNetwork(after + 1)};
}

LdEditResult pasteRange(LadderDocument &document, const LdCursor &cursor, LadderDocument pasted, PasteMode mode)
{
    if (pasted.networks.size() != 1 || pasted.networks.front().freehand)
        return {QCoreApplication::translate("iec::editors::ld::LdEdits", "The clipboard holds elements that do not form a rung."), {}};
    if (cursor.network < 0 || cursor.network >= int(document.networks.size()))
        return {QCoreApplication::translate("iec::editors::ld::LdEdits", "There is no network here. Insert a network first (Network After)."), {}};
    LdNetwork &network = document.networks[std::size_t(cursor.network)];
    if (network.freehand)
        return {QCoreApplication::translate("iec::editors::ld::LdEdits", "This network is drawn freely by another tool, not as a rung: paste into a rung network."), {}};
    const LdNetwork &source = pasted.networks.front();
    // The fragment's own rails stay behind; everything else joins the network.
    std::erase_if(pasted.elements, [&](const Element &e) {
        const quint64 id = header(e).localId;
        return id == source.leftRail || id == source.rightRail;
    });
    const std::unordered_map<quint64, quint64> map = renumberInto(document, pasted.elements);
    RungNode nodes = source.rung;
    renumberNode(nodes, map);
    const int firstIndex = fileIndexAfter(document, cursor.network);
    for (const Element &e : pasted.elements)
        network.members.push_back(header(e).localId);
    document.elements.insert(document.elements.begin() + firstIndex, std::make_move_iterator(pasted.elements.begin()),
        std::make_move_iterator(pasted.elements.end()));
    document.reindexFrom(std::size_t(firstIndex));
    for (const auto &[box, pins] : pasted.boxPins)
        document.boxPins[mapped(map, box)] = pins;
    const quint64 first = rungElements(nodes).empty() ? 0 : rungElements(nodes).front();
    if (mode == PasteMode::After) {
        std::vector<int> path;
        int index = tree::outputTail(document, network.rung);
        if (cursor.kind == LdCursor::Kind::Element) {
            if (const auto place = tree::placeOf(network.rung, cursor.element())) {
                path = place->seriesPath;
                index = place->index + 1;
            }
        } else if (cursor.kind == LdCursor::Kind::Wire) {
            path = cursor.wire.path;
            index = cursor.wire.index;
        }
        RungNode *series = tree::nodeAt(network.rung, path);
        if (!series || series->kind != RungNode::Kind::Series)
            return {QCoreApplication::translate("iec::editors::ld::LdEdits", "Put the cursor on an element or on a wire of the rung first."), {}};
        index = std::clamp(index, 0, int(series->children.size()));
        series->children.insert(series->children.begin() + index, std::move(nodes));
    } else {
        if (cursor.kind != LdCursor::Kind::Element)
            return {QCoreApplication::translate("iec::editors::ld::LdEdits", "Select the elements the pasted ones go parallel to."), {}};
        const std::vector<int> path = pathOf(network.rung, cursor.element());
        if (path.empty())
            return {QCoreApplication::translate("iec::editors::ld::LdEdits", "Select the elements the pasted ones go parallel to."), {}};
        RungNode *series = tree::nodeAt(network.rung, std::vector<int>(path.begin(), path.end() - 1));
        RungNode &around = series->children[std::size_t(path.back())];
        RungNode kept = RungNode::series({std::move(around)});
        around = mode == PasteMode::Below ? RungNode::parallel({std::move(kept), std::move(nodes)})
                                          : RungNode::parallel({std::move(nodes), std::move(kept)});
    }
    tree::normalize(network.rung);
    return {{}, first ? LdCursor::atElement(cursor.network, first) : LdCursor::atNetwork(cursor.network)};
}

} // namespace

std::vector<Element> copyAtCursor(const LadderDocument &document, const LdCursor &cursor, QString *error)
{
    const auto fail = [&](const char *text) {
        if (error)
            *error = tr(text);
        return std::vector<Element> {};
    };
    if (cursor.network < 0 || cursor.network >= int(document.networks.size()))
        return fail(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "There is nothing to copy here."));
    const LdNetwork &network = document.networks[std::size_t(cursor.network)];
    std::vector<Element> fragment;
    if (cursor.kind == LdCursor::Kind::Network) {
        for (const Element &e : document.elements)
            if (std::ranges::find(network.members, header(e).localId) != network.members.end())
                fragment.push_back(e);
        return fragment;
    }
    if (cursor.kind != LdCursor::Kind::Element)
        return fail(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Select elements or a network to copy."));
    if (network.freehand)
        return fail(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "This network is drawn freely: copy the whole network (click its number)."));
    std::vector<quint64> ids = cursor.elements;
    std::vector<std::vector<int>> paths;
    for (quint64 id : ids)
        if (std::vector<int> path = pathOf(network.rung, id); !path.empty())
            paths.push_back(std::move(path));
    if (paths.empty())
        return fail(QT_TRANSLATE_NOOP("iec::editors::ld::LdEdits", "Select rung elements (contacts, coils, boxes) or a network to copy."));
    // The range: children [first, last] of the deepest series that holds every selected element.
    std::vector<int> prefix = paths.front();
    prefix.pop_back();
    for (const auto &path : paths) {
        std::size_t same = 0;
        while (same < prefix.size() && same + 1 < path.size() && path[same] == prefix[same])
            ++same;
        prefix.resize(same);
    }
    while (!prefix.empty() && tree::nodeAt(network.rung, prefix)->kind != RungNode::Kind::Series)
        prefix.pop_back();
    int first = std::numeric_limits<int>::max();
    int last = -1;
    for (const auto &path : paths) {
        first = std::min(first, path[prefix.size()]);
        last = std::max(last, path[prefix.size()]);
    }
    const RungNode *series = tree::nodeAt(network.rung, prefix);
    RungNode range = RungNode::series(std::vector<RungNode>(series->children.begin() + first, series->children.begin() + last + 1));
    std::set<quint64> taken;
    for (quint64 id : rungElements(range)) {
        taken.insert(id);
        if (const Element *e = document.element(id); e && std::holds_alternative<Block>(*e)) {
            // A box's side variables come with it.
            const LdGraph graph(document.elements);
            const std::size_t index = std::size_t(document.indexOf(id));
            for (const LdGraph::Wire &wire : graph.inputs(index))
                if (wire.pin != document.pinsOf(id).input)
                    taken.insert(graph.localId(wire.source));
            for (const LdGraph::Reader &reader : graph.readers(index))
                if (std::holds_alternative<OutVariable>(graph.element(reader.target)) && reader.sourcePin != document.pinsOf(id).output)
                    taken.insert(graph.localId(reader.target));
        }
    }
    for (const Element &e : document.elements)
        if (taken.contains(header(e).localId))
            fragment.push_back(e);
    // Rails of its own: power enters the range's first elements and leaves its last ones.
    quint64 spare = 0;
    for (const Element &e : fragment)
        spare = std::max(spare, header(e).localId);
    LeftPowerRail left;
    left.localId = spare + 1;
    left.addData.push_back(AddDataEntry {kRangeMarker, QStringLiteral("discard"), QStringLiteral("<range/>")});
    left.connectionPointOuts.push_back(ConnectionPointOut {});
    RightPowerRail right;
    right.localId = spare + 2;
    std::vector<quint64> starts;
    std::vector<quint64> ends;
    startsOf(range, starts);
    endsOf(range, ends);
    for (Element &e : fragment) {
        const quint64 id = header(e).localId;
        if (std::ranges::find(starts, id) == starts.end())
            continue;
        const Connection fromRail {left.localId, std::nullopt, {}, {}, {}, {}};
        if (auto *block = std::get_if<Block>(&e)) {
            auto &input = block->inputVariables[std::size_t(document.pinsOf(id).input)].connectionPointIn;
            if (!input)
                input.emplace();
            input->connections = {fromRail};
        } else if (const std::vector<ConnectionPointIn *> points = inputPoints(e); !points.empty())
            points.front()->connections = {fromRail};
    }
    for (quint64 id : ends) {
        const Element *e = document.element(id);
        if (!e || !(std::holds_alternative<Contact>(*e) || std::holds_alternative<Coil>(*e) || std::holds_alternative<Block>(*e)))
            continue;
        std::optional<QString> formal;
        if (const auto *block = std::get_if<Block>(e); block && document.pinsOf(id).output >= 0)
            formal = block->outputVariables[std::size_t(document.pinsOf(id).output)].formalParameter;
        else if (std::holds_alternative<Block>(*e))
            continue;
        ConnectionPointIn point;
        point.connections.push_back(Connection {id, formal, {}, {}, {}, {}});
        right.connectionPointIns.push_back(std::move(point));
    }
    fragment.insert(fragment.begin(), std::move(left));
    fragment.push_back(std::move(right));
    return fragment;
}

LdEditResult pasteFragment(LadderDocument &document, const LdCursor &cursor, std::vector<Element> fragment, PasteMode mode)
{
    if (fragment.empty())
        return {QCoreApplication::translate("iec::editors::ld::LdEdits", "There is nothing to paste."), {}};
    if (!std::ranges::all_of(fragment, isLadderElement))
        return {QCoreApplication::translate("iec::editors::ld::LdEdits", "The clipboard holds elements of another language (not a ladder diagram): nothing was pasted."), {}};
    const bool range = isRangeFragment(fragment);
    LadderDocument pasted = readLadder(std::move(fragment));
    if (range)
        return pasteRange(document, cursor, std::move(pasted), mode);
    return pasteNetworks(document, cursor, std::move(pasted));
}

} // namespace iec::editors::ld
