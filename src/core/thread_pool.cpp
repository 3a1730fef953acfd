/// @file thread_pool.cpp
/// @brief The pool's job hand-over: one mutex, two condition variables, one atomic chunk counter.
///
/// Hand-over, per job: run() stores the job and bumps the generation under
/// the mutex and wakes every worker; each worker that sees a new generation
/// counts itself busy, then everyone (the caller too) takes chunk numbers
/// with fetch_add until they run out; the last worker to leave wakes the
/// caller. The mutex orders the job's fields before the workers read them,
/// and the workers' writes before run() returns (the "busy" count is only
/// changed under it), so the caller sees every chunk's results.
#include "core/thread_pool.hpp"

#include <cstdint>

namespace stepwise {

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
        stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
}

void ThreadPool::dispatch(std::size_t chunks, void* context, Trampoline call) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        context_ = context;
        call_ = call;
        chunkCount_ = chunks;
        nextChunk_.store(0, std::memory_order_relaxed);
        busyWorkers_ = static_cast<unsigned>(workers_.size());
        ++generation_;
    }
    wake_.notify_all();
    takeChunks();  // the caller works too
    std::unique_lock<std::mutex> lock(mutex_);
    finished_.wait(lock, [this] { return busyWorkers_ == 0; });
}

void ThreadPool::takeChunks() {
    for (;;) {
        const std::size_t i = nextChunk_.fetch_add(1, std::memory_order_relaxed);
        if (i >= chunkCount_) return;
        call_(context_, i);
    }
}

void ThreadPool::workerLoop() {
    std::uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
        if (stop_) return;
        seen = generation_;
        lock.unlock();
        takeChunks();
        lock.lock();
        if (--busyWorkers_ == 0) finished_.notify_one();
    }
}

}  // namespace stepwise
