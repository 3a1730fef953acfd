/// @file sphere_sphere.cpp
/// @brief Sphere against sphere: the distance between centres says it all.
///
/// Two spheres overlap when the distance between their centres is less than
/// the sum of their radii:
/// \f[ d = |c_B - c_A| < r_A + r_B, \qquad n = \frac{c_B - c_A}{d}, \qquad
///     \text{depth} = r_A + r_B - d. \f]
/// Reference: Ericson, *Real-Time Collision Detection*, §4.3.1.
#include <cmath>

#include "collision/narrowphase.hpp"

namespace stepwise {

/// Centres closer than this (m) have no usable direction between them.
constexpr Real kCoincidentCentres = Real(1e-12);

bool collideSphereSphere(const Geometry& a, const Geometry& b, ContactManifold& out) {
    const Vec3 between = b.centre - a.centre;
    const Real radii = a.radius + b.radius;
    // Compare squared lengths first: no square root for the many pairs that miss.
    const Real reach = radii + kTouchTolerance;
    const Real distanceSquared = glm::dot(between, between);
    if (distanceSquared > reach * reach) return false;

    const Real distance = std::sqrt(distanceSquared);
    // Concentric spheres: any direction separates them; pick world up so the
    // result is repeatable.
    out.normal = distance > kCoincidentCentres ? between / distance : Vec3(0, 1, 0);
    const Real depth = radii - distance;
    out.pointCount = 0;
    out.add(a.centre + out.normal * (a.radius - Real(0.5) * depth), depth, 0);
    return true;
}

}  // namespace stepwise
