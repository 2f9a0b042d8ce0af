#pragma once

#include "editors/common/boxspec.h"
#include "editors/ld/ldgeometry.h"
#include "editors/ld/ldnetwork.h"

#include <QStringList>

// The commands of the LD editor (RunPro / CoDeSys 2.3, seed 002 §1) as pure functions on a
// LadderDocument. Each acts at the cursor, keeps every rung a rung, and says where the cursor
// goes next, or refuses with a message the user reads. The editor then writes the document back
// (writeLadder) and pushes the elements as one undo step.
namespace iec::editors::ld {

// Where the user is: a network (its number was clicked), one or more elements (a shift-click
// range of contacts), or a point on a rung's wire between two elements.
struct LdCursor {
    enum class Kind { Network, Element, Wire };

    Kind kind = Kind::Network;
    int network = 0;
    std::vector<quint64> elements; // Element: the selected elements, the first one is "the" element
    WirePoint wire;                // Wire: the point (its path and gap index; the position is ignored)

    static LdCursor atNetwork(int network) { return {Kind::Network, network, {}, {}}; }
    static LdCursor atElement(int network, quint64 id) { return {Kind::Element, network, {id}, {}}; }
    static LdCursor atWire(int network, WirePoint point) { return {Kind::Wire, network, {}, std::move(point)}; }
    [[nodiscard]] quint64 element() const { return elements.empty() ? 0 : elements.front(); }
    bool operator==(const LdCursor &other) const
    {
        return kind == other.kind && network == other.network && elements == other.elements && wire == other.wire;
    }
};

struct LdEditResult {
    QString error; // empty: done
    LdCursor cursor;

    [[nodiscard]] bool ok() const { return error.isEmpty(); }
};

// BoxSpec, kPlaceholder and isExtensible are shared with FBD (editors/common/boxspec.h).

// ---- networks
LdEditResult insertNetwork(LadderDocument &document, const LdCursor &cursor, bool after);
LdEditResult setNetworkLabel(LadderDocument &document, int network, const QString &label);
LdEditResult setNetworkComment(LadderDocument &document, int network, const QString &comment);

// ---- rung elements
// A contact in series, left of the cursor (at a wire point: there; at a network: before its
// outputs).
LdEditResult insertContact(LadderDocument &document, const LdCursor &cursor);
// A contact in parallel around the selected elements (a range of one series): below, or above.
LdEditResult insertParallelContact(LadderDocument &document, const LdCursor &cursor, bool below = true);
// A coil at the right of the rung, parallel to the outputs there already (below the one at the
// cursor).
LdEditResult insertCoil(LadderDocument &document, const LdCursor &cursor);
LdEditResult insertJump(LadderDocument &document, const LdCursor &cursor, const QString &label);
LdEditResult insertReturn(LadderDocument &document, const LdCursor &cursor);
// A box in series at the cursor, like a contact; its other inputs read "???".
LdEditResult insertBox(LadderDocument &document, const LdCursor &cursor, const BoxSpec &spec);

// ---- at a box's pins (CoDeSys "insert at blocks")
// One more input on an extensible box (ADD, AND, MAX, CONCAT ...), reading "???".
LdEditResult insertBoxInput(LadderDocument &document, const LdCursor &cursor);
// An assignment ("???") on the box's first output that has none.
LdEditResult insertBoxAssignment(LadderDocument &document, const LdCursor &cursor);
// An operator box (the spec, AND by default) in front of the side input at the cursor: the
// variable there becomes its first input.
LdEditResult insertOperatorAtInput(LadderDocument &document, const LdCursor &cursor, const BoxSpec &spec);

// ---- properties
LdEditResult toggleNegation(LadderDocument &document, const LdCursor &cursor);
// A coil: normal → S → R → normal.
LdEditResult cycleSetReset(LadderDocument &document, const LdCursor &cursor);
// A contact or coil: normal → P (rising) → N (falling) → normal.
LdEditResult cycleEdge(LadderDocument &document, const LdCursor &cursor);
// The variable of a contact or coil, a box's instance, a jump's label, a side variable.
LdEditResult setElementText(LadderDocument &document, quint64 localId, const QString &text);
// The text setElementText would change ("" when the element has none).
QString elementText(const LadderDocument &document, quint64 localId);

// ---- delete, copy, paste
LdEditResult deleteAtCursor(LadderDocument &document, const LdCursor &cursor);
// What Copy takes: whole networks (cursor on a network) or the selected elements with the boxes'
// side variables. The elements are complete networks (rails included), so a paste reads them as
// it reads any body; a range of elements is marked as such.
std::vector<model::Element> copyAtCursor(const LadderDocument &document, const LdCursor &cursor, QString *error);
enum class PasteMode { After, Below, Above };
// Networks go after the cursor's network; a range of elements after the cursor (series), or
// parallel below or above it. `fragment` has fresh localIds already.
LdEditResult pasteFragment(LadderDocument &document, const LdCursor &cursor, std::vector<model::Element> fragment,
    PasteMode mode = PasteMode::After);

// ---- cursor helpers
// The path from the rung to an element's node (child indices), empty when it is not in a rung.
std::vector<int> pathOf(const RungNode &rung, quint64 localId);
// The cursor moved by an arrow key, using the network layouts (left/right along the rung through
// elements and wire points, up/down to the nearest element or network).
LdCursor moveCursor(const LadderDocument &document, const std::vector<NetworkGeometry> &layout, const LdCursor &cursor,
    int dx, int dy);
// A cursor that still exists in `document` (clamped after an undo changed it).
LdCursor validCursor(const LadderDocument &document, const LdCursor &cursor);

} // namespace iec::editors::ld
