/// @file spring_forces.cpp
/// @brief Soft step, stage 1: the springs along the mesh edges (and across them, for bending).
///
/// The model is src/forces/spring.cpp's, between two point masses: with
/// d = x_b − x_a, l = |d| and n = d / l,
/// \f[ F_a = \big(k\,(l - L_0) + c\,(v_b - v_a)\cdot n\big)\,n, \qquad F_b = -F_a . \f]
/// Hooke's term pulls a stretched spring together and pushes a compressed
/// one apart; the damper resists the rate l̇ at which the nodes separate,
/// and only that: two nodes moving together, or turning about each other,
/// feel no damping, so a spinning ball is not slowed by its own springs.
/// The two forces are equal, opposite and on the line through the nodes,
/// so the springs change neither the total momentum nor the total angular
/// momentum of the body.
///
/// Everything is read from the nodes' current state, so velocity Verlet can
/// evaluate the forces a second time at the new positions
/// (integrate_nodes.cpp), as it does for rigid springs.
#include <cmath>

#include "soft/soft_stages.hpp"

namespace stepwise {

namespace {

/// Below this length, m, a spring has no direction to pull along: it gives no force rather than divide by 0.
constexpr Real kShortestSpring = Real(1e-12);

}  // namespace

void clearNodeForces(SoftBody& body) {
    for (Vec3& force : body.nodeForces) force = Vec3(0);
}

void addSpringForces(SoftBody& body) {
    const std::vector<Vec3>& x = body.nodePositions;
    const std::vector<Vec3>& v = body.nodeVelocities;
    std::vector<Vec3>& force = body.nodeForces;
    for (const SoftSpring& spring : body.springs) {
        const Vec3 d = x[spring.b] - x[spring.a];
        const Real length = glm::length(d);
        if (length < kShortestSpring) continue;
        const Vec3 n = d / length;
        const Real stretchRate = glm::dot(v[spring.b] - v[spring.a], n);  // l̇, m/s: > 0 while they separate
        const Vec3 onA = (spring.stiffness * (length - spring.restLength) + spring.damping * stretchRate) * n;
        force[spring.a] += onA;
        force[spring.b] -= onA;  // Newton's third law
    }
}

}  // namespace stepwise
