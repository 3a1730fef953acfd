/// @file contact_waves.hpp
/// @brief Contacts put in waves of contacts that share no dynamic body, each body meeting its contacts in their order.
///
/// Gauss–Seidel solves contacts one after the other, each reading the
/// velocities the earlier ones left; but two contacts that share no dynamic
/// body do not read each other's results, so they may be solved at once in
/// SIMD lanes (lanes.hpp) with the same numbers to the last bit. Walking the
/// contacts in their order, each one takes the first wave after the latest
/// wave of an earlier contact on either of its bodies (the static record 0
/// does not count: nothing moves it),
/// \f[ w_c = \max\big(\text{next}(A_c),\ \text{next}(B_c)\big), \qquad
///     \text{next}(A_c) = \text{next}(B_c) = w_c + 1 . \f]
/// Two contacts of one wave never share a body, and every body meets its
/// contacts in waves in their own order (list scheduling of the contacts'
/// dependency graph; Tonge, "Iterative Rigid Body Solvers", GDC 2012).
///
/// How wide the waves are depends on the scene: a heap of balls gives waves of
/// dozens, a tower of boxes a chain whose every contact waits for the one
/// before (its waves hold one contact each).
#pragma once

#include <cstdint>
#include <vector>

namespace stepwise {

struct SolverWorkspace;
struct FastWorkspace;

/// @brief Puts the contacts @p list (indices in SolverWorkspace::contacts, in their pass order) in waves.
///
/// Fills FastWorkspace::waveOrder with the same contacts wave by wave (their order kept within a
/// wave), FastWorkspace::waveStart with where each wave *ends* in it (wave w runs from
/// waveStart[w − 1], or 0, to waveStart[w]), and FastWorkspace::waves. The scratch arrays are the
/// workspace's, reused by each call.
void scheduleWaves(const SolverWorkspace& solver, const std::vector<std::uint32_t>& list, FastWorkspace& fast);

}  // namespace stepwise
