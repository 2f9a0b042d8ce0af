#pragma once

#include "editors/fbd/fbdedits.h"

#include <optional>

// What the FBD edits (fbdedits.cpp) and the clipboard (fbdclipboard.cpp) share. Not for the editor.
namespace iec::editors::fbd::detail {

// A refusal; `text` is marked with QT_TRANSLATE_NOOP in the FbdEdits context.
FbdEditResult refuse(const char *text);
// Why the network cannot be edited (there is none; `structural` edits of a freehand one).
std::optional<QString> checkNetwork(const FbdDocument &document, int index, bool structural);
// The place a text cursor stands for: the input a variable feeds, the crossing of an assignment...
FbdCursor normalized(const FbdDocument &document, const FbdCursor &cursor);
// The network's root again after its wires changed.
void refreshRoot(FbdDocument &document, FbdNetwork &network);
// Removes a node and everything that feeds it.
void removeBranch(FbdDocument &document, FbdNetwork &network, quint64 node);

} // namespace iec::editors::fbd::detail
