#include "interpreter/compiler/compilerstack.h"

#include "interpreter/compiler/limits.h"

#include <QThread>

#include <exception>
#include <memory>

namespace iec::interp {

namespace {

// Where the compiler's stack starts on this thread (null: not running the compiler), and how much
// of it the compiler may use.
thread_local const char *t_stackStart = nullptr;
thread_local std::size_t t_stackBudget = 0;

const char *currentFrame()
{
    return static_cast<const char *>(__builtin_frame_address(0));
}

void runMeasured(const std::function<void()> &work, std::size_t budget)
{
    struct Leave {
        ~Leave() { t_stackStart = nullptr; }
    } leave;
    t_stackStart = currentFrame();
    t_stackBudget = budget;
    work();
}

} // namespace

void runOnCompilerStack(const std::function<void()> &work)
{
    if (t_stackStart) {
        work();
        return;
    }
    bool ran = false;
    std::exception_ptr failure;
    const std::unique_ptr<QThread> thread(QThread::create([&] {
        ran = true;
        try {
            runMeasured(work, limits::kCompilerStackBudget);
        } catch (...) {
            failure = std::current_exception();
        }
    }));
    thread->setStackSize(static_cast<uint>(limits::kCompilerStackBytes));
    thread->start();
    thread->wait();
    if (!ran) {
        // No thread could be started (the process is out of threads or memory): compile here,
        // with a budget any thread's stack has.
        constexpr std::size_t kFallbackBudget = 256 * 1024;
        runMeasured(work, kFallbackBudget);
    }
    if (failure)
        std::rethrow_exception(failure);
}

bool compilerStackExhausted()
{
    return t_stackStart && std::size_t(t_stackStart - currentFrame()) > t_stackBudget;
}

} // namespace iec::interp
