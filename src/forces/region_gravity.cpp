/// @file region_gravity.cpp
/// @brief Effect=Gravity: a += g_region − g_world.
#include "forces/region_gravity.hpp"

namespace stepwise {

void addRegionGravity(DynamicObject& body, const Region& region, const Vec3& worldGravity) {
    body.acceleration += region.gravity - worldGravity;  // applyUniformForces() added g_world
}

}  // namespace stepwise
