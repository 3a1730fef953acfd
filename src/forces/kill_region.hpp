/// @file kill_region.hpp
/// @brief Kill regions (Effect=Kill): the floor under a level that catches what falls off it.
///
/// A body whose centre is inside a Kill region at the end of a step is taken
/// out of the world, with its springs and joints, and the run's summary lists
/// it with the time it left. Without one, a ball that falls off the edge of a
/// level falls for ever, costing a body's work every step and, far enough
/// out, losing the precision of its position (a double's spacing at 10¹² m is
/// 0.1 mm).
///
/// Removal happens at the end of the step, after the bodies have moved: the
/// step the centre crosses into the region is the step the body goes. The
/// World finds the candidates through its broadphase, with the region's box
/// widened by the farthest any body can move in the step (killCandidatesReach()),
/// then tests each centre exactly (regionContains()).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "forces/region.hpp"

namespace stepwise {

/// @brief A body a Kill region removed: the run's summary lists them.
struct RemovedBody {
    std::string name;    ///< The body's name.
    std::string region;  ///< The Kill region that took it.
    Real time = 0;       ///< Simulated time at the end of the step it was removed in, s.
    Vec3 position{0, 0, 0};  ///< Where its centre was, m.
};

/// @brief True when any of @p regions is a Kill region.
bool anyKillRegion(std::span<const Region> regions);

}  // namespace stepwise
