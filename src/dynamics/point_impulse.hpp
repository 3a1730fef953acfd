/// @file point_impulse.hpp
/// @brief The three formulas every impulse at a point uses, shared by both contact solvers.
///
/// Both the pairwise resolver (impulse_resolver.cpp) and the sequential-impulse
/// contacts (contact_solver.hpp) describe a contact point by the same fields:
/// dynamic body A (`a`), body B when dynamic (`b`, else nullptr, with
/// `staticVelocity` the velocity of B's surface), lever arms `rA`, `rB`,
/// inverse masses `inverseMassA`, `inverseMassB` and world inverse inertias
/// `inverseInertiaA`, `inverseInertiaB` (zero for a static B).
#pragma once

#include "objects/game_object.hpp"

namespace stepwise {

/// @brief 1/m_eff along unit direction d at the point: the J·M⁻¹·Jᵀ of a one-row constraint,
/// \f$ m_A^{-1} + m_B^{-1} + (r_A\times d)\cdot I_A^{-1}(r_A\times d) + (r_B\times d)\cdot I_B^{-1}(r_B\times d) \f$.
template <class Point>
Real inverseEffectiveMass(const Point& c, const Vec3& d) {
    const Vec3 turnA = glm::cross(c.rA, d);
    const Vec3 turnB = glm::cross(c.rB, d);
    return c.inverseMassA + c.inverseMassB + glm::dot(turnA, c.inverseInertiaA * turnA) +
           glm::dot(turnB, c.inverseInertiaB * turnB);
}

/// @brief Velocity of B's surface minus A's at the point: (v_B + ω_B×r_B) − (v_A + ω_A×r_A), m/s.
template <class Point>
Vec3 relativeVelocity(const Point& c) {
    const Vec3 va = c.a->velocity + glm::cross(c.a->angularVelocity, c.rA);
    const Vec3 vb = c.b ? c.b->velocity + glm::cross(c.b->angularVelocity, c.rB) : c.staticVelocity;
    return vb - va;
}

/// @brief Impulse P on B at the point and −P on A: Δv = ±P/m, ΔL = ±r×P, Δω = I⁻¹·ΔL.
///
/// L is the bodies' state and ω follows it: both change together here, with
/// the inverse inertia the caller fixed for the step (nothing turns the
/// bodies while impulses are being exchanged).
template <class Point>
void applyImpulse(Point& c, const Vec3& P) {
    const Vec3 angularA = glm::cross(c.rA, P);
    c.a->velocity -= P * c.inverseMassA;
    c.a->angularMomentum -= angularA;
    c.a->angularVelocity -= c.inverseInertiaA * angularA;
    if (c.b) {
        const Vec3 angularB = glm::cross(c.rB, P);
        c.b->velocity += P * c.inverseMassB;
        c.b->angularMomentum += angularB;
        c.b->angularVelocity += c.inverseInertiaB * angularB;
    }
}

}  // namespace stepwise
