/// @file thread_pool.cpp
/// @brief The pool's job hand-over: a ticket word for the fast road, one mutex and a condition variable for sleepers.
///
/// Hand-over, per job: run() stores the job's fields, resets the count of
/// finished chunks, publishes the ticket (job number, chunk 0) with a release
/// store and bumps the generation (under the mutex, so that a worker falling
/// asleep cannot miss it), and notifies only if a worker sleeps. A thread
/// claims a chunk by a compare-and-swap of the ticket from (job, i) to
/// (job, i + 1): the swap succeeds only while the ticket still names the job
/// whose fields the thread read, so a worker that wakes late, after its job
/// is over and the next has begun, claims nothing by mistake. Each chunk that
/// returns adds one to the finished count (a release), and run() returns when
/// that count reaches the job's chunks (an acquire): every chunk's writes are
/// then visible to the caller. The caller never waits for a worker that
/// claimed nothing.
#include "core/thread_pool.hpp"

#include <cstdint>

namespace stepwise {

namespace {

/// One round of a spin: tells the processor this is a wait loop (x86 PAUSE), so a spinning core
/// leaves its shared resources to its sibling and does not flood the memory bus.
inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#else
    std::this_thread::yield();
#endif
}

/// Spins between two looks at the clock: a clock read costs about as much as these pauses.
constexpr int kSpinsPerClockRead = 64;

}  // namespace

unsigned autoThreadCount() {
    const unsigned n = std::thread::hardware_concurrency();  // 0 when the system cannot tell
    return n == 0 ? 1u : n;
}

ThreadPool::ThreadPool(unsigned threads) {
    const unsigned workers = threads > 1 ? threads - 1 : 0;
    workers_.reserve(workers);
    for (unsigned i = 0; i < workers; ++i) workers_.emplace_back([this] { workerLoop(); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_.store(true, std::memory_order_release);
    }
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
}

void ThreadPool::dispatch(std::size_t chunks, void* context, Trampoline call) {
    // The last job is over (run() returned), so no thread can be inside it: its fields are free.
    const std::uint64_t job = generation_.load(std::memory_order_relaxed) + 1;
    context_.store(context, std::memory_order_relaxed);
    call_.store(call, std::memory_order_relaxed);
    jobChunks_.store((job << 32) | chunks, std::memory_order_relaxed);
    doneChunks_.store(0, std::memory_order_relaxed);
    ticket_.store(job << 32, std::memory_order_release);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        generation_.store(job, std::memory_order_release);
    }
    if (sleepers_.load(std::memory_order_acquire) > 0) wake_.notify_all();
    takeChunks(job);  // the caller works too
    // Chunks other threads claimed are finishing: spin, but give the core away after a while, in
    // case the thread that holds one is not running (more threads than cores).
    for (int spin = 0; doneChunks_.load(std::memory_order_acquire) != chunks; ++spin) {
        if (spin < kSpinsPerClockRead) {
            relax();
        } else {
            std::this_thread::yield();
        }
    }
}

void ThreadPool::takeChunks(std::uint64_t job) {
    const std::uint64_t tag = job & 0xffffffffu;  // the job's number as the ticket and the count hold it
    std::uint64_t ticket = ticket_.load(std::memory_order_acquire);
    for (;;) {
        if ((ticket >> 32) != tag) return;  // a newer job: this one is over
        const std::size_t chunk = static_cast<std::size_t>(ticket & 0xffffffffu);
        // The count of the ticket's job, or none: a count of the next job means this one is over.
        const std::uint64_t jobChunks = jobChunks_.load(std::memory_order_relaxed);
        if ((jobChunks >> 32) != tag) return;
        const std::size_t chunks = static_cast<std::size_t>(jobChunks & 0xffffffffu);
        void* const context = context_.load(std::memory_order_relaxed);
        const Trampoline call = call_.load(std::memory_order_relaxed);
        if (chunk >= chunks) return;
        // Claim the chunk only if the ticket has not moved since these fields were read (acq_rel:
        // the reads above stay before the claim); on failure `ticket` is reloaded and the loop
        // looks again.
        if (ticket_.compare_exchange_weak(ticket, ticket + 1, std::memory_order_acq_rel, std::memory_order_acquire)) {
            call(context, chunk);
            doneChunks_.fetch_add(1, std::memory_order_release);
            ticket = ticket_.load(std::memory_order_acquire);
        }
    }
}

bool ThreadPool::waitForJob(std::uint64_t seen) {
    const auto sleepAt = std::chrono::steady_clock::now() + kSpinBeforeSleep;
    for (int spin = 1;; ++spin) {
        if (stop_.load(std::memory_order_acquire)) return false;
        if (generation_.load(std::memory_order_acquire) != seen) return true;
        relax();
        if (spin % kSpinsPerClockRead == 0 && std::chrono::steady_clock::now() >= sleepAt) break;
    }
    std::unique_lock<std::mutex> lock(mutex_);
    sleepers_.fetch_add(1, std::memory_order_acq_rel);
    wake_.wait(lock, [&] {
        return stop_.load(std::memory_order_acquire) || generation_.load(std::memory_order_acquire) != seen;
    });
    sleepers_.fetch_sub(1, std::memory_order_acq_rel);
    return !stop_.load(std::memory_order_acquire);
}

void ThreadPool::workerLoop() {
    std::uint64_t seen = 0;
    while (waitForJob(seen)) {
        seen = generation_.load(std::memory_order_acquire);
        takeChunks(seen);
    }
}

}  // namespace stepwise
