/// @file thread_pool.hpp
/// @brief A small persistent pool of worker threads for the stages that split into independent chunks.
///
/// The threads are created once, with the World, and sleep on a condition
/// variable between jobs: a step creates no thread and allocates nothing.
/// A job is "run this function on chunks 0 … n−1"; the workers and the
/// calling thread take chunk numbers from one atomic counter until none are
/// left, and run() returns when every chunk is done. Which thread runs which
/// chunk changes from run to run, so a job must write only into the slots of
/// its own chunk and the caller must merge the chunks in chunk order: that is
/// what keeps the results bit-identical whatever the number of threads
/// (src/collision/narrowphase.cpp does exactly this).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>
#include <vector>

namespace stepwise {

/// @brief How many threads `Threads=0` (Auto) means: the machine's hardware threads, at least 1.
unsigned autoThreadCount();

/// @brief Persistent worker threads that run one chunked job at a time.
class ThreadPool {
public:
    /// @brief Starts @p threads − 1 workers; the thread that calls run() is the last one.
    /// @param threads total threads working on a job, ≥ 1 (1: no worker, run() runs inline)
    explicit ThreadPool(unsigned threads);
    /// @brief Wakes the workers, tells them to stop and joins them.
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;             ///< Threads are not copied.
    ThreadPool& operator=(const ThreadPool&) = delete;  ///< Threads are not copied.

    /// @brief Threads that work on a job, the caller included.
    unsigned threadCount() const { return static_cast<unsigned>(workers_.size()) + 1; }

    /// @brief Calls @p chunk(i) once for every i in [0, @p chunks), spread over the threads;
    /// returns when all calls have returned.
    ///
    /// @p chunk is called concurrently from several threads: it must only
    /// read shared data and write into what belongs to chunk i. Taken by
    /// reference through a plain function pointer, so no std::function and
    /// no allocation.
    template <class ChunkFunction>
    void run(std::size_t chunks, ChunkFunction& chunk) {
        if (chunks == 0) return;
        if (workers_.empty() || chunks == 1) {
            for (std::size_t i = 0; i < chunks; ++i) chunk(i);
            return;
        }
        dispatch(chunks, &chunk, [](void* context, std::size_t i) { (*static_cast<ChunkFunction*>(context))(i); });
    }

private:
    using Trampoline = void (*)(void* context, std::size_t chunk);

    void dispatch(std::size_t chunks, void* context, Trampoline call);
    void workerLoop();
    void takeChunks();

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_;      ///< Workers wait here for a new job (or for stop_).
    std::condition_variable finished_;  ///< run() waits here for the last worker to leave the job.

    // The current job, written under mutex_ before generation_ is bumped.
    void* context_ = nullptr;
    Trampoline call_ = nullptr;
    std::size_t chunkCount_ = 0;
    std::atomic<std::size_t> nextChunk_{0};
    std::uint64_t generation_ = 0;  ///< Bumped once per job: a worker runs each job once.
    unsigned busyWorkers_ = 0;      ///< Workers still inside the current job.
    bool stop_ = false;
};

}  // namespace stepwise
