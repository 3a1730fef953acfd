/// @file parallel_waves.hpp
/// @brief A wave's contacts split between threads: the same numbers with any number of threads.
///
/// **Why a wave can be split.** The contacts of one wave share no dynamic
/// body (contact_waves.hpp): no contact of the wave reads a velocity
/// another one writes. So the batches of a wave may be solved in any order,
/// or at the same time on different cores, and every body still meets its
/// contacts in the plain pass's order. That is what graph colouring buys an
/// engine (Box2D v3's constraint graph, Jolt's and PhysX's batches): the
/// contacts of one *colour* are independent, and a colour can be cut into as
/// many pieces as there are threads. Here the colours are the waves.
///
/// **Why the waves cannot.** Wave w + 1 reads what wave w wrote. So the
/// threads finish a wave together before any starts the next: the pool's
/// run() returns only when every piece is done, a *barrier*.
///
/// **What a barrier costs.** Handing a wave out and waiting for its pieces
/// costs a few microseconds (the workers spin between jobs, thread_pool.hpp),
/// while a batch of four contacts costs some 0.1 µs. A wave is cut only when
/// it holds at least kParallelWaveBatches batches, enough work to be worth a
/// barrier; the small waves between are solved by the calling thread alone,
/// in order. A scene of a few hundred contacts has no such wave and runs
/// exactly as with one thread.
///
/// **The same bits.** Each piece is solved by solveRoundContactRange() or
/// solveBoxContactRange(), the same lines a single thread runs, on batches that touch no body of another
/// piece. So the velocities are the one-thread pass's, to the bit, with 1, 2
/// or 4 threads (tests/test_threads.cpp: "[threads][fast]").
///
/// Reference: Catto, "Solver2D" and Box2D v3 `constraint_graph.c`, `solver.c`
/// (colours solved by worker threads between barriers), 2024; Tonge,
/// "Iterative Rigid Body Solvers" (GDC 2012).
#pragma once

#include <cstddef>

#include "core/thread_pool.hpp"
#include "dynamics/contact_solver.hpp"
#include "fast/fast_workspace.hpp"

namespace stepwise {

/// A wave of at least this many batches (four contacts each) is split between the threads;
/// smaller ones run on the calling thread. 64 batches are some 256 contacts, about 20 µs of
/// work, against a barrier of a few µs.
inline constexpr std::size_t kParallelWaveBatches = 64;

/// The fewest batches one piece of a split wave gets: pieces smaller than this cost more in
/// hand-over than they save.
inline constexpr std::size_t kMinBatchesPerPiece = 16;

/// @brief One Gauss–Seidel pass over the batched round contacts, as solveRoundContacts(), with each
/// large wave split between @p pool's threads. With one thread it is solveRoundContacts() itself.
void solveRoundContactsOnThreads(SolverWorkspace& solver, FastWorkspace& fast, const ContactSolverSettings& settings,
                                 bool useBias, ThreadPool& pool);

/// @brief The same for the batched contacts with stored rows (solveBoxContacts(), box_contact_lanes.hpp).
void solveBoxContactsOnThreads(SolverWorkspace& solver, FastWorkspace& fast, const ContactSolverSettings& settings,
                               bool useBias, ThreadPool& pool);

}  // namespace stepwise
