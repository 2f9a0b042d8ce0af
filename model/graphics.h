#pragma once

#include "model/opaque.h"

#include <QString>

#include <optional>
#include <vector>

namespace iec::model {

// ppx:position (also used for relPosition and connection waypoints). The XSD says decimal.
struct Position {
    double x = 0;
    double y = 0;

    bool operator==(const Position &) const = default;
};

// ppx:connection: lives on the input pin and names its source (DESIGN.md: "a connection lives
// on the input pin, as in the file").
struct Connection {
    quint64 refLocalId = 0; // the source element
    std::optional<QString> formalParameter; // the source pin when the source has several
    std::vector<Position> waypoints; // absolute positions of the wire's corners
    std::optional<QString> globalId;
    AddData addData;
    Extras extras;

    bool operator==(const Connection &) const = default;
};

// ppx:connectionPointIn: either connections or an expression (the choice is optional).
struct ConnectionPointIn {
    std::optional<Position> relPosition;
    std::vector<Connection> connections;
    std::optional<QString> expression;
    std::optional<QString> globalId;
    AddData addData;
    Extras extras;

    bool operator==(const ConnectionPointIn &) const = default;
};

// ppx:connectionPointOut. `formalParameter` is set where the XSD extends the type with it
// (power rail outputs, step outputs, divergence branches).
struct ConnectionPointOut {
    std::optional<Position> relPosition;
    std::optional<QString> expression;
    std::optional<QString> formalParameter;
    std::optional<QString> globalId;
    AddData addData;
    Extras extras;

    bool operator==(const ConnectionPointOut &) const = default;
};

enum class EdgeModifier { None, Falling, Rising };
enum class StorageModifier { None, Set, Reset };

// What every element of a graphical body carries. width/height are optional in the XSD for most
// elements; `executionOrderId` orders the evaluation of FBD/CFC networks.
struct ElementHeader {
    quint64 localId = 0; // CODESYS writes 64-bit values
    Position position;
    std::optional<double> width;
    std::optional<double> height;
    std::optional<quint64> executionOrderId;
    std::optional<QString> globalId;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const ElementHeader &) const = default;
};

} // namespace iec::model
