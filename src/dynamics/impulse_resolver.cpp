/// @file impulse_resolver.cpp
/// @brief Stage 6: normal and friction impulses at each contact (see impulse_resolver.hpp for the derivation).
#include "dynamics/impulse_resolver.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/contact_body.hpp"

namespace stepwise {

/// Tangential speeds below this (m/s) have no direction worth rubbing along.
constexpr Real kNegligibleSlidingSpeed = Real(1e-12);

void resolveImpulses(const BodySet& bodies, std::span<const Contact> contacts, Real h,
                     std::span<ImpulseReport> reports) {
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        const Contact& contact = contacts[c];
        DynamicObject& a = bodies.dynamics[contact.a];
        ContactBody b = contactBody(bodies, contact.b, contact.point);
        const Vec3& n = contact.normal;
        const Real inverseMassSum = a.inverseMass + b.inverseMass;

        // --- Normal impulse: stop the approach, then bounce with restitution.
        const Real vn = glm::dot(b.velocity - a.velocity, n);
        if (vn >= Real(0)) continue;  // already separating: nothing to stop

        const Real an = glm::dot(b.acceleration - a.acceleration, n);
        const Real depth = std::max(contact.depth, Real(0));
        const Real approachAtTouch = std::sqrt(std::max(Real(0), vn * vn + Real(2) * an * depth));
        const bool resting = approachAtTouch <= kRestingContactSteps * std::abs(an) * h;
        const Real e = resting ? Real(0) : combineElasticity(a.elasticity, b.elasticity);

        const Real j = (e * approachAtTouch - vn) / inverseMassSum;
        a.velocity -= j * a.inverseMass * n;
        b.applyImpulse(j * n);

        // --- Friction: recompute the relative velocity, because the normal
        // impulse just changed it; friction acts on what is left sliding.
        const Vec3 relative = b.velocity - a.velocity;
        const Vec3 sliding = relative - glm::dot(relative, n) * n;
        const Real slidingSpeed = glm::length(sliding);
        Real jt = 0;
        if (slidingSpeed > kNegligibleSlidingSpeed) {
            const Vec3 tangent = sliding / slidingSpeed;
            const Real stopSliding = slidingSpeed / inverseMassSum;  // impulse that would stop it
            const Real mu = combineFriction(a.friction, b.friction);
            jt = std::min(stopSliding, mu * j);  // Coulomb: |j_t| ≤ μ·j_n
            a.velocity += jt * a.inverseMass * tangent;  // A is dragged along B's motion
            b.applyImpulse(-jt * tangent);
        }

        if (!reports.empty()) reports[c] = {-vn, approachAtTouch, e, j, jt};
    }
}

void correctPositions(const BodySet& bodies, std::span<const Contact> contacts) {
    for (const Contact& contact : contacts) {
        if (contact.depth <= Real(0)) continue;
        DynamicObject& a = bodies.dynamics[contact.a];
        DynamicObject* b = contact.b.kind == BodyKind::Dynamic ? &bodies.dynamics[contact.b.index] : nullptr;
        const Real inverseMassB = b ? b->inverseMass : Real(0);
        const Vec3 push = contact.normal * (contact.depth / (a.inverseMass + inverseMassB));
        a.position -= push * a.inverseMass;
        if (b) b->position += push * inverseMassB;
    }
}

}  // namespace stepwise
