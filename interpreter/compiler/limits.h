#pragma once

#include <cstddef>

// How deeply a program may nest, the same in the IDE and on the command line
// (docs/interpreter.md, "Limits"). The parser and the compiler recurse once per level of
// nesting, never once per item of a list: a sum of 100,000 terms, a body of 100,000 statements or
// an ELSIF chain of any length is read with loops and has no limit. Deeper nesting than this is
// refused with one located message instead of overflowing the stack.
namespace iec::interp::limits {

// Expressions and statements together. A level is a parenthesis, an operand that binds tighter
// than the operator before it (the 2 * 3 in 1 + 2 * 3), a unary operator (NOT, -), an argument
// list, an index, a member or bit access, an element of an array or structure initial value, and a
// block (IF, CASE, FOR, WHILE, REPEAT, an action of a chart). Hand-written programs stay far
// below; generated code rarely nests a tenth as deep.
inline constexpr int kMaxNesting = 1000;

// Types written inside types (ARRAY OF ARRAY OF ..., a STRUCT inside a STRUCT) and initial values
// inside initial values ([[1, 2], [3, 4]]). Each level is two or three levels of PLCopen XML, and
// the XML reader refuses more than 200; this limit keeps every declaration a .st file holds
// readable again from the .xml it converts to.
inline constexpr int kMaxTypeNesting = 40;

// The stack the compiler runs on (compile, compileText, frontend::compileProject hand their work
// to a thread with it when they are not on one already), so that the limits above hold on every platform and
// in every thread that asks for a compile: a GUI thread on Windows has 1 MB, a worker thread on
// macOS 512 KB.
inline constexpr std::size_t kCompilerStackBytes = std::size_t(64) * 1024 * 1024;

// What the compiler may use of that stack before it refuses to go deeper (chains that are not
// nesting in the text: constants defined by constants, types by types, function block instances
// inside instances). The rest is a margin for the code that runs at the deepest point.
inline constexpr std::size_t kCompilerStackBudget = std::size_t(48) * 1024 * 1024;

} // namespace iec::interp::limits
