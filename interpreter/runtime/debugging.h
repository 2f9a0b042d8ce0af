#pragma once

#include <QString>
#include <QtGlobal>

#include <vector>

// What the runtime's debugger works with: breakpoints, where a halted program stands, and how
// it goes on. The runtime (runtime.h) halts mid-scan and goes on from there; the virtual clock
// does not move while it is halted.
namespace iec::interp {

// A place in a body: a line of an ST or IL body, or an element of a graphical one (the root
// element of an LD/FBD network, a CFC box, an SFC step or transition).
struct CodeLocation {
    QString pou;         // the body's owner as the module names it: Main, or Main.Reset for an action
    int line = 0;        // text bodies: the line, counted from 1 as the editor shows it
    qint64 localId = -1; // graphical bodies: the element's localId; -1 for text
    // Graphical bodies: any of these elements (the elements of an LD/FBD network), besides localId.
    std::vector<qint64> elements;

    bool operator==(const CodeLocation &) const = default;
};

// When a breakpoint that is reached halts, by how often it was reached (CODESYS's hit count).
enum class HitRule {
    Always,
    Equal,      // on the n-th time only
    MultipleOf, // every n-th time
    AtLeast,    // the n-th time and every time after
};

struct Breakpoint {
    CodeLocation at;
    HitRule hitRule = HitRule::Always;
    int hitTarget = 1;
    // A Boolean expression in the halted POU's names ("i = 5 AND x > 2.5"); empty: none. It is
    // checked only after the hit count passed, and halts when it is TRUE.
    QString condition;
    bool enabled = true;
};

// How a halted program goes on.
enum class ResumeKind {
    Continue, // to the next breakpoint
    StepOver, // to the next line (network, step) of this body, or of its caller once it returns
    StepInto, // to the next line wherever it is, inside a call too
    StepOut,  // to the next line after this body returned
};

struct StackFrame {
    QString pou;      // Main, Main.Reset, Counter (a function block), ADD_3 (a function)
    QString instance; // Main, Main.Counter1; empty for functions
    int line = 0;
    qint64 localId = -1;
};

struct HaltInfo {
    CodeLocation at;
    int cycle = 0;       // the cycle that is halted (it has not finished)
    int breakpoint = -1; // index into the breakpoints set, -1 when a step halted it
    int hits = 0;        // how often that breakpoint was reached so far
    std::vector<StackFrame> stack; // outermost first, the halted body last
    QString conditionProblem;      // the breakpoint's condition could not be evaluated: why
};

} // namespace iec::interp
