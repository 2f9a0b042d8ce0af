#pragma once

#include "editors/common/boxspec.h"
#include "editors/fbd/fbdlayout.h"

#include <QString>

// The commands of the FBD editor (RunPro / CoDeSys 2.3, seed 002 §2, commands (1)–(8)) as pure
// functions on an FbdDocument. Each acts at the cursor (one of the positions of table 1), keeps
// every network a tree, and says where the cursor goes next, or refuses with a message the user
// reads. The editor then writes the document back (writeFbd) and pushes the elements as one undo
// step.
namespace iec::editors::fbd {

struct FbdEditResult {
    QString error; // empty: done
    FbdCursor cursor;

    [[nodiscard]] bool ok() const { return error.isEmpty(); }
};

// ---- networks
// A new network `??? → ???` (an input assigned to an output) before or after the cursor's.
FbdEditResult insertNetwork(FbdDocument &document, const FbdCursor &cursor, bool after);
FbdEditResult setNetworkLabel(FbdDocument &document, int network, const QString &label);
FbdEditResult setNetworkComment(FbdDocument &document, int network, const QString &comment);

// ---- (1) Input: one more input on an extensible box (ADD, MUL, AND, OR, XOR, MAX, MIN, CONCAT,
// MUX), reading "???": before the selected input, or last when the box is selected.
FbdEditResult insertInput(FbdDocument &document, const FbdCursor &cursor);
// ---- (2) Output: one more assignment on the output (or next to the selected assignment).
FbdEditResult insertOutput(FbdDocument &document, const FbdCursor &cursor);
// ---- (3) Operator: before a selected input, after a selected output, replacing a selected box
// (its wires kept, the extra ones dropped), before a selected assignment, jump or return, or at
// the end of the network. Its free inputs read "???".
FbdEditResult insertOperator(FbdDocument &document, const FbdCursor &cursor, const BoxSpec &spec);
// ---- (4)–(6) Assignment, jump, return: before an input, after an output, before the crossing of
// an assignment, at the end of the network.
FbdEditResult insertAssignment(FbdDocument &document, const FbdCursor &cursor);
FbdEditResult insertJump(FbdDocument &document, const FbdCursor &cursor, const QString &label);
FbdEditResult insertReturn(FbdDocument &document, const FbdCursor &cursor);
// ---- (7) Negate an input, an output, an assignment, a jump or a return (again: not negated).
FbdEditResult toggleNegation(FbdDocument &document, const FbdCursor &cursor);
// ---- (8) Set/Reset on an assignment: normal → S → R → normal.
FbdEditResult cycleSetReset(FbdDocument &document, const FbdCursor &cursor);
// Edge detection on an input: normal → rising → falling → normal.
FbdEditResult cycleEdge(FbdDocument &document, const FbdCursor &cursor);

// ---- texts
// A variable's or assignment's expression, a box's instance name, a jump's label.
FbdEditResult setElementText(FbdDocument &document, quint64 localId, const QString &text);
// The text setElementText would change ("" when the element has none).
QString elementText(const FbdDocument &document, quint64 localId);

// ---- delete, copy, paste
FbdEditResult deleteAtCursor(FbdDocument &document, const FbdCursor &cursor);
// What Copy takes: the network at the cursor, or the branch at a box, an input or a variable
// (the box and everything that feeds it).
std::vector<model::Element> copyAtCursor(const FbdDocument &document, const FbdCursor &cursor, QString *error);
// A branch goes on the selected input (replacing what fed it: cut an input and paste it on
// another to move a branch); networks go after the cursor's network. `fragment` may reuse ids:
// it is renumbered above the document's.
FbdEditResult pasteFragment(FbdDocument &document, const FbdCursor &cursor, std::vector<model::Element> fragment);

// ---- the cursor
// The cursor moved by an arrow key to the nearest position in that direction.
FbdCursor moveCursor(const std::vector<FbdGeometry> &layout, const FbdCursor &cursor, int dx, int dy);
// The position a click at `point` selects (the smallest one under it; else the network there).
std::optional<FbdCursor> cursorAt(const std::vector<FbdGeometry> &layout, QPointF point);
// A cursor that still exists in `document` (after an undo changed it).
FbdCursor validCursor(const FbdDocument &document, const FbdCursor &cursor);
// Where the cursor is drawn, if it stands anywhere.
std::optional<QRectF> cursorRect(const std::vector<FbdGeometry> &layout, const FbdCursor &cursor);

} // namespace iec::editors::fbd
