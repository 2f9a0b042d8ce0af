#pragma once

#include "editors/sfc/sfcstructure.h"

// Placing what an edit changed in a chart that keeps its positions (the automatic layout is in
// sfclayout.h).
namespace iec::editors::sfc {

// Whether a level's elements carry no positions of their own (every one at the origin, as CODESYS
// writes them): such a chart is laid out automatically after every edit.
bool isUnplaced(const std::vector<model::Element> &elements);

// After an edit (`before` as it was, `after` edited and wired): every element that was there
// keeps its position and only what the edit added or changed is placed. New nodes go below the
// node above them on its axis and the nodes below in that column move down as far as needed; a
// new branch goes right of the widest drawing of the branch before it and later branches move
// right; a deletion closes its gap in the edited column only; a block that dissolves puts its
// remaining branch back on the chain's axis. Wires whose ends kept their places keep their
// corners. A chart without positions (or `before` empty) gets the automatic layout instead.
void placeEdit(const ChartDocument &before, ChartDocument &after);

} // namespace iec::editors::sfc
