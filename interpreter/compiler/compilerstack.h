#pragma once

#include <functional>

// The compiler runs on a thread with a stack of known size (limits::kCompilerStackBytes), so that
// how deep a program may nest does not depend on the thread that asks for a compile.
namespace iec::interp {

// Runs `work` on such a thread and waits for it; directly when this thread is one already. An
// exception thrown by `work` is thrown again here.
void runOnCompilerStack(const std::function<void()> &work);

// True when the compiler has used its stack budget (limits::kCompilerStackBudget) on this thread:
// whatever recursion asks goes no deeper. Always false outside runOnCompilerStack.
bool compilerStackExhausted();

} // namespace iec::interp
