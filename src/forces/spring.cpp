/// @file spring.cpp
/// @brief Stage 1, springs: Hooke's law plus a damper, applied at the anchor points.
///
/// For each spring, with p_A, p_B its anchors in the world,
/// \f[ d = p_B - p_A, \quad l = |d|, \quad n = d / l, \quad
///     \dot l = (v_B - v_A)\cdot n, \quad
///     F_A = \big(k\,(l - L_0) + c\,\dot l\big)\,n, \quad F_B = -F_A . \f]
/// k·(l − L₀) is Hooke's law along the spring; c·l̇ is a dashpot that
/// resists stretching and shortening. Both act along n, so the pair of forces
/// is equal, opposite and on one line: the spring moves neither the total
/// momentum nor the total angular momentum of the bodies it joins.
///
/// A force F at a point r from a body's centre of mass both accelerates the
/// centre, a = F/m, and turns the body, τ = r × F (Millington §10.3). This is
/// the rotational half that a spring hooked to the corner of a box needs.
///
/// Every quantity here is read from the bodies' *current* state. That is what
/// lets velocity Verlet call the same force function a second time at the new
/// positions (verlet.cpp): a spring's force depends on where the bodies are.
/// Under Verlet the damper sees the velocity after the first half kick,
/// v_n + ½h·a_n, since v_{n+1} is not known yet.
#include "forces/spring.hpp"

#include <cmath>

#include "objects/inertia.hpp"

namespace stepwise {

namespace {

/// Velocity of the world point @p point if it is carried by @p body, else 0 for a fixed end.
Vec3 anchorVelocity(std::span<const DynamicObject> bodies, std::size_t index, const Vec3& point) {
    return index == kFixedInWorld ? Vec3(0) : velocityAt(bodies[index], point);
}

/// 1/m + (r×n)·I_world⁻¹·(r×n): how freely the body's point at r moves along n under a push along n.
Real inverseMassAlong(const DynamicObject& body, const Vec3& r, const Vec3& n) {
    const Vec3 rn = glm::cross(r, n);
    return body.inverseMass + glm::dot(rn, worldInverseInertia(body.orientation, body.inverseInertiaBody) * rn);
}

}  // namespace

SpringEnds springEnds(const Spring& spring, std::span<const DynamicObject> bodies) {
    SpringEnds ends;
    ends.a = anchorInWorld(bodies[spring.bodyA], spring.anchorA);
    ends.b = spring.bodyB == kFixedInWorld ? spring.anchorB : anchorInWorld(bodies[spring.bodyB], spring.anchorB);
    return ends;
}

void applySprings(std::span<DynamicObject> bodies, std::span<const Spring> springs) {
    for (const Spring& spring : springs) {
        const SpringEnds ends = springEnds(spring, bodies);
        const Vec3 d = ends.b - ends.a;
        const Real length = glm::length(d);
        if (length < kMinSpringLength) continue;  // no line to pull along (and k·(l − L₀)·n would divide by 0)
        const Vec3 n = d / length;

        const Vec3 relativeVelocity = anchorVelocity(bodies, spring.bodyB, ends.b) - anchorVelocity(bodies, spring.bodyA, ends.a);
        const Real stretchRate = glm::dot(relativeVelocity, n);  // l̇, m/s: > 0 while the anchors separate
        const Vec3 forceOnA = (spring.stiffness * (length - spring.restLength) + spring.damping * stretchRate) * n;

        DynamicObject& a = bodies[spring.bodyA];
        a.acceleration += forceOnA * a.inverseMass;
        a.torque += glm::cross(ends.a - a.position, forceOnA);
        if (spring.bodyB != kFixedInWorld) {
            DynamicObject& b = bodies[spring.bodyB];
            b.acceleration -= forceOnA * b.inverseMass;  // Newton's third law: F_B = −F_A
            b.torque -= glm::cross(ends.b - b.position, forceOnA);
        }
    }
}

Real springPotentialEnergy(const Spring& spring, std::span<const DynamicObject> bodies) {
    const SpringEnds ends = springEnds(spring, bodies);
    const Real stretch = glm::length(ends.b - ends.a) - spring.restLength;
    return Real(0.5) * spring.stiffness * stretch * stretch;
}

Real springEffectiveMass(const Spring& spring, std::span<const DynamicObject> bodies) {
    const SpringEnds ends = springEnds(spring, bodies);
    const Vec3 d = ends.b - ends.a;
    const Real length = glm::length(d);
    const Vec3 n = length < kMinSpringLength ? Vec3(1, 0, 0) : d / length;

    const DynamicObject& a = bodies[spring.bodyA];
    Real inverseMass = inverseMassAlong(a, ends.a - a.position, n);
    if (spring.bodyB != kFixedInWorld) {
        const DynamicObject& b = bodies[spring.bodyB];
        inverseMass += inverseMassAlong(b, ends.b - b.position, n);
    }
    return Real(1) / inverseMass;
}

}  // namespace stepwise
