#pragma once

#include "model/body.h"
#include "model/ids.h"
#include "model/variables.h"

#include <QString>

#include <optional>
#include <vector>

namespace iec::model {

enum class PouKind { Program, FunctionBlock, Function };

// The declarations of a POU. The XSD allows the var lists in any order and any number.
struct Interface {
    std::optional<DataType> returnType; // functions only
    std::vector<VarList> varLists;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const Interface &) const = default;
};

// A POU action (pou/actions/action) or transition (pou/transitions/transition): a named body.
// The XSD gives both the same shape.
struct PouPart {
    QString name;
    std::optional<QString> globalId;
    Body body;
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;

    bool operator==(const PouPart &) const = default;
};
using PouAction = PouPart;
using PouTransition = PouPart;

struct Pou {
    PouId id; // not in the file: assigned by ProjectModel, fixed while the project is open
    QString name;
    PouKind kind = PouKind::Program;
    std::optional<QString> globalId;
    std::optional<Interface> pouInterface; // <interface>
    std::vector<PouAction> actions;
    std::vector<PouTransition> transitions;
    std::vector<Body> bodies; // the XSD allows several; tools write one
    AddData addData;
    std::optional<FormattedText> documentation;
    Extras extras;
    // Non-zero when the POU came from a vendor addData entry (CODESYS/TwinCAT keep POUs there).
    // The writer puts it back into that entry, so nothing is lost and nothing duplicated.
    quint32 addDataSlot = 0;

    // The language of the first body (ST when there is none).
    [[nodiscard]] BodyLanguage language() const;
    [[nodiscard]] const Body *body() const { return bodies.empty() ? nullptr : &bodies.front(); }

    bool operator==(const Pou &) const = default;
};

} // namespace iec::model
