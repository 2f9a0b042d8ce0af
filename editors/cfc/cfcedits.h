#pragma once

#include "editors/common/editoutcome.h"
#include "model/element.h"

#include <QPointF>
#include <QString>

#include <optional>
#include <vector>

// The edits of a CFC body, as pure functions of its elements (the editor runs them on a copy and
// pushes the result as one command). Elements that run carry an execution-order number; the
// numbers are always 1..n without gaps, and a new element runs last.
namespace iec::editors::cfc {

// Whether an element takes part in the execution order (boxes, outputs, in-outs, jumps, returns
// and labels; inputs, connection marks and comments are read where they are used).
[[nodiscard]] bool runsInOrder(const model::Element &element);

// Places `element` with its top left at `at` under a fresh localId (the largest in use + 1), last in
// the order when it runs; selects it.
EditOutcome insertElement(std::vector<model::Element> &elements, model::Element element, QPointF at);
// Places pasted elements (already renumbered to free ids) moved so that their top left is at `at`,
// after the others in the order, keeping their order among themselves.
EditOutcome insertElements(std::vector<model::Element> &elements, std::vector<model::Element> pasted, QPointF at);
// Removes the elements and every wire from them; the order closes up.
EditOutcome deleteElements(std::vector<model::Element> &elements, const std::vector<quint64> &localIds);
// Moves elements to new positions (top left corners).
EditOutcome moveElements(std::vector<model::Element> &elements, const std::vector<quint64> &localIds,
    const std::vector<QPointF> &positions);
// Moves elements by a step (the arrow keys).
EditOutcome nudgeElements(std::vector<model::Element> &elements, const std::vector<quint64> &localIds, QPointF step);
// Wires output `formalParameter` of `source` to input `pin` of `target`, replacing what that input
// read before (an input reads one wire; an output feeds any number).
EditOutcome connectPins(std::vector<model::Element> &elements, quint64 source, const std::optional<QString> &formalParameter,
    quint64 target, int pin);
// Puts `fresh` (a box built for another type, or with EN/ENO added or taken away) in the place of
// box `localId`: position, order and instance name stay; each input keeps its wire when the new box
// has an input of that name, else the one at its place among the inputs other than EN; readers of
// outputs the new box does not have lose their wire.
EditOutcome replaceBlock(std::vector<model::Element> &elements, quint64 localId, model::Block fresh);

// ---- execution order
// By data flow: an element runs after the elements it reads (a feedback loop is cut where it
// closes, so the loop reads the value of the scan before), ties top to bottom, left to right.
EditOutcome orderByDataFlow(std::vector<model::Element> &elements);
// By topology: top to bottom, then left to right.
EditOutcome orderByTopology(std::vector<model::Element> &elements);
enum class OrderMove { Earlier, Later, ToFront, ToBack };
// Moves the selected elements that run one place earlier or later, or to the start or the end.
EditOutcome moveInOrder(std::vector<model::Element> &elements, const std::vector<quint64> &localIds, OrderMove move);
// Gives the element number `number` (1..n; the others shift to make room).
EditOutcome setOrderNumber(std::vector<model::Element> &elements, quint64 localId, int number);
// The elements that run, in their order (those without a number last, in file order).
[[nodiscard]] std::vector<quint64> executionOrder(const std::vector<model::Element> &elements);

} // namespace iec::editors::cfc
