#pragma once

#include "model/body.h"

namespace iec::model {

// CODESYS and TwinCAT write every LD/FBD/SFC position as (0,0). When every element of a graphical
// body sits at the origin, this computes a readable layout (the editors refine it later) and sets
// Body::layoutGenerated:
//  - SFC: top-down rows by distance from the initial steps, branches side by side, action
//    blocks to the right of their step, condition inputs to the left of their transition;
//  - FBD/LD: data-flow columns from left to right, one network (connected group) below the other.
// Returns whether it changed the body.
bool generateLayoutIfUnplaced(Body &body);

} // namespace iec::model
