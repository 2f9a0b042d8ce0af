#pragma once

#include "editors/ld/ldgeometry.h"
#include "editors/ld/ldnetwork.h"

// Writing the networks back into the elements, so that the PLCopen file says what the editor
// shows: each rung network gets a left and a right rail of its own, every rung element its wires
// from the tree (rung order is file order too), and every element, pin and wire the position the
// layout gives it; a freehand network keeps its drawing and moves as a whole. Other tools
// (Beremiz, OpenPLC) then draw the same rungs, and the interpreter runs networks top to bottom.
namespace iec::editors::ld {

// Lays out and writes every network, stacked from the top. Returns the layouts.
std::vector<NetworkGeometry> writeLadder(LadderDocument &document);

} // namespace iec::editors::ld
