/// @file thread_pool.hpp
/// @brief A small persistent pool of worker threads for the stages that split into independent chunks.
///
/// The threads are created once, with the World, and sleep on a condition
/// variable between jobs: a step creates no thread and allocates nothing.
/// A job is "run this function on chunks 0 … n−1"; the workers and the
/// calling thread take chunk numbers from one atomic counter until none are
/// left, and run() returns when every chunk is done.
///
/// **A busy machine.** run() waits for the chunks, never for the workers: a
/// worker the operating system has not scheduled (more runnable threads than
/// cores) simply claims no chunk, and the caller does its share. A pool whose
/// caller had to wait until every worker had looked at each job would pay a
/// scheduler time slice, milliseconds, for each of the hundreds of jobs of a
/// step whenever another program holds a core.
///
/// **Jobs in quick succession.** The solver hands out a job per wave of
/// contacts, hundreds of times a step, each a few microseconds long. Waking
/// a sleeping thread through the operating system takes tens of
/// microseconds, longer than such a job. So a worker that finishes a job
/// first *spins* (keeps checking for the next one) for kSpinBeforeSleep and
/// only then sleeps: within a step the next job finds it awake, and between
/// steps, or in a program that never calls run(), it sleeps and costs nothing. Which thread runs which
/// chunk changes from run to run, so a job must write only into the slots of
/// its own chunk and the caller must merge the chunks in chunk order: that is
/// what keeps the results bit-identical whatever the number of threads
/// (src/collision/narrowphase.cpp does exactly this).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>
#include <vector>

namespace stepwise {

/// How long an idle worker keeps checking for the next job before it sleeps. A little over the
/// longest gap between two jobs of one step's contact passes (a serial stage of a large scene),
/// and short enough that an idle pool gives its cores back almost at once.
inline constexpr std::chrono::microseconds kSpinBeforeSleep{200};

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
        if (workers_.empty() || chunks == 1 || chunks > kMaxChunksPerJob) {  // the last: more than a ticket counts
            for (std::size_t i = 0; i < chunks; ++i) chunk(i);
            return;
        }
        dispatch(chunks, &chunk, [](void* context, std::size_t i) { (*static_cast<ChunkFunction*>(context))(i); });
    }

private:
    using Trampoline = void (*)(void* context, std::size_t chunk);
    /// The most chunks a job's ticket can count (its low 32 bits); a larger job runs on the caller alone.
    static constexpr std::size_t kMaxChunksPerJob = 0xffffffffu;
    void dispatch(std::size_t chunks, void* context, Trampoline call);
    void workerLoop();
    /// Claims and runs chunks of job @p job until none are left or a newer job has started.
    void takeChunks(std::uint64_t job);
    /// Waits for a job newer than @p seen: spinning for up to kSpinBeforeSleep, then asleep on wake_.
    /// Returns false when the pool is stopping.
    bool waitForJob(std::uint64_t seen);

    std::vector<std::thread> workers_;
    std::mutex mutex_;                  ///< Held only to fall asleep and to publish a job to sleepers.
    std::condition_variable wake_;      ///< Workers that spun long enough sleep here.
    // The current job. Its fields are written before its ticket is published (a release) and read
    // after a worker loads that ticket (an acquire); atomics, because a worker that comes late may
    // read them while the next job writes them. Such a worker holds the old job's ticket, whose
    // chunks are all claimed; so the chunk count carries its job's number, and a count that names
    // another job than the ticket's is never compared with the ticket's chunk (the next job's
    // count, larger than the old one, would let the late worker claim, under the old ticket, a
    // chunk of the next job that another thread claims too).
    std::atomic<void*> context_{nullptr};
    std::atomic<Trampoline> call_{nullptr};
    /// The job's number in the high 32 bits and its chunk count in the low 32.
    std::atomic<std::uint64_t> jobChunks_{0};
    /// The job's number in the high 32 bits and its next unclaimed chunk in the low 32: a chunk is
    /// claimed by a compare-and-swap of the whole word, so a late worker can never claim a chunk of
    /// a job it has not read.
    std::atomic<std::uint64_t> ticket_{0};
    std::atomic<std::size_t> doneChunks_{0};    ///< Chunks of the current job that have returned.
    std::atomic<std::uint64_t> generation_{0};  ///< The current job's number: what waiting workers watch.
    std::atomic<unsigned> sleepers_{0};         ///< Workers asleep on wake_ (only those need a notify).
    std::atomic<bool> stop_{false};
};

}  // namespace stepwise
