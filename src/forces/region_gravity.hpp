/// @file region_gravity.hpp
/// @brief A region with its own gravity (Effect=Gravity): a low-gravity room, an updraft, a ceiling walk.
///
/// Inside, a body falls with the region's acceleration g_r instead of the
/// World's g. Gravity is uniform, so it acts at the centre of mass and has no
/// torque (apply_forces.hpp); all that changes is a = g_r + a_obj. Where two
/// Gravity regions overlap, each replaces the World's g by its own, and the
/// two changes add: a = g + (g_r1 − g) + (g_r2 − g).
#pragma once

#include "forces/region.hpp"

namespace stepwise {

/// @brief Replaces the World's gravity @p worldGravity by the region's in @p body's acceleration.
void addRegionGravity(DynamicObject& body, const Region& region, const Vec3& worldGravity);

}  // namespace stepwise
