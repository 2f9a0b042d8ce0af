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

// The same after an edit of `before` (whose layout is `beforeLayout`): a network the edit did not
// touch, written already, keeps its layout and only moves (its elements' positions shift), so a
// command in a long body lays out only what it changed. (The scene lays the result out again,
// reusing the same unchanged networks, so no layout is returned.)
void writeLadder(LadderDocument &document, const LadderDocument &before, const std::vector<NetworkGeometry> &beforeLayout);

// The layout of a network moved down by dy.
NetworkGeometry shifted(NetworkGeometry g, double dy);

} // namespace iec::editors::ld
