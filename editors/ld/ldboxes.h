#pragma once

#include "editors/ld/ldedits.h"
#include "model/project.h"

#include <optional>

// What a box in a rung looks like: its pins from the standard library (the CODESYS V2.3 set the
// editors offer) or from the project's own POU, and which pins carry the rung: a function
// block's first BOOL input and output (TON's IN and Q, CTU's CU and Q), a logic function's first
// input and its output (AND, OR, XOR, NOT); everything else (and every "box with EN") runs on
// EN/ENO.
namespace iec::editors::ld {

std::optional<BoxSpec> boxSpecFor(const model::Project &project, const QString &typeName, bool withEn, QString *error);

} // namespace iec::editors::ld
