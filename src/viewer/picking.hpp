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
///
/// With spaces, the ray is cast into every space's World, moved into that
/// space's own coordinates (minus its SpaceLayout offset), and the nearest
/// hit of them all wins: the body under the cursor, in whichever space. Side
/// by side, a space's planes are drawn only across its band of x, so a plane
/// hit outside that band does not count: the floor under the cursor is the
/// floor of the space drawn there.
#pragma once

#include <limits>
#include <optional>

#include "viewer/camera.hpp"
#include "viewer/simulation.hpp"
#include "world/world.hpp"

namespace stepwise::viewer {

/// @brief How far along the mouse ray picking looks, m: without limit, as far as the view reaches.
inline constexpr Real kPickReach = std::numeric_limits<Real>::infinity();

/// @brief The nearest dynamic body, kinematic body or plane along @p ray (unit direction), or nothing.
inline std::optional<RayHit> pickBody(const World& world, const Ray& ray) {
    return world.raycast(ray.origin, ray.direction, kPickReach);
}

/// @brief A pick in a Simulation: the hit, in its space's own coordinates, and which space.
struct SpaceHit {
    std::size_t space = 0;  ///< Index of the space (0 for a scene without spaces).
    RayHit hit;             ///< The body, and the point and normal in the space's coordinates.
};

/// @brief The nearest body or plane along @p ray among every World of @p simulation, as drawn.
inline std::optional<SpaceHit> pickInSimulation(const Simulation& simulation, const Ray& ray) {
    if (!simulation.hasSpaces()) {
        const std::optional<RayHit> hit = pickBody(simulation.world(), ray);
        if (!hit) return std::nullopt;
        return SpaceHit{0, *hit};
    }
    std::optional<SpaceHit> nearest;
    const SpaceLayout& layout = simulation.layout();
    for (std::size_t k = 0; k < simulation.worldCount(); ++k) {
        const Ray own{ray.origin - layout.offset(k), ray.direction};
        const std::optional<RayHit> hit = pickBody(simulation.worldAt(k), own);
        if (!hit) continue;
        const auto [low, high] = layout.band(k);
        if (hit->body.kind == BodyKind::Plane && (hit->point.x < low || hit->point.x > high)) continue;
        if (!nearest || hit->distance < nearest->hit.distance) nearest = SpaceHit{k, *hit};
    }
    return nearest;
}

}  // namespace stepwise::viewer
