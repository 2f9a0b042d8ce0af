// Copy, cut and paste in the FBD editor: networks, and branches (a box and everything that feeds
// it) that move from one input to another (editors/fbd/fbdedits.h).
#include "editors/fbd/fbdedits.h"

#include "editors/fbd/fbdeditsupport.h"

#include <QCoreApplication>

#include <algorithm>
#include <unordered_map>

namespace iec::editors::fbd {

using namespace model;
using namespace detail;
using Kind = FbdCursor::Kind;

std::vector<Element> copyAtCursor(const FbdDocument &document, const FbdCursor &cursor, QString *error)
{
    std::vector<quint64> ids;
    if (cursor.network < 0 || cursor.network >= int(document.networks.size())) {
        *error = QCoreApplication::translate("iec::editors::fbd::FbdEdits", "There is nothing to copy here.");
        return {};
    }
    const FbdNetwork &network = document.networks[std::size_t(cursor.network)];
    const FbdCursor at = normalized(document, cursor);
    if (cursor.kind == Kind::Network) {
        ids = network.members;
    } else if (at.kind == Kind::Box) {
        ids = branchOf(document, network, at.element);
    } else if (at.kind == Kind::Input) {
        if (const auto source = sourceOf(document, at.element, at.pin))
            ids = branchOf(document, network, source->element);
    }
    if (ids.empty()) {
        *error = QCoreApplication::translate("iec::editors::fbd::FbdEdits", "Select a network, a box or an input to copy.");
        return {};
    }
    std::vector<Element> fragment;
    for (const Element &e : document.elements)
        if (std::ranges::find(ids, header(e).localId) != ids.end())
            fragment.push_back(e);
    // Wires to elements outside the copy are dropped.
    for (Element &e : fragment)
        for (ConnectionPointIn *point : inputPoints(e))
            std::erase_if(point->connections, [&](const Connection &c) { return std::ranges::find(ids, c.refLocalId) == ids.end(); });
    return fragment;
}

FbdEditResult pasteFragment(FbdDocument &document, const FbdCursor &cursor, std::vector<Element> fragment)
{
    if (fragment.empty())
        return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "There is nothing to paste."));
    const bool fbdOnly = std::ranges::all_of(fragment, [](const Element &e) {
        return isNode(e) || isSink(e) || std::holds_alternative<Label>(e) || std::holds_alternative<Comment>(e);
    });
    if (!fbdOnly)
        return refuse(QT_TRANSLATE_NOOP("iec::editors::fbd::FbdEdits", "The clipboard holds elements of another language (not a function block diagram): nothing was pasted."));
    // Fresh ids above the document's, wires inside the fragment following them.
    std::unordered_map<quint64, quint64> ids;
    quint64 next = document.idFloor;
    for (Element &e : fragment)
        ids[header(e).localId] = ++next;
    for (Element &e : fragment) {
        header(e).localId = ids[header(e).localId];
        for (ConnectionPointIn *point : inputPoints(e)) {
            std::erase_if(point->connections, [&](const Connection &c) { return !ids.contains(c.refLocalId); });
            for (Connection &c : point->connections)
                c.refLocalId = ids[c.refLocalId];
        }
    }
    FbdDocument pasted = readFbd(fragment);
    const bool branch = pasted.networks.size() == 1 && !pasted.networks.front().freehand && pasted.networks.front().root
        && !pasted.networks.front().label
        && std::ranges::none_of(fragment, [&](const Element &e) {
               return isSink(e) && sourceOf(pasted, header(e).localId, 0) && sourceOf(pasted, header(e).localId, 0)->element == pasted.networks.front().root;
           });
    const auto addAll = [&](FbdNetwork &network) {
        for (Element &e : fragment) {
            network.members.push_back(header(e).localId);
            document.elements.push_back(std::move(e));
        }
        document.reindexFrom(document.elements.size() - fragment.size());
    };
    const FbdCursor at = normalized(document, cursor);
    if (branch && at.kind == Kind::Input && !checkNetwork(document, at.network, true)) {
        // On an input: the branch replaces what fed it.
        FbdNetwork &network = document.networks[std::size_t(at.network)];
        if (const auto source = sourceOf(document, at.element, at.pin))
            removeBranch(document, network, source->element);
        const quint64 root = pasted.networks.front().root;
        addAll(network);
        connectInput(document, at.element, at.pin, {root, 0});
        refreshRoot(document, network);
        return {{}, FbdCursor::at(Kind::Box, at.network, root)};
    }
    // Otherwise as networks of their own, after the cursor's.
    int insertAt = document.networks.empty() ? 0 : std::clamp(cursor.network + 1, 0, int(document.networks.size()));
    const int first = insertAt;
    for (FbdNetwork &piece : pasted.networks) {
        FbdNetwork network;
        network.label = piece.label;
        network.comment = piece.comment;
        network.root = piece.root;
        network.freehand = piece.freehand;
        for (quint64 id : piece.members) {
            const auto it = std::ranges::find_if(fragment, [&](const Element &e) { return header(e).localId == id; });
            if (it == fragment.end())
                continue;
            network.members.push_back(id);
            document.elements.push_back(std::move(*it));
            document.reindexFrom(document.elements.size() - 1);
        }
        document.networks.insert(document.networks.begin() + insertAt++, std::move(network));
    }
    return {{}, FbdCursor::atNetwork(first)};
}

} // namespace iec::editors::fbd
