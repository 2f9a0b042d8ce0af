#pragma once

#include "model/elements_common.h"
#include "model/elements_fbd.h"
#include "model/elements_ld.h"
#include "model/elements_sfc.h"

#include <variant>

namespace iec::model {

// Every graphical element kind of the XSD, in the order of its groups (common, FBD, LD, SFC).
using Element = std::variant<Comment, Error, Connector, Continuation, ActionBlock, VendorElement, //
    Block, InVariable, OutVariable, InOutVariable, Label, Jump, Return, //
    LeftPowerRail, RightPowerRail, Coil, Contact, //
    Step, MacroStep, JumpStep, Transition, SelectionDivergence, SelectionConvergence, SimultaneousDivergence,
    SimultaneousConvergence>;

// The XSD element name of a kind ("contact", "selectionDivergence", ...).
const char *elementTagName(const Element &element);
const char *elementTagName(std::size_t variantIndex);

inline const ElementHeader &header(const Element &element)
{
    return std::visit([](const auto &e) -> const ElementHeader & { return e; }, element);
}

inline ElementHeader &header(Element &element)
{
    return std::visit([](auto &e) -> ElementHeader & { return e; }, element);
}

// Every connection point in of an element (block pins, rails, conditions wired in, ...), for
// connect/disconnect and reverse lookups.
std::vector<ConnectionPointIn *> inputPoints(Element &element);
std::vector<const ConnectionPointIn *> inputPoints(const Element &element);

} // namespace iec::model
