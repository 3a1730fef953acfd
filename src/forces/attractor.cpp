/// @file attractor.cpp
/// @brief Stage 1, central forces: Newton's inverse-square pull towards fixed points.
///
/// With r = x − p from the attractor to the body and r = |r|,
/// \f[ a = -\frac{\mu}{r^2}\,\hat r = -\frac{\mu}{r^3}\,\mathbf r \qquad (r \ge r_c), \qquad
///     a = -\frac{\mu}{r_c^3}\,\mathbf r \qquad (r < r_c). \f]
/// The mass of the body cancels, as for uniform gravity: F = −G·M·m·r̂/r² and
/// a = F/m. Inside the core radius r_c (kAttractorCoreRadius) the attractor
/// is a uniform ball, whose field grows linearly from the centre.
#include "forces/attractor.hpp"

#include <algorithm>

namespace stepwise {

Vec3 attractorAcceleration(const Attractor& attractor, const Vec3& point) {
    const Vec3 r = point - attractor.position;
    const Real distance = std::max(glm::length(r), kAttractorCoreRadius);
    return -attractor.mu / (distance * distance * distance) * r;
}

void applyAttractors(std::span<DynamicObject> bodies, std::span<const Attractor> attractors) {
    for (const Attractor& attractor : attractors) {
        for (DynamicObject& body : bodies) body.acceleration += attractorAcceleration(attractor, body.position);
    }
}

Real attractorPotentialEnergy(const Attractor& attractor, Real mass, const Vec3& point) {
    const Real r = glm::length(point - attractor.position);
    if (r >= kAttractorCoreRadius) return -attractor.mu * mass / r;
    const Real rc = kAttractorCoreRadius;
    return -attractor.mu * mass * (3 * rc * rc - r * r) / (2 * rc * rc * rc);
}

}  // namespace stepwise
