/// @file impulse_resolver.cpp
/// @brief Stages 6 and 7: impulses at contact points, then position correction
/// (the derivations are in impulse_resolver.hpp).
#include "dynamics/impulse_resolver.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/contact_body.hpp"
#include "dynamics/inertia.hpp"
#include "integrators/integrators.hpp"

namespace stepwise {

namespace {

/// |n·x| above this means x is too close to n to build a tangent from.
constexpr Real kAlmostParallel = Real(0.57735);  // 1/√3: some axis always has |n_i| ≤ 1/√3

/// Two unit vectors that complete n to a right-handed orthonormal basis.
void tangentBasis(const Vec3& n, Vec3 (&t)[2]) {
    const Vec3 helper = std::abs(n.x) < kAlmostParallel ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    t[0] = glm::normalize(glm::cross(n, helper));
    t[1] = glm::cross(n, t[0]);
}

/// 1/m_eff along direction d: m_A⁻¹ + m_B⁻¹ + (r_A×d)·I_A⁻¹(r_A×d) + (r_B×d)·I_B⁻¹(r_B×d).
Real inverseEffectiveMass(const ContactConstraint& c, const Vec3& d) {
    const Vec3 turnA = glm::cross(c.rA, d);
    const Vec3 turnB = glm::cross(c.rB, d);
    return c.a->inverseMass + c.inverseMassB + glm::dot(turnA, c.inverseInertiaA * turnA) +
           glm::dot(turnB, c.inverseInertiaB * turnB);
}

/// Velocity of B's surface minus A's at the contact point.
Vec3 relativeVelocity(const ContactConstraint& c) {
    const Vec3 va = c.a->velocity + glm::cross(c.a->angularVelocity, c.rA);
    const Vec3 vb = c.b ? c.b->velocity + glm::cross(c.b->angularVelocity, c.rB) : c.staticVelocity;
    return vb - va;
}

/// Impulse P on B at the contact, −P on A: Δv = ±P/m, ΔL = ±r×P, Δω = I⁻¹ΔL.
/// (The world inverse inertia is fixed during the passes: nothing turns the
/// bodies until the next integration.)
void applyImpulse(ContactConstraint& c, const Vec3& P) {
    const Vec3 angularA = glm::cross(c.rA, P);
    c.a->velocity -= P * c.a->inverseMass;
    c.a->angularMomentum -= angularA;
    c.a->angularVelocity -= c.inverseInertiaA * angularA;
    if (c.b) {
        const Vec3 angularB = glm::cross(c.rB, P);
        c.b->velocity += P * c.inverseMassB;
        c.b->angularMomentum += angularB;
        c.b->angularVelocity += c.inverseInertiaB * angularB;
    }
}

/// Sets up one contact: lever arms, effective masses, and the bounce it aims for.
ContactConstraint prepare(const BodySet& bodies, const Contact& contact, Real h, ImpulseReport& report) {
    ContactConstraint c;
    DynamicObject& a = bodies.dynamics[contact.a];
    const ContactBody other = contactBody(bodies, contact.b, contact.point);
    c.a = &a;
    c.b = other.dynamic;
    c.staticVelocity = other.velocity;
    c.inverseInertiaA = worldInverseInertia(a.orientation, a.inverseInertiaBody);
    c.rA = contact.point - a.position;
    if (c.b) {
        c.inverseMassB = c.b->inverseMass;
        c.inverseInertiaB = worldInverseInertia(c.b->orientation, c.b->inverseInertiaBody);
        c.rB = contact.point - c.b->position;
    } else {
        c.inverseInertiaB = Mat3(0);
    }
    c.normal = contact.normal;
    tangentBasis(c.normal, c.tangent);
    c.normalMass = Real(1) / inverseEffectiveMass(c, c.normal);
    for (int k = 0; k < 2; ++k) c.tangentMass[k] = Real(1) / inverseEffectiveMass(c, c.tangent[k]);
    c.friction = combineFriction(a.friction, other.friction);

    // The bounce is decided once, from the velocities before any impulse:
    // restitution is a property of the impact, not of the passes.
    const Real vn = glm::dot(relativeVelocity(c), c.normal);
    const Real an = glm::dot(other.acceleration - a.acceleration, c.normal);
    const Real depth = std::max(contact.depth, Real(0));
    const Real approachAtTouch = vn < 0 ? std::sqrt(std::max(Real(0), vn * vn + Real(2) * an * depth)) : Real(0);
    c.resting = approachAtTouch <= kRestingContactSteps * std::abs(an) * h;
    const Real e = c.resting ? Real(0) : combineElasticity(a.elasticity, other.elasticity);
    c.targetSeparation = e * approachAtTouch;
    report = {std::max(-vn, Real(0)), approachAtTouch, e, 0, 0};
    return c;
}

/// One pass at one contact: the normal impulse, then friction within the new bound.
void solve(ContactConstraint& c) {
    // Normal: drive v_n to the target separation speed, keep the total j ≥ 0.
    const Real vn = glm::dot(relativeVelocity(c), c.normal);
    const Real previous = c.normalImpulse;
    c.normalImpulse = std::max(previous + c.normalMass * (c.targetSeparation - vn), Real(0));
    applyImpulse(c, (c.normalImpulse - previous) * c.normal);

    // Friction: recompute the relative velocity, because the normal impulse
    // just changed it; friction acts on what is left sliding, and its total
    // may not leave Coulomb's cone |j_t| ≤ μ·j.
    const Vec3 relative = relativeVelocity(c);
    const Real limit = c.friction * c.normalImpulse;
    Real total[2];
    for (int k = 0; k < 2; ++k) {
        total[k] = c.tangentImpulse[k] - c.tangentMass[k] * glm::dot(relative, c.tangent[k]);
    }
    const Real magnitude = std::sqrt(total[0] * total[0] + total[1] * total[1]);
    if (magnitude > limit) {  // sliding: kinetic friction at the full μ·j, along the sliding direction
        const Real scale = magnitude > 0 ? limit / magnitude : Real(0);
        total[0] *= scale;
        total[1] *= scale;
    }
    const Vec3 change = (total[0] - c.tangentImpulse[0]) * c.tangent[0] + (total[1] - c.tangentImpulse[1]) * c.tangent[1];
    c.tangentImpulse[0] = total[0];
    c.tangentImpulse[1] = total[1];
    applyImpulse(c, change);
}

}  // namespace

void resolveImpulses(const BodySet& bodies, std::span<const Contact> contacts, Real h, int iterations,
                     ContactWorkspace& workspace, std::span<ImpulseReport> reports) {
    std::vector<ContactConstraint>& constraints = workspace.constraints;
    constraints.resize(contacts.size());
    ImpulseReport unused;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        constraints[i] = prepare(bodies, contacts[i], h, reports.empty() ? unused : reports[i]);
    }
    for (int pass = 0; pass < iterations; ++pass) {
        for (ContactConstraint& c : constraints) solve(c);
    }
    // Angular momentum was updated alongside ω; refresh ω from L once so the
    // two stay exactly consistent (ω = I⁻¹L) for the next stage.
    for (ContactConstraint& c : constraints) {
        updateAngularVelocity(*c.a);
        if (c.b) updateAngularVelocity(*c.b);
    }

