#pragma once

#include "model/elements_common.h"

#include <variant>

namespace iec::model {

// sfcObjects of the XSD.

struct Step : ElementHeader {
    QString name;
    bool initialStep = false;
    bool negated = false;
    std::optional<ConnectionPointIn> connectionPointIn;
    std::optional<ConnectionPointOut> connectionPointOut; // to the following transition
    std::optional<ConnectionPointOut> connectionPointOutAction; // to the step's action block

    bool operator==(const Step &) const = default;
};

struct MacroStep : ElementHeader {
    std::optional<QString> name;
    std::optional<ConnectionPointIn> connectionPointIn;
    std::optional<ConnectionPointOut> connectionPointOut;
    std::optional<Box<Body>> body;

    bool operator==(const MacroStep &) const = default;
};

struct JumpStep : ElementHeader {
    QString targetName;
    std::optional<ConnectionPointIn> connectionPointIn;

    bool operator==(const JumpStep &) const = default;
};

// Transition conditions: a reference to a POU transition, a wire (connectionPointIn), or an
// inline body.
struct InlineCondition {
    QString name;
    Box<Body> body;

    bool operator==(const InlineCondition &) const = default;
};

struct Condition {
    bool negated = false;
    std::variant<Reference, ConnectionPointIn, InlineCondition> kind;

    bool operator==(const Condition &) const = default;
};

struct Transition : ElementHeader {
    std::optional<quint64> priority;
    std::optional<ConnectionPointIn> connectionPointIn;
    std::optional<ConnectionPointOut> connectionPointOut;
    std::optional<Condition> condition;

    bool operator==(const Transition &) const = default;
};

struct SelectionDivergence : ElementHeader {
    std::optional<ConnectionPointIn> connectionPointIn;
    std::vector<ConnectionPointOut> connectionPointOuts;

    bool operator==(const SelectionDivergence &) const = default;
};

struct SelectionConvergence : ElementHeader {
    std::vector<ConnectionPointIn> connectionPointIns;
    std::optional<ConnectionPointOut> connectionPointOut;

    bool operator==(const SelectionConvergence &) const = default;
};

struct SimultaneousDivergence : ElementHeader {
    std::optional<QString> name;
    std::optional<ConnectionPointIn> connectionPointIn;
    std::vector<ConnectionPointOut> connectionPointOuts;

    bool operator==(const SimultaneousDivergence &) const = default;
};

struct SimultaneousConvergence : ElementHeader {
    std::vector<ConnectionPointIn> connectionPointIns;
    std::optional<ConnectionPointOut> connectionPointOut;

    bool operator==(const SimultaneousConvergence &) const = default;
};

} // namespace iec::model
