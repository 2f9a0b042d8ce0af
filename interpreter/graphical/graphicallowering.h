#pragma once

#include "interpreter/compiler/ast.h"
#include "interpreter/compiler/diagnostics.h"

#include "model/body.h"
#include "model/graphics.h"

#include <memory>
#include <optional>
#include <vector>

// Lowering of LD and FBD/CFC networks to the compiler's statements (ast.h), so graphical POUs
// run on the same VM as ST. Hidden state the networks need (edge detectors for P/N contacts and
// coils, instances of ADD-like blocks are not needed, but R_TRIG/F_TRIG are) is declared as extra
// variables of the POU being lowered; their names start with "__" so they can never clash with
// a user's identifier.
//
// Diagnostics carry (owner, localId): owner is the POU name, or "Pou.Action" / "Pou.Transition"
// for a body that belongs to an action or a transition.
namespace iec::interp::graphical {

struct LoweringContext {
    ast::Pou &pou;          // receives hidden VAR declarations
    QString owner;          // the name diagnostics are filed under
    Diagnostics &diagnostics;
    // lowerInput only: where the statements go that must run before its value is read (function
    // block calls, edge detectors, values read twice). Without it, a network that needs any of
    // them gives a diagnostic; plain contacts, variables and functions need none.
    std::vector<ast::Stmt> *setup = nullptr;
};

// The statements of an LD or FBD body, in execution order (LD: networks top to bottom, left to
// right; FBD: executionOrderId, else data flow). Jumps make the statements a loop over the
// segments between labels (WHILE with CONTINUE), since ST has no GOTO.
std::vector<ast::Stmt> lowerBody(const model::Body &body, LoweringContext &context);

// The value that flows into `input` inside `body`: used by SFC charts whose transition
// conditions are wired to FBD/LD elements placed in the chart (Beremiz, CODESYS). nullopt (and a
// diagnostic) when the input is not connected or its source cannot be lowered.
std::optional<ast::Expr> lowerInput(const model::Body &body, const model::ConnectionPointIn &input,
    LoweringContext &context);

class Network;

// lowerInput for many inputs of one body (every wired transition of a chart): the body's network
// is built and checked once, and its problems are reported once. `body` must outlive it.
class InputLowering
{
public:
    InputLowering(const model::Body &body, const QString &owner, Diagnostics &diagnostics);
    ~InputLowering();
    InputLowering(const InputLowering &) = delete;
    InputLowering &operator=(const InputLowering &) = delete;

    std::optional<ast::Expr> lower(const model::ConnectionPointIn &input, LoweringContext &context) const;

private:
    const model::Body &m_body;
    std::unique_ptr<Network> m_network; // null: no elements, or a network that cannot run
};

// CODESYS keeps a CFC diagram in the addData of a body whose ST text is empty
// (http://www.3s-software.com/plcopenxml/cfc). Returns it as an FBD body (its elements carry
// their execution order), or nullopt when `body` holds none.
std::optional<model::Body> cfcDiagram(const model::Body &body);

// The addData entry that marks an FBD body as IEC Studio's CFC (the editors' name,
// editors::kIecStudioCfcAddDataName); cfcDiagram's result carries it too.
inline constexpr const char *kCfcMarkAddDataName = "http://www.iecstudio.org/cfc";
// Whether `body` is a CFC diagram: its elements run one by one in execution order, so each is a
// place of its own for the debugger (a breakpoint halts before that element runs), where an
// LD or FBD network is one place.
bool isCfc(const model::Body &body);

} // namespace iec::interp::graphical
