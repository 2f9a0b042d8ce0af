#pragma once

#include "interpreter/compiler/diagnostics.h"

#include "model/element.h"

#include <QHash>
#include <QString>

#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

// The wiring of an LD or FBD body as a graph of element indices: who reads whom, how many
// readers each output has, the loops broken at feedback variables, and the order in which the
// elements with an effect (coils, outputs, blocks, jumps, returns, labels) run.
namespace iec::interp::graphical {

enum class NodeKind {
    Ignored,      // comments, vendor elements without pins
    LeftRail,
    RightRail,
    Contact,
    Coil,
    InVariable,
    OutVariable,
    InOutVariable,
    Block,
    Connector,
    Continuation,
    Jump,
    Return,
    Label,
    Foreign,      // SFC elements and action blocks: not part of a network
    Unsupported,  // vendor elements with pins, error elements
};

struct Node {
    const model::Element *element = nullptr;
    NodeKind kind = NodeKind::Ignored;
    quint64 localId = 0;
    std::size_t fileIndex = 0;
    std::vector<std::size_t> sources; // elements wired to any input (continuations: their connector)
};

class Network
{
public:
    // Diagnoses duplicate localIds and continuations without a connector under `owner`.
    Network(const std::vector<model::Element> &elements, const QString &owner, Diagnostics &diagnostics);

    const std::vector<Node> &nodes() const { return m_nodes; }
    const Node &node(std::size_t index) const { return m_nodes[index]; }
    std::optional<std::size_t> indexOf(quint64 localId) const;
    std::optional<std::size_t> connectorOf(std::size_t continuation) const;

    // The output a wire names: the upper-case pin of a block (its only output when the wire names
    // none), empty for elements with one output.
    QString outputKey(std::size_t source, const std::optional<QString> &formalParameter) const;
    // How many wires read that output (right rails do not count: they do nothing).
    int readers(std::size_t source, const QString &key) const;

    // Finds every loop of wires; a loop through an in-out variable reads that variable's value
    // from before (feedback), so does a loop through a function block instance. A loop through
    // functions whose boxes all carry an execution order (CFC, as CODESYS allows it) is broken
    // where a box runs before the box it reads: that box keeps its output from one scan to the
    // next (isStoredBox). Any other loop is an error. Returns false after diagnosing one.
    bool breakLoops(const QString &owner, Diagnostics &diagnostics);
    bool isFeedback(std::size_t consumer, std::size_t source) const { return m_feedback.contains({consumer, source}); }
    // A function box whose outputs a loop reads from the scan before (breakLoops).
    bool isStoredBox(std::size_t node) const { return m_storedBoxes.contains(node); }
    // A block that calls a function block instance (its outputs persist between scans).
    bool isInstanceBlock(std::size_t node) const;

    // The elements with an effect, in execution order: by executionOrderId where given, else
    // network by network (top to bottom; file order when the importer generated the layout) and
    // left to right, top to bottom inside a network.
    std::vector<std::size_t> rootOrder(bool layoutGenerated) const;

    bool ok() const { return m_ok; }

private:
    std::optional<std::vector<std::size_t>> findCycle() const;
    // The function box of an ordered loop that keeps its output (see breakLoops); end() if none.
    std::vector<std::size_t>::const_iterator orderedLoopBreak(const std::vector<std::size_t> &cycle) const;

    std::vector<Node> m_nodes;
    QHash<quint64, std::size_t> m_index;
    std::map<std::size_t, std::size_t> m_connectorOf;
    std::map<std::pair<std::size_t, QString>, int> m_readers;
    std::set<std::pair<std::size_t, std::size_t>> m_feedback;
    std::set<std::size_t> m_storedBoxes;
    bool m_ok = true;
};

} // namespace iec::interp::graphical
