#pragma once

#include "editors/sfc/sfcstructure.h"

// The automatic layout of a chart (CODESYS 2.3 style): each chain in a column, steps and
// transitions one below the other, the branches of a divergence side by side to the right of
// the first one, action blocks right of their steps, transition conditions right of their bars.
// Nothing overlaps and no wire crosses another: loops are drawn as jumps. Writes positions,
// sizes, pin positions and wire waypoints into the elements, so other tools draw the same picture.
namespace iec::editors::sfc {

void layoutChart(ChartDocument &document);

} // namespace iec::editors::sfc
