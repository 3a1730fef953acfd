/// @file contact_colours.hpp
/// @brief The order of a pass: contacts grouped in colours, no two contacts of a colour on one dynamic body.
///
/// **Why the order matters.** A Gauss–Seidel pass solves the contacts one
/// after the other, each reading the velocities the earlier ones left, so
/// the order of the contacts is part of the result (contact_solver.hpp, "The
/// order of a pass"). Any fixed order is a valid sweep; they differ in how
/// far one pass carries an impulse through touching bodies, and in how much
/// of the pass could be done at the same time.
///
/// **Colours.** Think of the contacts as the edges of a graph whose nodes are
/// the dynamic bodies (a plane or a kinematic body is not a node: nothing
/// moves it, so it can be shared). Two contacts that share no node read and
/// write different velocities: solved one after the other or at once, they
/// give the same numbers. A *colouring* gives each contact a colour such that
/// the contacts of one colour share no node. Greedy colouring walks the
/// contacts in the order the narrowphase found them and gives each the lowest
/// colour that neither of its bodies holds yet,
/// \f[ k_c = \min\{\,k \ge 0 : k \notin \text{used}(A_c) \cup \text{used}(B_c)\,\}, \f]
/// with a bit mask of used colours per body: the first free colour is the
/// lowest zero bit of used(A) | used(B). A body with d contacts uses at most d
/// colours, so a colouring needs at most 2·d_max − 1 colours: a heap of balls
/// takes some 10, a pyramid of boxes some 20 (Box2D v3's constraint graph,
/// `constraint_graph.c`, colours the same way).
///
/// **The colour order.** With `ContactOrder=Colours` (the default) a pass
/// solves colour 0, then colour 1, and so on, each colour's contacts in the
/// order they were found. Every colour is then a set of contacts that can be
/// solved at once: four at a time in SIMD lanes and, for a wide colour, on
/// several threads (src/fast/), with the numbers of this plain loop to the
/// last bit. With `ContactOrder=Found` a pass takes the contacts in the order
/// they were found; the fast path then finds far fewer contacts to solve at
/// once (a tower's contacts wait for each other one by one).
///
/// Reference: Catto, "Solver2D" and Box2D v3 (the constraint graph, 2024);
/// Tonge, "Iterative Rigid Body Solvers" (GDC 2012).
#pragma once

#include <cstdint>
#include <vector>

namespace stepwise {

struct SolverWorkspace;

/// More colours than a body's bit mask holds: the contacts that find no free colour among the first
/// kColourCount go to one last group, solved one after the other in their order.
inline constexpr std::uint32_t kColourCount = 64;

/// @brief Reorders @p list (indices into SolverWorkspace::contacts, in the order found) colour by
/// colour: greedy colouring in the list's order, each colour's contacts keeping that order.
///
/// The contacts that fit no colour (a body already in kColourCount colours) come last, in their
/// order. @p colourEnds gets where each colour's contacts end in the new list (colour k runs from
/// colourEnds[k − 1], or 0, to colourEnds[k]) and one more entry, the list's size: the fast path
/// batches the colours from there (contact_waves.hpp). Works on the workspace's scratch arrays and
/// @p colourEnds; allocates nothing once they have grown.
/// @return how many colours the list uses (the last group counted as one)
std::uint32_t orderByColour(SolverWorkspace& workspace, std::vector<std::uint32_t>& list,
                            std::vector<std::uint32_t>& colourEnds);

struct ContactWaveSchedule;

/// @brief Puts the contacts @p list (indices into SolverWorkspace::contacts, in their pass order) in
/// waves: each contact, in the list's order, takes the first wave after the latest wave of an earlier
/// contact on either of its bodies (the static record 0 does not count: nothing moves it),
/// \f[ w_c = \max\big(\text{next}(A_c),\ \text{next}(B_c)\big), \qquad
///     \text{next}(A_c) = \text{next}(B_c) = w_c + 1 . \f]
///
/// Two contacts of one wave never share a dynamic body, and every body meets its contacts wave by
/// wave in the list's order (list scheduling of the contacts' dependency graph; Tonge, "Iterative
/// Rigid Body Solvers", GDC 2012). So a pass that takes the list wave by wave, and the contacts of a
/// wave in any order or at once, computes the numbers of a pass in the list's order, to the last
/// bit. Unlike the colours, the waves keep *any* order: the order found too. Fills @p schedule
/// (its arrays keep their capacity). For a list in colour order the waves are its colours
/// (fast/contact_waves.hpp).
void scheduleWaves(const SolverWorkspace& workspace, const std::vector<std::uint32_t>& list,
                   ContactWaveSchedule& schedule);

}  // namespace stepwise
