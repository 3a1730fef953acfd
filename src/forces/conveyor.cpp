/// @file conveyor.cpp
/// @brief Effect=Conveyor: the surface under a body moves at v_s = u − (u·n)·n (the law is in conveyor.hpp).
#include "forces/conveyor.hpp"

#include <algorithm>

namespace stepwise {

Vec3 conveyorSurfaceVelocity(const Vec3& belt, const Vec3& normal) {
    return belt - glm::dot(belt, normal) * normal;  // a belt slides along itself: no part along n
}

bool anyConveyor(std::span<const Region> regions) {
    return std::any_of(regions.begin(), regions.end(), [](const Region& r) { return r.effect == RegionEffect::Conveyor; });
}

void conveyorVelocities(std::span<const Region> regions, const RegionMembers& members, std::size_t bodyCount,
                        std::vector<Vec3>& velocities) {
    velocities.assign(bodyCount, Vec3(0));  // no allocation once the array has grown to the scene's bodies
    // From the last region to the first, so that where two belts overlap the first one's velocity stays
    for (std::size_t r = regions.size(); r-- > 0;) {
        if (regions[r].effect != RegionEffect::Conveyor) continue;
        for (const std::uint32_t i : members.of(r)) velocities[i] = regions[r].velocity;
    }
}

}  // namespace stepwise
