/// @file region.cpp
/// @brief Stage 1, effects of the regions: which bodies a region holds, and each effect's dispatch.
#include "forces/region.hpp"

#include <algorithm>

#include "forces/buoyancy.hpp"
#include "forces/drag.hpp"
#include "forces/random_force.hpp"
#include "forces/region_gravity.hpp"
#include "forces/wind.hpp"

namespace stepwise {

bool regionContains(const Region& region, const Vec3& p) {
    switch (region.shape) {
        case RegionShape::Box: {
            const Vec3 d = glm::abs(p - region.position);
            return d.x <= region.halfExtents.x && d.y <= region.halfExtents.y && d.z <= region.halfExtents.z;
        }
        case RegionShape::Sphere: {
            const Vec3 d = p - region.position;
            return glm::dot(d, d) <= region.radius * region.radius;
        }
        case RegionShape::HalfSpace: return glm::dot(p - region.position, region.normal) <= 0;
    }
    return false;
}

namespace {

/// Radius of a ball around the body's centre that holds all of it, m (spheres and boxes; buoyancy's shapes).
Real boundingRadius(const DynamicObject& body) {
    return body.shape == Shape::Box ? glm::length(body.halfExtents()) : body.radius;
}

/// Distance from @p p to the region's volume, m (0 inside).
Real distanceTo(const Region& region, const Vec3& p) {
    switch (region.shape) {
        case RegionShape::Box: {
            const Vec3 outside = glm::max(glm::abs(p - region.position) - region.halfExtents, Vec3(0));
            return glm::length(outside);
        }
        case RegionShape::Sphere: return std::max(Real(0), glm::length(p - region.position) - region.radius);
        case RegionShape::HalfSpace: return std::max(Real(0), glm::dot(p - region.position, region.normal));
    }
    return 0;
}

}  // namespace

bool regionHolds(const Region& region, const DynamicObject& body) {
    if (region.effect == RegionEffect::Buoyancy) return distanceTo(region, body.position) <= boundingRadius(body);
    return regionContains(region, body.position);
}

void regionBounds(const Region& region, Vec3& lowest, Vec3& highest) {
    switch (region.shape) {
        case RegionShape::Box:
            lowest = region.position - region.halfExtents;
            highest = region.position + region.halfExtents;
            return;
        case RegionShape::Sphere:
            lowest = region.position - Vec3(region.radius);
            highest = region.position + Vec3(region.radius);
            return;
        case RegionShape::HalfSpace:
            // Unbounded, except along an axis the plane faces squarely: below a floor-level plane
            // (normal +y), y ≤ the plane's height; otherwise all of space.
            lowest = Vec3(-kRegionFar);
            highest = Vec3(kRegionFar);
            for (int axis = 0; axis < 3; ++axis) {
                const Vec3 along = Vec3(axis == 0, axis == 1, axis == 2);
                if (region.normal == along) highest[axis] = region.position[axis];
                if (region.normal == -along) lowest[axis] = region.position[axis];
            }
            return;
    }
}

void applyRegions(std::span<DynamicObject> bodies, const RegionForces& in) {
    if (in.members == nullptr) return;
    for (std::size_t r = 0; r < in.regions.size(); ++r) {
        const Region& region = in.regions[r];
        if (region.effect == RegionEffect::Conveyor) continue;  // no force: it acts through the contacts (conveyor.hpp)
        for (const std::uint32_t i : in.members->of(r)) {
            DynamicObject& body = bodies[i];
            if (body.asleep) continue;  // a sleeper is not integrated: a force on it would wait in its acceleration
            switch (region.effect) {
                case RegionEffect::Drag: addDrag(body, region, region.velocity, Real(1), in.substepTime); break;
                case RegionEffect::Wind: addWind(body, region, in.substepTime); break;
                case RegionEffect::Gravity: addRegionGravity(body, region, in.worldGravity); break;
                case RegionEffect::Buoyancy: addBuoyancy(body, region, in.worldGravity, in.substepTime); break;
                case RegionEffect::RandomForce: addRandomForce(body, i, region, in.step); break;
                case RegionEffect::Kill: break;  // the World removes these bodies at the end of the step
                case RegionEffect::Conveyor: break;  // skipped above
            }
        }
    }
}

const char* toString(RegionEffect effect) {
    switch (effect) {
        case RegionEffect::Drag: return "Drag";
        case RegionEffect::Wind: return "Wind";
        case RegionEffect::Gravity: return "Gravity";
        case RegionEffect::Buoyancy: return "Buoyancy";
        case RegionEffect::RandomForce: return "RandomForce";
        case RegionEffect::Kill: return "Kill";
        case RegionEffect::Conveyor: return "Conveyor";
    }
    return "?";
}

}  // namespace stepwise
