#pragma once

#include "model/elements_common.h"

namespace iec::model {

// fbdObjects of the XSD: usable in FBD, LD and SFC bodies.

// A function or function block call.
struct Block : ElementHeader {
    QString typeName;
    std::optional<QString> instanceName;
    std::vector<BlockVariable> inputVariables;
    std::vector<BlockVariable> inOutVariables;
    std::vector<BlockVariable> outputVariables;

    bool operator==(const Block &) const = default;
};

struct InVariable : ElementHeader {
    QString expression;
    bool negated = false;
    EdgeModifier edge = EdgeModifier::None;
    StorageModifier storage = StorageModifier::None;
    std::optional<ConnectionPointOut> connectionPointOut;

    bool operator==(const InVariable &) const = default;
};

struct OutVariable : ElementHeader {
    QString expression;
    bool negated = false;
    EdgeModifier edge = EdgeModifier::None;
    StorageModifier storage = StorageModifier::None;
    std::optional<ConnectionPointIn> connectionPointIn;

    bool operator==(const OutVariable &) const = default;
};

struct InOutVariable : ElementHeader {
    QString expression;
    bool negatedIn = false;
    EdgeModifier edgeIn = EdgeModifier::None;
    StorageModifier storageIn = StorageModifier::None;
    bool negatedOut = false;
    EdgeModifier edgeOut = EdgeModifier::None;
    StorageModifier storageOut = StorageModifier::None;
    std::optional<ConnectionPointIn> connectionPointIn;
    std::optional<ConnectionPointOut> connectionPointOut;

    bool operator==(const InOutVariable &) const = default;
};

struct Label : ElementHeader {
    QString label;

    bool operator==(const Label &) const = default;
};

struct Jump : ElementHeader {
    QString label;
    std::optional<ConnectionPointIn> connectionPointIn;

    bool operator==(const Jump &) const = default;
};

struct Return : ElementHeader {
    std::optional<ConnectionPointIn> connectionPointIn;

    bool operator==(const Return &) const = default;
};

} // namespace iec::model
