#pragma once

#include "editors/sfc/sfcstructure.h"

#include <QPointF>

// The automatic layout of a chart (CODESYS 2.3 style): each chain in a column, steps and
// transitions one below the other, the branches of a divergence side by side to the right of
// the first one, action blocks right of their steps, transition conditions right of their bars.
// Nothing overlaps (the condition texts included) and no wire crosses another: loops are drawn
// as jumps. Writes positions, sizes, pin positions and wire waypoints into the elements, so other
// tools draw the same picture.
namespace iec::editors::sfc {

void layoutChart(ChartDocument &document);

// The pieces the layout is made of, for placing what an edit adds to a chart that keeps its
// positions (sfcplacement.h).
struct Extent {
    double left = 0;  // from the chain's axis to its leftmost drawing
    double right = 0; // from the axis to the rightmost drawing (texts and action blocks included)
    double height = 0;
};
Extent measureNode(const ChartDocument &document, const Node &node);
Extent measureSequence(const ChartDocument &document, const Sequence &sequence);
// Places a node and everything inside it as the layout does: its axis at x = `axis`, its top at `top`.
void placeNode(ChartDocument &document, Node &node, double axis, double top);
// Puts a step's action block with its top left corner at `topLeft`, sized for its actions.
void placeActionBlock(ChartDocument &document, quint64 stepId, QPointF topLeft);

} // namespace iec::editors::sfc
