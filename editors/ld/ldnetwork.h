#pragma once

#include "editors/common/elementpool.h"
#include "model/body.h"
#include "model/element.h"

#include <QHash>
#include <QString>

#include <unordered_map>
#include <vector>

// The structure of a ladder diagram, read from the elements of an LD body and written back to
// them. PLCopen keeps an LD body as a graph (contacts, coils and boxes wired to each other and to
// power rails); the editor works on networks (CODESYS "Netzwerk", RunPro "节"), each a rung whose
// power flow from the left rail to the outputs is a series-parallel tree. Pure functions, no
// widgets: tested as tables.
namespace iec::editors::ld {

// One node of a rung's power flow.
struct RungNode {
    enum class Kind { Element, Series, Parallel };

    Kind kind = Kind::Series;
    quint64 localId = 0;            // Element: a contact, coil, box, jump, return or assignment
    std::vector<RungNode> children; // Series: left to right; Parallel: the branches, top to bottom

    static RungNode element(quint64 localId) { return {Kind::Element, localId, {}}; }
    static RungNode series(std::vector<RungNode> children = {}) { return {Kind::Series, 0, std::move(children)}; }
    static RungNode parallel(std::vector<RungNode> branches) { return {Kind::Parallel, 0, std::move(branches)}; }

    [[nodiscard]] bool isElement() const { return kind == Kind::Element; }
    bool operator==(const RungNode &) const = default;
};

// One network: its rung and the elements that belong to it.
struct LdNetwork {
    std::vector<quint64> members; // every element of the network, in file order
    quint64 leftRail = 0;         // 0: none yet (written when the network is laid out)
    quint64 rightRail = 0;
    quint64 label = 0;            // a Label element: the network's jump label
    quint64 comment = 0;          // a Comment element: the network's comment
    quint64 title = 0;            // CODESYS's network title (a vendor element), kept as it is
    RungNode rung = RungNode::series(); // a Series; empty for an empty network
    // Not a rung (a graph drawn freehand by another tool, a box fed by two rungs, a loop): the
    // network is shown as drawn and edited element by element; `rung` is empty.
    bool freehand = false;

    bool operator==(const LdNetwork &) const = default;
};

// The pins by which a box sits in the rung: the input the power flows into and the output it
// flows out of (EN/ENO, or a function block's BOOL pins such as TON's IN and Q). -1 when the box
// has none of that kind (a box at the end of a rung may feed nothing).
struct RungPins {
    int input = -1;  // index into Block::inputVariables
    int output = -1; // index into Block::outputVariables

    bool operator==(const RungPins &) const = default;
};

// An LD body's elements (the pool, in file order) with the networks read from them.
struct LadderDocument : ElementPool {
    std::vector<LdNetwork> networks;

    // Removes the elements, the wires from them and their places in the networks.
    void remove(const std::vector<quint64> &localIds);
    // The network an element belongs to, -1 for none.
    [[nodiscard]] int networkOf(quint64 localId) const;
    // The rung pins of every box in a rung (read from its wires, or set by the edit that made it).
    std::unordered_map<quint64, RungPins> boxPins;
    [[nodiscard]] RungPins pinsOf(quint64 boxId) const;
};

// Our own addData on the rails of a network the editor laid out: such a rail belongs to one
// network, so the rung's branches that meet only at the rail are one network. Rails without it
// may be shared by several networks (Beremiz draws one left rail for all, CODESYS writes one).
inline const QString kNetworkRailMarker = QStringLiteral("https://iec-studio.org/ld-network");
bool isNetworkRail(const model::Element &element);
void markNetworkRail(model::Element &element);

// Reads the networks of an LD body. `layoutGenerated` (the positions were made up on import,
// CODESYS writes none) orders networks by file order instead of by position.
LadderDocument readLadder(std::vector<model::Element> elements, bool layoutGenerated = false);

// What a rung element is, for the layout and the edits.
enum class RungRole { Contact, Coil, Box, Jump, Return, Assignment, Other };
RungRole rungRole(const model::Element &element);
// Outputs end a rung on the right (coils, jumps, returns, assignments); contacts and boxes do
// not.
bool isOutput(const model::Element &element);

// Every localId in the node, left to right and top to bottom.
void collectElements(const RungNode &node, std::vector<quint64> &out);
std::vector<quint64> rungElements(const RungNode &node);

} // namespace iec::editors::ld
