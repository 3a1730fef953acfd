/// @file picking.hpp
/// @brief Which body is under the mouse: the ray through the cursor's pixel, cast with World::raycast.
///
/// The viewer has no ray tests of its own: it asks the engine's
/// World::raycast (src/world/world_raycast.cpp; the ray tests of
/// src/collision/raycast.cpp for every shape, Ericson, *Real-Time Collision
/// Detection*, §5.3), which tests every dynamic body, kinematic body and
/// plane and returns the nearest hit with its point and normal. Planes take
/// part, so a body below the floor cannot be picked through it; the viewer
/// neither highlights nor pushes a plane. A ray that starts behind a plane
/// (a camera below the floor) meets it at distance 0, so from down there
/// nothing is picked: the floor, drawn two-sided, hides the scene anyway.
#pragma once

#include <limits>
#include <optional>

#include "viewer/camera.hpp"
#include "world/world.hpp"

namespace stepwise::viewer {

/// @brief How far along the mouse ray picking looks, m: without limit, as far as the view reaches.
inline constexpr Real kPickReach = std::numeric_limits<Real>::infinity();

/// @brief The nearest dynamic body, kinematic body or plane along @p ray (unit direction), or nothing.
inline std::optional<RayHit> pickBody(const World& world, const Ray& ray) {
    return world.raycast(ray.origin, ray.direction, kPickReach);
}

}  // namespace stepwise::viewer
