#pragma once

#include "editors/common/elementpool.h"
#include "model/body.h"
#include "model/element.h"

#include <QString>

#include <optional>
#include <vector>

// The structure of a function block diagram, read from the elements of an FBD body. PLCopen keeps
// an FBD body as a graph of boxes and variables; the editor works on networks (CoDeSys
// "Netzwerk", RunPro "节", seed 002 §2), each a tree: variables and boxes feed the inputs of the
// boxes to their right, and the result of the tree's last node (its root) goes to assignments,
// a jump or a return. An inner box's output may carry assignments of its own. Pure functions, no
// widgets: tested as tables.
namespace iec::editors::fbd {

// An output of an element: a box's output variable (by index), or a variable's only output (0).
struct Port {
    quint64 element = 0;
    int pin = 0;

    bool operator==(const Port &) const = default;
};

// One network.
struct FbdNetwork {
    std::vector<quint64> members; // every element of the network, in file order
    quint64 label = 0;            // a Label element: the network's jump label
    quint64 comment = 0;          // a Comment element
    quint64 root = 0;             // the tree's last node (a box or a variable), 0 when there is none
    // Not a tree (a box output feeding two boxes, a loop, connectors): shown as drawn and edited
    // element by element.
    bool freehand = false;

    bool operator==(const FbdNetwork &) const = default;
};

// An FBD body's elements (the pool, in file order) with the networks read from them.
struct FbdDocument : ElementPool {
    std::vector<FbdNetwork> networks;
    // Elements no network draws (CODESYS's "FBD implementation attributes" vendor element): kept
    // where they are in the file.
    std::vector<quint64> unshown;

    // Removes the elements, the wires from them and their places in the networks.
    void remove(const std::vector<quint64> &localIds);
    // The network an element belongs to, -1 for none.
    [[nodiscard]] int networkOf(quint64 localId) const;
};

// Reads the networks of an FBD body: each group of wired elements is a network (a label or a
// comment belongs to the network after it), ordered top to bottom, or in file order when
// `layoutGenerated` (CODESYS writes every position as 0,0).
FbdDocument readFbd(std::vector<model::Element> elements, bool layoutGenerated = false);

// Networks deeper than this are shown as drawn (freehand): the layout recurses along the tree.
inline constexpr int kMaxTreeDepth = 200;

// ---- what an element is in a tree
// A node computes a value: a box, an input variable (an in-out variable too).
bool isNode(const model::Element &element);
// A sink ends a branch: an assignment (output variable), a jump, a return.
bool isSink(const model::Element &element);
// The input pins: a box's input then in-out variables; a sink's or in-out variable's one input.
int inputCount(const model::Element &element);
const model::ConnectionPointIn *inputPoint(const model::Element &element, int pin);
model::ConnectionPointIn *inputPoint(model::Element &element, int pin);
// The name of an input pin (a box's formal parameter; empty otherwise).
QString inputName(const model::Element &element, int pin);
int outputCount(const model::Element &element);
// The source wired to an input pin (its first connection), if any.
std::optional<Port> sourceOf(const FbdDocument &document, quint64 element, int pin);
// Wires the input pin to `source` (replacing what it was wired to).
void connectInput(FbdDocument &document, quint64 element, int pin, Port source);
// Who reads an output, within a network: the nodes (element, input pin) and the sinks.
struct Readers {
    std::vector<std::pair<quint64, int>> nodes;
    std::vector<quint64> sinks;
};
Readers readersOf(const FbdDocument &document, const FbdNetwork &network, Port output);
// The input pin of `target` that reads `output`, -1 when none does.
int pinReading(const FbdDocument &document, quint64 target, Port output);
// A node and everything that feeds it, with the sinks on their outputs (not the sinks on the
// node's own output that leads to its reader), in file order.
std::vector<quint64> branchOf(const FbdDocument &document, const FbdNetwork &network, quint64 node);

} // namespace iec::editors::fbd
