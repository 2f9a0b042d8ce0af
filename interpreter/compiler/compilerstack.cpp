#include "interpreter/compiler/compilerstack.h"

#include "interpreter/compiler/limits.h"

#include <QThread>

#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

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

// A thread with the compiler's stack that runs one piece of work after another. Starting such a
// thread for every parse cost more than the parse: the IDE parses a declaration on each keystroke,
// and under the sanitizers the fuzzers spent most of their time mapping and clearing 64 MB stacks.
class CompilerThread
{
public:
    CompilerThread()
        : m_thread(QThread::create([this] { serve(); }))
    {
        m_thread->setStackSize(static_cast<uint>(limits::kCompilerStackBytes));
        m_thread->start();
    }

    ~CompilerThread()
    {
        {
            const std::lock_guard lock(m_mutex);
            m_quit = true;
        }
        m_wake.notify_all();
        m_thread->wait();
    }

    CompilerThread(const CompilerThread &) = delete;
    CompilerThread &operator=(const CompilerThread &) = delete;

    // False when no thread could be started (the process is out of threads or memory).
    bool running() const { return m_thread->isRunning(); }

    // Runs `work` there and waits for it; what it threw is returned.
    std::exception_ptr run(const std::function<void()> &work)
    {
        std::unique_lock lock(m_mutex);
        m_work = &work;
        m_failure = nullptr;
        m_wake.notify_all();
        m_wake.wait(lock, [this] { return m_work == nullptr; });
        return std::exchange(m_failure, nullptr);
    }

private:
    void serve()
    {
        std::unique_lock lock(m_mutex);
        for (;;) {
            m_wake.wait(lock, [this] { return m_quit || m_work != nullptr; });
            if (m_quit)
                return;
            lock.unlock();
            std::exception_ptr failure;
            try {
                runMeasured(*m_work, limits::kCompilerStackBudget);
            } catch (...) {
                failure = std::current_exception();
            }
            lock.lock();
            m_failure = failure;
            m_work = nullptr;
            m_wake.notify_all();
        }
    }

    std::unique_ptr<QThread> m_thread;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    const std::function<void()> *m_work = nullptr;
    std::exception_ptr m_failure;
    bool m_quit = false;
};

// Compiler threads waiting for work. Two compiles at once (the IDE's build and a declaration
// parsed on the GUI thread) each take a thread of their own; at most kKeptIdle are kept after.
class CompilerThreadPool
{
public:
    static constexpr std::size_t kKeptIdle = 2;

    std::unique_ptr<CompilerThread> take()
    {
        {
            const std::lock_guard lock(m_mutex);
            if (!m_idle.empty()) {
                std::unique_ptr<CompilerThread> thread = std::move(m_idle.back());
                m_idle.pop_back();
                return thread;
            }
        }
        return std::make_unique<CompilerThread>();
    }

    void giveBack(std::unique_ptr<CompilerThread> thread)
    {
        const std::lock_guard lock(m_mutex);
        if (m_idle.size() < kKeptIdle)
            m_idle.push_back(std::move(thread));
    }

private:
    std::mutex m_mutex;
    std::vector<std::unique_ptr<CompilerThread>> m_idle;
};

CompilerThreadPool &compilerThreads()
{
    // Never destroyed: a compile still running on another thread when the process exits gives its
    // thread back after static destructors would have run. The idle threads end with the process.
    static auto *const pool = new CompilerThreadPool;
    return *pool;
}

} // namespace

void runOnCompilerStack(const std::function<void()> &work)
{
    if (t_stackStart) {
        work();
        return;
    }
    std::unique_ptr<CompilerThread> thread = compilerThreads().take();
    if (!thread->running()) {
        // No thread could be started: compile here, with a budget any thread's stack has.
        constexpr std::size_t kFallbackBudget = 256 * 1024;
        runMeasured(work, kFallbackBudget);
        return;
    }
    const std::exception_ptr failure = thread->run(work);
    compilerThreads().giveBack(std::move(thread));
    if (failure)
        std::rethrow_exception(failure);
}

bool compilerStackExhausted()
{
    return t_stackStart && std::size_t(t_stackStart - currentFrame()) > t_stackBudget;
}

} // namespace iec::interp
