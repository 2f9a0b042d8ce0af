#pragma once

#include "model/box.h"
#include "model/graphics.h"

namespace iec::model {

struct Body;

// Refers to a POU action (in an action block) or a POU transition (in a condition) by name.
struct Reference {
    QString name;

    bool operator==(const Reference &) const = default;
};

// commonObjects of the XSD: usable in FBD, LD and SFC bodies.

struct Comment : ElementHeader {
    FormattedText content;

    bool operator==(const Comment &) const = default;
};

// An element a tool could not interpret (it keeps the text the user wrote).
struct Error : ElementHeader {
    FormattedText content;

    bool operator==(const Error &) const = default;
};

// A named connector: the wire goes in here and comes out at the continuation of the same name.
struct Connector : ElementHeader {
    QString name;
    std::optional<ConnectionPointIn> connectionPointIn;

    bool operator==(const Connector &) const = default;
};

struct Continuation : ElementHeader {
    QString name;
    std::optional<ConnectionPointOut> connectionPointOut;

    bool operator==(const Continuation &) const = default;
};

// One action of an action block: a qualifier and either a reference to a POU action or an inline
// body.
struct ActionBlockAction {
    quint64 localId = 0;
    std::optional<QString> qualifier; // N when absent; P1 N P0 R S L D P DS DL SD SL
    std::optional<double> width;
    std::optional<double> height;
    std::optional<QString> duration;
    std::optional<QString> indicator;
    std::optional<quint64> executionOrderId;
    std::optional<QString> globalId;
    Position relPosition;
    std::optional<Reference> reference;
    std::optional<Box<Body>> inlineBody;
    std::optional<ConnectionPointOut> connectionPointOut;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const ActionBlockAction &) const = default;
};

struct ActionBlock : ElementHeader {
    bool negated = false;
    std::optional<ConnectionPointIn> connectionPointIn;
    std::vector<ActionBlockAction> actions;

    bool operator==(const ActionBlock &) const = default;
};

// A variable (pin) of a block or vendor element.
struct BlockVariable {
    QString formalParameter;
    bool negated = false;
    EdgeModifier edge = EdgeModifier::None;
    StorageModifier storage = StorageModifier::None;
    bool hidden = false;
    std::optional<ConnectionPointIn> connectionPointIn;
    std::optional<ConnectionPointOut> connectionPointOut;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const BlockVariable &) const = default;
};

// A vendor-specific graphical element with a textual fallback.
struct VendorElement : ElementHeader {
    FormattedText alternativeText;
    std::optional<std::vector<BlockVariable>> inputVariables;
    std::optional<std::vector<BlockVariable>> inOutVariables;
    std::optional<std::vector<BlockVariable>> outputVariables;

    bool operator==(const VendorElement &) const = default;
};

} // namespace iec::model