    // What the resting contacts did to each body, for stage 7: the velocity
    // change of their friction impulse P_t (along the surface), Δv = ±P_t/m,
    // and the spin change of their whole impulse P, Δω = ±I⁻¹(r × P).
    const std::size_t bodyCount = bodies.dynamics.size();
    workspace.supportVelocityChange.assign(bodyCount, Vec3(0));
    workspace.supportSpinChange.assign(bodyCount, Vec3(0));
    for (std::size_t i = 0; i < constraints.size(); ++i) {
        const ContactConstraint& c = constraints[i];
        if (!c.resting) continue;
        const Vec3 Pt = c.tangentImpulse[0] * c.tangent[0] + c.tangentImpulse[1] * c.tangent[1];
        const Vec3 P = c.normalImpulse * c.normal + Pt;
        workspace.supportVelocityChange[contacts[i].a] -= Pt * c.a->inverseMass;
        workspace.supportSpinChange[contacts[i].a] -= c.inverseInertiaA * glm::cross(c.rA, P);
        if (c.b) {
            workspace.supportVelocityChange[contacts[i].b.index] += Pt * c.inverseMassB;
            workspace.supportSpinChange[contacts[i].b.index] += c.inverseInertiaB * glm::cross(c.rB, P);
        }
    }
    if (!reports.empty()) {
        for (std::size_t i = 0; i < contacts.size(); ++i) {
            const ContactConstraint& c = constraints[i];
            reports[i].normalImpulse = c.normalImpulse;
            reports[i].frictionImpulse = std::hypot(c.tangentImpulse[0], c.tangentImpulse[1]);
        }
    }
}

void correctPositions(const BodySet& bodies, std::span<const Contact> contacts, Real supportStep,
                      ContactWorkspace& workspace) {
    std::vector<Vec3>& startPositions = workspace.startPositions;
    startPositions.resize(bodies.dynamics.size());
    for (std::size_t i = 0; i < bodies.dynamics.size(); ++i) startPositions[i] = bodies.dynamics[i].position;

    // Support: the displacement the integrator would have given the support force.
    if (workspace.supportVelocityChange.size() == bodies.dynamics.size()) {
        for (std::size_t i = 0; i < bodies.dynamics.size(); ++i) {
            DynamicObject& body = bodies.dynamics[i];
            body.position += supportStep * workspace.supportVelocityChange[i];
            const Vec3& spin = workspace.supportSpinChange[i];
            if (spin != Vec3(0)) {
                body.orientation = rotateByAngularVelocity(body.orientation, spin, supportStep);
                updateAngularVelocity(body);  // I_world turned with the body: ω = I_world⁻¹·L
            }
        }
    }

    // Overlap: whatever the support did not already remove.
    for (const Contact& contact : contacts) {
        DynamicObject& a = bodies.dynamics[contact.a];
        DynamicObject* b = contact.b.kind == BodyKind::Dynamic ? &bodies.dynamics[contact.b.index] : nullptr;
        const Vec3 movedA = a.position - startPositions[contact.a];
        const Vec3 movedB = b ? b->position - startPositions[contact.b.index] : Vec3(0);
        const Real remaining = contact.depth - glm::dot(movedB - movedA, contact.normal);
        if (remaining <= Real(0)) continue;

        const Real inverseMassB = b ? b->inverseMass : Real(0);
        const Vec3 push = contact.normal * (remaining / (a.inverseMass + inverseMassB));
        a.position -= push * a.inverseMass;
        if (b) b->position += push * inverseMassB;
    }
}

}  // namespace stepwise
