#pragma once

#include "editors/common/textmetrics.h"
#include "editors/ld/ldnetwork.h"

#include <QList>
#include <QPointF>
#include <QRectF>

#include <unordered_map>
#include <vector>

// Where everything of a ladder network goes: the automatic layout of a rung (contacts in series
// left to right, parallel branches below with their vertical links, outputs at the right rail,
// boxes inline with their variables on the side pins). Pure functions in file units (the editor
// draws 1:1); text widths are estimated from the characters, so the same body always gives the
// same positions on every machine.
namespace iec::editors::ld {

namespace geometry {
constexpr double kRailX = 50;          // the left rail's line; network numbers sit left of it
constexpr double kRailWidth = 3;
constexpr double kWire = 20;           // the shortest wire between two rung elements
constexpr double kSymbolWidth = 30;    // contact and coil symbols
constexpr double kSymbolHeight = 20;
constexpr double kNameHeight = 16;     // the variable's name above a contact, coil or box
constexpr double kCellPad = 6;         // room on each side of a name
constexpr double kBranchPad = 10;      // between a vertical link and a branch's first element
constexpr double kRowGap = 8;          // between parallel branches
constexpr double kPinPitch = 20;       // between a box's pins
constexpr double kBoxTitle = 20;       // a box's type name row
constexpr double kVariableHeight = 20; // a variable on a box's side pin
constexpr double kSideGap = 20;        // between a side variable and its pin
constexpr double kMinRungWidth = 440;  // from the left to the right rail
constexpr double kWidthStep = 80;      // right rails line up in steps of this
constexpr double kHeaderLine = 16;     // a label or comment line above the rung
constexpr double kNetworkPad = 10;     // above and below the rung, inside the network
} // namespace geometry

// textWidth, roundUp and boxWidth are shared (editors/common/textmetrics.h).
using editors::textWidth;
using editors::roundUp;

// A point on a rung's wire where the cursor can stand: between two elements of a series, or at
// its start or end. `path` leads from the rung (a Series) through child indices to a Series;
// `index` is the gap (0: before the first child, size: after the last).
struct WirePoint {
    std::vector<int> path;
    int index = 0;
    QPointF position;

    bool operator==(const WirePoint &other) const { return path == other.path && index == other.index; }
};

// One wire as the layout draws it, from the source's output pin to the target's input pin.
struct WireRun {
    quint64 source = 0;
    int sourcePin = 0;  // a box's output variable index, 0 otherwise
    quint64 target = 0;
    int targetPin = 0;  // a box's input variable index, 0 otherwise (right rail: 0)
    QList<QPointF> points; // first the source pin, last the target pin; orthogonal
};

// The layout of one network, in body coordinates.
struct NetworkGeometry {
    double top = 0;
    double height = 0;
    double rungTop = 0;            // where the rails start
    double rungHeight = 0;
    double rightRailX = 0;
    double lineY = 0;              // the rung's main line
    std::unordered_map<quint64, QRectF> rects; // every placed element: its position and size
    std::vector<WireRun> wires;    // rung wires (rails included) and side wires of boxes
    std::vector<WirePoint> wirePoints;
    QRectF labelRect;              // the label line, the comment lines (empty when absent)
    QRectF commentRect;
    double freehandShift = 0;      // a freehand network: how far its drawing moves down
};

// Lays out network `index` of the document with its top at `top` (rungs only: a freehand network
// keeps its drawing and is only measured). Names come from the elements.
NetworkGeometry layoutNetwork(const LadderDocument &document, std::size_t index, double top);

// The layout of every network, stacked from y = 0.
std::vector<NetworkGeometry> layoutLadder(const LadderDocument &document);

// Pin positions relative to an element's position, as the layout places them (written into the
// connection points so other tools draw the wires where the editor does).
QPointF inputPinOffset(const model::Element &element, int pin, const RungPins &rungPins);
QPointF outputPinOffset(const model::Element &element, int pin, const RungPins &rungPins);
// A box's pin rows: the rung pins first, the others in declaration order.
int boxInputRow(const model::Block &block, int pin, const RungPins &rungPins);
int boxOutputRow(const model::Block &block, int pin, const RungPins &rungPins);
QSizeF boxSize(const model::Block &block);

} // namespace iec::editors::ld
