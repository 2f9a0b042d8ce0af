#pragma once

#include "model/element.h"

#include <QHash>
#include <QList>
#include <QPointF>
#include <QRectF>
#include <QString>

#include <optional>
#include <vector>

// Where the elements of a CFC stand and how its wires run, from the elements alone (no items), so
// that the scene, the editor's hit tests and the tests agree.
namespace iec::editors::cfc {

inline constexpr double kCfcRow = 20;       // a variable's height, a box's pin pitch
inline constexpr double kWireClearance = 10; // kept between a wire and a box, and the pins' stubs

// The element's frame: its position and a size from its content (a box grows with its pins and
// names; a comment keeps the size the file gives it).
[[nodiscard]] QRectF cfcRect(const model::Element &element);
// Writes each element's drawn size into its width and height (a comment keeps the size it has), so
// that other tools (Beremiz reads a CFC as FBD) draw it as large as it is here. Only elements that
// are new, changed or without a size since `before` are measured (measuring text is what costs).
void writeCfcSizes(std::vector<model::Element> &elements, const std::vector<model::Element> &before);
// Pins in body coordinates: input `pin` (model::inputPoints order) and the output a connection's
// formalParameter names (the only one when empty). nullopt when there is no such pin.
[[nodiscard]] std::optional<QPointF> cfcInputPin(const model::Element &element, int pin);
[[nodiscard]] std::optional<QPointF> cfcOutputPin(const model::Element &element, const std::optional<QString> &formalParameter);

// One wire: from an output of `source` to input `pin` of `target`, its corners, and whether the
// router found no room for it (then it is the straight line between the pins, drawn red).
struct CfcWire {
    quint64 source = 0;
    std::optional<QString> formalParameter;
    quint64 target = 0;
    int pin = 0;
    QList<QPointF> points;
    bool broken = false;

    bool operator==(const CfcWire &) const = default;
};

// The frames of a body's elements by localId: what wires are routed around.
using CfcFrames = QHash<quint64, QRectF>;
[[nodiscard]] CfcFrames cfcFrames(const std::vector<model::Element> &elements);

// Routes a wire between two pins around the frames near them. Broken when there is no orthogonal
// way: the elements stand too close, or a stub runs into another element.
[[nodiscard]] CfcWire routeCfcWire(QPointF from, QPointF to, const CfcFrames &frames);

// Every wire of the body, routed.
[[nodiscard]] std::vector<CfcWire> routeCfcWires(const std::vector<model::Element> &elements, const CfcFrames &frames);

} // namespace iec::editors::cfc
