/// @file picking.hpp
/// @brief Which body is under the mouse: ray casts against spheres, oriented boxes and planes.
///
/// The viewer's own ray tests, kept here (plain maths, no OpenGL) until the
/// engine gets `World::raycast` (issue 6); then picking should call that.
/// Both tests return the smallest s ≥ 0 at which origin + s·direction enters
/// the shape; a ray that starts inside a shape hits it at s = 0.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "viewer/camera.hpp"

namespace stepwise::viewer {

/// @brief |cos| of the angle between a ray and a slab's or plane's normal below which the ray counts as parallel to it.
inline constexpr Real kParallelCosine = Real(1e-12);

/// @brief Where a ray first meets a sphere of @p radius at @p centre, as the ray parameter s; nothing if it misses.
///
/// With m = origin − centre and a unit direction d, the points at distance r
/// from the centre solve s² + 2(m·d)s + (m·m − r²) = 0; the hit is the
/// smaller root, or 0 when the origin is already inside (Ericson, *Real-Time
/// Collision Detection*, §5.3.2).
inline std::optional<Real> raySphere(const Ray& ray, const Vec3& centre, Real radius) {
    const Vec3 m = ray.origin - centre;
    const Real b = glm::dot(m, ray.direction);
    const Real c = glm::dot(m, m) - radius * radius;
    if (c <= 0) return Real(0);     // inside
    if (b > 0) return std::nullopt; // outside and pointing away
    const Real discriminant = b * b - c;
    if (discriminant < 0) return std::nullopt;
    return -b - std::sqrt(discriminant);
}

/// @brief Where a ray first meets an oriented box, as the ray parameter s; nothing if it misses.
///
/// The slab test (Ericson, *Real-Time Collision Detection*, §5.3.3) in the
/// box's own frame: rotate the ray into it with the inverse orientation, then
/// intersect the three slabs |x_i| ≤ h_i; the ray is inside the box where it
/// is inside all three, between the largest entry and the smallest exit.
inline std::optional<Real> rayBox(const Ray& ray, const Vec3& centre, const Quat& orientation,
                                  const Vec3& halfExtents) {
    const Quat toBody = glm::conjugate(orientation);
    const Vec3 origin = toBody * (ray.origin - centre);
    const Vec3 direction = toBody * ray.direction;
    Real enter = 0;
    Real exit = std::numeric_limits<Real>::max();
    for (int i = 0; i < 3; ++i) {
        if (std::abs(direction[i]) < kParallelCosine) {
            if (std::abs(origin[i]) > halfExtents[i]) return std::nullopt;  // parallel and outside the slab
            continue;
        }
        Real s1 = (-halfExtents[i] - origin[i]) / direction[i];
        Real s2 = (halfExtents[i] - origin[i]) / direction[i];
        if (s1 > s2) std::swap(s1, s2);
        enter = std::max(enter, s1);
        exit = std::min(exit, s2);
        if (enter > exit) return std::nullopt;
    }
    return enter;
}

/// @brief Where a ray crosses the plane through @p point with unit normal @p normal, as the ray parameter s; nothing
/// if it runs parallel to the plane or away from it.
///
/// The plane's points q satisfy n·(q − p₀) = 0; on the ray q = o + s·d, so
/// \f[ s = \frac{n \cdot (p_0 - o)}{n \cdot d}. \f]
/// A collision plane is the boundary of a solid half-space, but the viewer
/// draws it as a surface seen from both sides, so the ray may cross it from
/// either side (Ericson, *Real-Time Collision Detection*, §5.3.1).
inline std::optional<Real> rayPlane(const Ray& ray, const Vec3& point, const Vec3& normal) {
    const Real approach = glm::dot(normal, ray.direction);
    if (std::abs(approach) < kParallelCosine) return std::nullopt;
    const Real s = glm::dot(normal, point - ray.origin) / approach;
    if (s < 0) return std::nullopt;
    return s;
}

/// @brief What a ray hits first: a body, or a plane in front of every body.
struct PickHit {
    BodyKind kind = BodyKind::Dynamic;  ///< Dynamic, Kinematic, or Plane (a plane hides what is behind it).
    std::uint32_t index = 0;            ///< Index in the World's array of that kind.
    Real distance = 0;                  ///< Ray parameter of the hit, m along the ray.
    Vec3 point{0, 0, 0};                ///< World-space hit point, m.
};

/// @brief The nearest dynamic body, kinematic body or plane along @p ray, or nothing.
///
/// Planes take part so that a body hidden below the floor cannot be picked
/// through it: when a plane is nearest, the hit is the plane (which the
/// viewer neither highlights nor pushes). The test is a linear scan over
/// every object, fine for the tens of bodies of a teaching scene.
inline std::optional<PickHit> pickBody(const World& world, const Ray& ray) {
    std::optional<PickHit> best;
    auto keep = [&](BodyKind kind, std::size_t index, const std::optional<Real>& s) {
        if (s && (!best || *s < best->distance)) {
            best = PickHit{kind, static_cast<std::uint32_t>(index), *s, ray.origin + *s * ray.direction};
        }
    };
    auto consider = [&](BodyKind kind, std::size_t index, const auto& body) {
        keep(kind, index,
             body.shape == Shape::Sphere ? raySphere(ray, body.position, body.radius)
                                         : rayBox(ray, body.position, body.orientation, body.halfExtents()));
    };
    for (std::size_t i = 0; i < world.dynamics().size(); ++i) consider(BodyKind::Dynamic, i, world.dynamics()[i]);
    for (std::size_t i = 0; i < world.kinematics().size(); ++i) {
        consider(BodyKind::Kinematic, i, world.kinematics()[i]);
    }
    for (std::size_t i = 0; i < world.planes().size(); ++i) {
        keep(BodyKind::Plane, i, rayPlane(ray, world.planes()[i].position, world.planes()[i].normal));
    }
    return best;
}

}  // namespace stepwise::viewer
