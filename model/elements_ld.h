#pragma once

#include "model/elements_common.h"

namespace iec::model {

// ldObjects of the XSD: usable in LD and SFC bodies.

struct LeftPowerRail : ElementHeader {
    std::vector<ConnectionPointOut> connectionPointOuts; // each with its formalParameter

    bool operator==(const LeftPowerRail &) const = default;
};

struct RightPowerRail : ElementHeader {
    std::vector<ConnectionPointIn> connectionPointIns;

    bool operator==(const RightPowerRail &) const = default;
};

// Coil: negated; edge = positive/negative transition-sensing coil; storage = set/reset coil.
struct Coil : ElementHeader {
    QString variable;
    bool negated = false;
    EdgeModifier edge = EdgeModifier::None;
    StorageModifier storage = StorageModifier::None;
    std::optional<ConnectionPointIn> connectionPointIn;
    std::optional<ConnectionPointOut> connectionPointOut;

    bool operator==(const Coil &) const = default;
};

struct Contact : ElementHeader {
    QString variable;
    bool negated = false;
    EdgeModifier edge = EdgeModifier::None;
    StorageModifier storage = StorageModifier::None;
    std::optional<ConnectionPointIn> connectionPointIn;
    std::optional<ConnectionPointOut> connectionPointOut;

    bool operator==(const Contact &) const = default;
};

} // namespace iec::model
