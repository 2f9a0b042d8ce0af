#pragma once

#include "editors/fbd/fbddocument.h"

#include <QList>
#include <QPointF>
#include <QRectF>

#include <unordered_map>
#include <unordered_set>
#include <vector>

// Where everything of an FBD network goes: the tree laid out from its root leftwards (each
// input's branch to the left of its pin, branches stacked top to bottom, a box stretched so that
// every branch meets its pin on a straight line), the root's assignments, jumps and returns in a
// column on the right after a crossing line, assignments on inner outputs drawn on the wire.
// Everything sits on rows of 20 units, the pitch of a box's pins. Pure functions in file units
// (the editor draws 1:1); texts are measured from their characters.
namespace iec::editors::fbd {

namespace layout {
constexpr double kRow = 20;         // a variable's height, the pitch of box pins
constexpr double kLeft = 60;        // where the leftmost element of a network starts
constexpr double kGap = 30;         // the wire from a branch to the pin it feeds
constexpr double kCrossing = 20;    // from the root's output to the crossing line of its outputs
constexpr double kHeaderLine = 16;  // a label or comment line above the tree
constexpr double kNetworkPad = 10;  // above and below the tree, inside the network
constexpr double kMinWidth = 400;   // the band of a network is at least this wide
} // namespace layout

// Where the cursor stands (seed 002 §2, table 1): on a network (its number), a text (a variable,
// an assignment, an instance name, a jump's label: position 1), an input of a box (2), a box (3),
// an output (4), the crossing in front of an assignment, jump or return (5 and 7), or the last
// position of a network (6).
struct FbdCursor {
    enum class Kind { Network, Text, Input, Box, Output, Crossing, End };

    Kind kind = Kind::Network;
    int network = 0;
    quint64 element = 0; // Text, Input, Box, Output: the element; Crossing: the sink
    int pin = 0;         // Input: the box's input pin; Output: the output pin

    static FbdCursor atNetwork(int network) { return {Kind::Network, network, 0, 0}; }
    static FbdCursor at(Kind kind, int network, quint64 element = 0, int pin = 0) { return {kind, network, element, pin}; }
    bool operator==(const FbdCursor &) const = default;
};

// A place the cursor can stand, and the rectangle it draws there.
struct CursorSpot {
    FbdCursor cursor;
    QRectF rect;
};

// One wire as the layout draws it, from an output to an input.
struct FbdWire {
    quint64 source = 0;
    int sourcePin = 0;
    quint64 target = 0;
    int targetPin = 0;
    QList<QPointF> points; // first the output, last the input; orthogonal
};

// The layout of one network, in body coordinates.
struct FbdGeometry {
    double top = 0;
    double height = 0;
    double width = 0; // the right edge of the drawing
    std::unordered_map<quint64, QRectF> rects;           // every placed element
    std::unordered_map<quint64, std::vector<int>> inputRows;  // a box's input pins: their rows
    std::unordered_map<quint64, std::vector<int>> outputRows; // a box's outputs: their rows
    std::vector<FbdWire> wires;
    std::unordered_set<quint64> onWire; // assignments drawn on the wire between two boxes (framed)
    std::vector<CursorSpot> spots;
    QRectF labelRect;
    QRectF commentRect;
    QPointF end; // the network's last position
};

// Lays out network `index` with its top at `top` (a freehand network keeps its drawing and is
// moved down to `top` as a whole).
FbdGeometry layoutNetwork(const FbdDocument &document, std::size_t index, double top);
// Every network, stacked from y = 0.
std::vector<FbdGeometry> layoutFbd(const FbdDocument &document);
// The layout of a network moved down by dy.
FbdGeometry shifted(FbdGeometry g, double dy);
// The layout of a network that is now network `index` (its cursor spots say so).
void renumber(FbdGeometry &g, int index);

} // namespace iec::editors::fbd
