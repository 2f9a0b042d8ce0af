#pragma once

#include "editors/fbd/fbdlayout.h"

// Writing the networks back into the elements, so that the PLCopen file says what the editor
// shows: every element of a tree gets the position and size the layout gives it, every pin and
// wire its place, and the file lists the networks in order, each tree from its inputs to its
// outputs (the order tools that run an unplaced body in file order use). A freehand network keeps
// its drawing and moves as a whole. Beremiz and OpenPLC then draw the same networks.
namespace iec::editors::fbd {

// Lays out and writes every network, stacked from the top.
void writeFbd(FbdDocument &document);

} // namespace iec::editors::fbd
