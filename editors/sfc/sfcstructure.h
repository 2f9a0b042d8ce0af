#pragma once

#include "model/body.h"
#include "model/element.h"

#include <QString>

#include <optional>
#include <vector>

// The structure of an SFC chart, read from the elements of its body and written back to them.
// Editing works on this tree (steps and transitions alternate; divergences hold branches side by
// side; a chain ends in a jump), which keeps every edit valid by construction. Pure functions, no
// Qt widgets: tested as tables.
namespace iec::editors::sfc {

enum class NodeKind { Step, MacroStep, Transition, Jump, Selection, Parallel };

struct Node;
using Sequence = std::vector<Node>;

struct Node {
    NodeKind kind = NodeKind::Step;
    quint64 localId = 0;       // the step, transition, jump or divergence element
    quint64 convergenceId = 0; // branches: the convergence (0 when every branch ends in a jump)
    std::vector<Sequence> branches;
    // A wire back to a step drawn by another tool (no jump element yet): the step's localId.
    // (CODESYS numbers from 0, so 0 is a real localId and `wired` says what this is.)
    bool wired = false;
    quint64 wiredTarget = 0;

    bool operator==(const Node &) const = default;
};

struct Chart {
    Sequence main;               // starts at the initial step
    std::vector<Sequence> loose; // chains not reachable from it, kept as they are

    [[nodiscard]] bool isEmpty() const { return main.empty() && loose.empty(); }
    bool operator==(const Chart &) const = default;
};

// Steps, macro steps and parallel blocks sit between transitions; transitions and alternative
// blocks sit between steps. A jump ends a chain after a transition.
enum class Role { StepLike, TransitionLike, Jump };
Role roleOf(NodeKind kind);

// A chart's elements (the pool, in file order) with the structure read from them.
struct ChartDocument {
    std::vector<model::Element> elements;
    Chart chart;
    // Never below the largest localId this document has held, so an edit that removes an element
    // and adds another does not hand out the removed one's id (undo relies on ids being distinct).
    quint64 idFloor = 0;

    [[nodiscard]] const model::Element *element(quint64 localId) const;
    model::Element *element(quint64 localId);
    [[nodiscard]] quint64 allocateId(); // one more than the largest localId in use
    quint64 add(model::Element element); // gives it a fresh localId and appends it
    void remove(const std::vector<quint64> &localIds);
    // The action block wired to a step, 0 when it has none.
    [[nodiscard]] quint64 actionBlockOf(quint64 stepId) const;
    [[nodiscard]] QString stepName(quint64 localId) const;
    [[nodiscard]] std::optional<quint64> stepNamed(const QString &name) const;
};

Chart parseChart(const std::vector<model::Element> &elements);
ChartDocument readChart(std::vector<model::Element> elements);

// Rewrites the wires of every structural element from the tree: each element's input is the
// element before it, divergences and convergences get one pin per branch, missing convergences
// are created and jumps replace wires back to a step. Other elements keep their wires.
void wireChart(ChartDocument &document);

// Every localId a node stands for (with everything inside its branches and the action blocks of
// its steps).
std::vector<quint64> elementsOf(const ChartDocument &document, const Node &node);

// The network wired into a transition's condition (variables, blocks, contacts, rails: every
// element that feeds it, up to the chart's own elements), which belongs to the transition.
std::vector<quint64> conditionNetwork(const ChartDocument &document, quint64 transitionId);

// Where a node sits: the sequence holding it and its index there.
struct NodePlace {
    Sequence *sequence = nullptr;
    std::size_t index = 0;
    Node *parent = nullptr; // the branch node whose branch `sequence` is; nullptr at top level
    bool isMain = false;
};
std::optional<NodePlace> findNode(Chart &chart, quint64 localId);

} // namespace iec::editors::sfc
