/// @file contact_waves.hpp
/// @brief Contacts put in waves of contacts that share no dynamic body, each body meeting its contacts in their order.
///
/// Gauss–Seidel solves contacts one after the other, each reading the
/// velocities the earlier ones left; but two contacts that share no dynamic
/// body do not read each other's results, so they may be solved at once in
/// SIMD lanes (lanes.hpp) with the same numbers to the last bit. The waves of
/// a list (scheduleWaves(), dynamics/contact_colours.hpp) are such sets: each
/// contact takes the first wave after the latest wave of an earlier contact on
/// either of its bodies, so no wave holds a body twice and every body meets its
/// contacts in the list's order.
///
/// How wide the waves are depends on the scene: a heap of balls gives waves of
/// dozens, a tower of boxes a chain whose every contact waits for the one
/// before (its waves hold one contact each).
///
/// **In colour order the waves are known.** A list that orderByColour() has put
/// colour by colour (`ContactOrder=Colours`) has the colours for its waves,
/// contact for contact: a contact of colour k waits for one of colour k − 1 on
/// one of its bodies, and for none of a higher colour (contact_colours.hpp;
/// lecture appendix 8a, section 6, proves it). So contactWaves() takes the
/// colours as they are and schedules only a list in the order found, or one
/// with contacts that found no colour (the last group, which may hold a body
/// twice).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace stepwise {

struct SolverWorkspace;
struct FastWorkspace;

/// @brief A list of contacts in waves: wave w is order[ends[w − 1] (or 0) … ends[w]).
struct ContactWaves {
    std::span<const std::uint32_t> order;  ///< The contacts (indices in SolverWorkspace::contacts), wave by wave.
    std::span<const std::uint32_t> ends;   ///< Per wave: where its contacts end in `order`.
};

/// @brief The waves of @p list (in its pass order): its colours when @p colourEnds gives them
/// (orderByColour(); empty when the list is as found) and every contact found a colour; otherwise
/// scheduleWaves(). Sets FastWorkspace::waves either way. The spans point into @p list and
/// @p colourEnds, or into @p fast's scratch: valid until either changes.
ContactWaves contactWaves(const SolverWorkspace& solver, const std::vector<std::uint32_t>& list,
                          const std::vector<std::uint32_t>& colourEnds, FastWorkspace& fast);

}  // namespace stepwise
