#pragma once

#include "editors/ld/ldnetwork.h"

#include <optional>

// Small operations on rung trees shared by the edits: finding nodes, and keeping a rung in its
// normal form (series in series and parallels in parallels flattened, no empty or one-branch
// parallels).
namespace iec::editors::ld::tree {

RungNode *nodeAt(RungNode &root, const std::vector<int> &path);
const RungNode *nodeAt(const RungNode &root, const std::vector<int> &path);

// Brings the rung back to its normal form.
void normalize(RungNode &rung);

// The series that holds the element and its index there.
struct Place {
    std::vector<int> seriesPath;
    int index = 0;
};
std::optional<Place> placeOf(const RungNode &rung, quint64 localId);

// The children of the main series from which on everything is an output (coils, jumps ...,
// or branches that all end in one): the rung's output group.
int outputTail(const LadderDocument &document, const RungNode &rung);
bool endsInOutput(const LadderDocument &document, const RungNode &node);

} // namespace iec::editors::ld::tree
