/// @file thread_pool.cpp
/// @brief The pool's job hand-over: atomics for the fast road, one mutex and a condition variable for sleepers.
///
/// Hand-over, per job: run() stores the job's fields, marks every worker
/// busy and bumps the generation (a release store, under the mutex so that a
/// worker falling asleep cannot miss it), and notifies only if a worker
/// sleeps. Each worker that sees a new generation (an acquire load) takes
/// chunk numbers with fetch_add until they run out, the caller too, then
/// counts itself out of the job (a release decrement). run() waits until the
/// count is zero (an acquire load): every chunk's writes are then visible to
/// the caller. A worker takes part in every job, so no job can start before
/// every worker has left the one before.
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
    context_ = context;
    call_ = call;
    chunkCount_ = chunks;
    nextChunk_.store(0, std::memory_order_relaxed);
    busyWorkers_.store(static_cast<unsigned>(workers_.size()), std::memory_order_relaxed);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        generation_.fetch_add(1, std::memory_order_release);
    }
    if (sleepers_.load(std::memory_order_acquire) > 0) wake_.notify_all();
    takeChunks();  // the caller works too
    // The workers are finishing their last chunks: spin, but give the core away if one of them
    // is not running (more threads than cores), so that it can finish.
    for (int spin = 0; busyWorkers_.load(std::memory_order_acquire) != 0; ++spin) {
        if (spin < kSpinsPerClockRead) {
            relax();
        } else {
            std::this_thread::yield();
        }
    }
}

void ThreadPool::takeChunks() {
    for (;;) {
        const std::size_t i = nextChunk_.fetch_add(1, std::memory_order_relaxed);
        if (i >= chunkCount_) return;
        call_(context_, i);
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
        takeChunks();
        busyWorkers_.fetch_sub(1, std::memory_order_release);
    }
}

}  // namespace stepwise
