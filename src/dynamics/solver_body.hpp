/// @file solver_body.hpp
/// @brief The sequential-impulse contact solver's view of a body: a small record in one contiguous array.
///
/// **Why a separate array.** A contact pass touches, for every contact point,
/// the velocity, angular velocity and inverse mass of both bodies. A
/// DynamicObject holds those among some thirty other fields (name, colour,
/// shape, forces, sleep state…), so reading them through the object costs
/// several cache lines per body. Catto's Box2D v3 solves on *solver bodies*
/// instead: the solver copies what it needs of each body it touches into a
/// packed array before a run of passes (gather: copyVelocitiesIn() in
/// contact_solver.hpp), the contacts refer to those records by a 32-bit
/// index, and the velocities are written back after it (scatter:
/// copyVelocitiesOut()), once per solve and once per relax stage when the
/// scene has no joints. The world inverse inertia I⁻¹ = R·I_body⁻¹·Rᵀ is computed
/// once per body per step (the solver holds it fixed through the step, see
/// point_impulse.hpp) and goes into the contacts' rows (ContactRow below),
/// not into the record a pass reads.
///
/// Only bodies that are in a contact or a joint get a record, numbered in the order of
/// the World's dynamic array, so that the copies in and out walk the objects
/// front to back. Record 0 is the *static body*: B of a contact with a
/// plane or a kinematic body. It has m⁻¹ = 0 and I⁻¹ = 0, so an impulse does
/// not move it, and its velocity stays zero; the velocity of a moving kinematic
/// surface is kept in the contact's stored rows (ContactRows::normalSurfaceSpeed and
/// tangentSurfaceSpeed). With it, a contact pass needs no test "is B
/// dynamic?" per contact.
///
/// The formulas are those of point_impulse.hpp, written per row of the
/// Jacobian (ContactRow below) so that what is fixed through the step is
/// computed once.
///
/// Reference: Catto, Box2D v3 `solver.h` (b2BodyState, b2BodySim), 2024.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace stepwise {

/// @brief Record 0 of the solver-body array: the immovable B of a contact with a plane or kinematic body.
inline constexpr std::uint32_t kStaticSolverBody = 0;

/// @brief Bytes a SolverBody is aligned to: its own size, eight Reals (64 bytes, one x86-64 cache line, in double).
inline constexpr std::size_t kSolverBodyAlignment = 8 * sizeof(Real);

/// @brief What a contact pass reads and writes of one dynamic body: 64 bytes, one cache line.
///
/// A pass copies both records of a contact into local variables, solves the
/// contact's three rows on the copies, and stores them back once. The copies
/// cannot alias anything else, so the compiler keeps them in registers
/// instead of storing and reloading a body after every row.
///
/// Aligned to its size, so that a record is one cache line and not two halves of
/// two: a record that straddles two lines costs two fetches from memory
/// whenever a pass touches its body, once the records outgrow the caches.
struct alignas(kSolverBodyAlignment) SolverBody {
    Vec3 velocity{0, 0, 0};         ///< Linear velocity of the centre of mass, m/s.
    Vec3 angularVelocity{0, 0, 0};  ///< Angular velocity, world frame, rad/s.
    Real inverseMass = 0;           ///< 1/m, 1/kg (zero: static).
    /// A ball's I⁻¹, the same about every axis, 1/(kg·m²): what a *round*
    /// contact's friction turns it by (applyRoundFrictionImpulse() below). Zero for a box,
    /// whose contacts keep their turn per unit impulse in stored rows.
    Real inverseInertia = 0;
};

/// @brief What only prepare and a box's write-back read of a body: its inertia for the step.
///
/// The pass changes ω only. The angular momentum follows at the write-back,
/// ΔL = I_world·Δω (with the same world tensor the pass used), once per body
/// instead of once per row of every contact. A ball's I is one number, kept in
/// a small array of its own (SolverWorkspace::ballInertia), so its write-back
/// never reads these 144 bytes: it writes L = I·ω.
struct SolverBodyInertia {
    Mat3 inverseInertia{0};  ///< World I⁻¹ at the start of the step, 1/(kg·m²) (zero: static).
    Mat3 inertia{0};         ///< World I at the start of the step, kg·m² (zero: static).
};

/// @brief One row of a contact's Jacobian: what an impulse λ along a unit direction d does to A and B.
///
/// Along d (the normal, or a friction tangent) the velocity of B's surface
/// relative to A's at the point is
/// \f[ J v = d\cdot(v_B - v_A) + (r_B\times d)\cdot\omega_B - (r_A\times d)\cdot\omega_A , \f]
/// because (ω × r)·d = ω·(r × d) (the scalar triple product). An impulse λ
/// along d, +λd on B and −λd on A, changes
/// \f[ \Delta v_B = \lambda\, m_B^{-1} d,\quad \Delta L_B = \lambda\,(r_B\times d),\quad
///     \Delta\omega_B = \lambda\, I_B^{-1}(r_B\times d) \f]
/// (and the opposite for A). The lever arms, the directions and the world I⁻¹
/// are held fixed through the step, so the two angular parts of each body are
/// fixed too: prepareContacts() computes them once per step, and a pass does
/// dot products and scaled additions only, with no cross product and no 3×3
/// product per contact (as Bullet's btSolverConstraint stores its
/// m_relpos1CrossNormal and m_angularComponentA; Catto, GDC 2005).
/// For two spheres r ∥ n, so the normal row's arms are (almost) zero: a
/// push through both centres does not turn either ball.
struct ContactRow {
    Vec3 armA{0, 0, 0};   ///< r_A × d: A's angular part of J (ΔL_A per unit impulse, negated), m.
    Vec3 armB{0, 0, 0};   ///< r_B × d, m.
    Vec3 turnA{0, 0, 0};  ///< I_A⁻¹·(r_A × d): A's Δω per unit impulse (negated), 1/(kg·m).
    Vec3 turnB{0, 0, 0};  ///< I_B⁻¹·(r_B × d), 1/(kg·m).
};

/// @brief The row of direction @p d for lever arms @p rA, @p rB and the bodies' world I⁻¹ (static: zeros).
inline ContactRow makeContactRow(const SolverBodyInertia& a, const SolverBodyInertia& b, const Vec3& rA, const Vec3& rB,
                                 const Vec3& d) {
    ContactRow row;
    row.armA = glm::cross(rA, d);
    row.armB = glm::cross(rB, d);
    row.turnA = a.inverseInertia * row.armA;
    row.turnB = b.inverseInertia * row.armB;
    return row;
}

/// @brief K = J·M⁻¹·Jᵀ along the row: m_A⁻¹ + m_B⁻¹ + (r_A×d)·I_A⁻¹(r_A×d) + (r_B×d)·I_B⁻¹(r_B×d), 1/kg.
inline Real inverseEffectiveMass(const SolverBody& a, const SolverBody& b, const ContactRow& row) {
    return a.inverseMass + b.inverseMass + glm::dot(row.armA, row.turnA) + glm::dot(row.armB, row.turnB);
}

/// @brief J·v along the row: B's surface velocity minus A's along @p d at the point, m/s
/// (a kinematic B's own surface speed is added by the caller).
inline Real rowVelocity(const SolverBody& a, const SolverBody& b, const Vec3& d, const ContactRow& row) {
    return glm::dot(b.velocity - a.velocity, d) + glm::dot(row.armB, b.angularVelocity) -
           glm::dot(row.armA, a.angularVelocity);
}

/// @brief Impulse λ along the row: +λd on B, −λd on A (λ in N·s).
///
/// The static record's m⁻¹ and I⁻¹ are zero (so is its turnB), so its
/// velocities stay zero.
inline void applyRowImpulse(SolverBody& a, SolverBody& b, const Vec3& d, const ContactRow& row, Real lambda) {
    a.velocity -= (lambda * a.inverseMass) * d;
    a.angularVelocity -= lambda * row.turnA;
    b.velocity += (lambda * b.inverseMass) * d;
    b.angularVelocity += lambda * row.turnB;
}

/// @name Rows of a round contact: computed from the normal, not stored
///
/// A *round* contact is one between a ball and a ball, or a ball and a plane
/// (SolverContact::rows in contact_solver.hpp). Its lever arms lie along the
/// normal: the point is on the line through the centres, or under the
/// ball's centre, so r_A = ℓ_A·n and r_B = ℓ_B·n with ℓ = r·n (a plane's
/// "centre" does not move, ℓ_B = 0). A ball's I⁻¹ is a number, the same about
/// every axis. So the four vectors of a ContactRow follow from two numbers:
/// along the normal, r × n = 0, and a push through the centres turns neither
/// ball; along a tangent t, with u = n × t,
/// \f[ r_A\times t = \ell_A\,u,\qquad I_A^{-1}(r_A\times t) = I_A^{-1}\ell_A\,u . \f]
/// The pass computes them on the fly instead of reading 288 bytes of rows per
/// contact: what does not have to come from memory is what a pass over tens
/// of thousands of contacts would otherwise wait for.
///@{

/// @brief J·v along the normal of a round contact: (v_B − v_A)·n, m/s.
inline Real roundNormalVelocity(const SolverBody& a, const SolverBody& b, const Vec3& n) {
    return glm::dot(b.velocity - a.velocity, n);
}

/// @brief Impulse λ along the normal of a round contact: it moves the centres only.
inline void applyRoundNormalImpulse(SolverBody& a, SolverBody& b, const Vec3& n, Real lambda) {
    a.velocity -= (lambda * a.inverseMass) * n;
    b.velocity += (lambda * b.inverseMass) * n;
}

/// @brief J·v along both tangents of a round contact, m/s: @p out[0] along t₁ = `t[0]`, @p out[1] along t₂ = `t[1]`.
///
/// Along a tangent t the arms are ℓ·u with u = n × t (above), and the basis
/// has n × t₁ = t₂ and n × t₂ = −t₁ (tangentBasis()). So with the sliding
/// Δv = v_B − v_A and the *spin* s = ℓ_B·ω_B − ℓ_A·ω_A (the relative turn of
/// the two surfaces at the point)
/// \f[ J_1 v = t_1\cdot\Delta v + t_2\cdot s,\qquad J_2 v = t_2\cdot\Delta v - t_1\cdot s . \f]
/// Δv and s serve both tangents: two vectors, four dot products.
inline void roundFrictionVelocities(const SolverBody& a, const SolverBody& b, const Vec3 (&t)[2], Real leverA,
                                    Real leverB, Real (&out)[2]) {
    const Vec3 sliding = b.velocity - a.velocity;
    const Vec3 spin = leverB * b.angularVelocity - leverA * a.angularVelocity;
    out[0] = glm::dot(sliding, t[0]) + glm::dot(t[1], spin);
    out[1] = glm::dot(sliding, t[1]) - glm::dot(t[0], spin);
}

/// @brief Friction impulses λ₁ along t₁ and λ₂ along t₂ of a round contact, applied as one vector.
///
/// The impulse is P = λ₁·t₁ + λ₂·t₂ in the tangent plane, at the point r = ℓ·n
/// from each centre, so its angular impulse is r × P = ℓ·(n × P), with
/// n × P = λ₁·t₂ − λ₂·t₁ (the *twist*):
/// \f[ \Delta v_A = -m_A^{-1} P,\quad \Delta\omega_A = -I_A^{-1}\ell_A\,(n\times P),\qquad
///     \Delta v_B = m_B^{-1} P,\quad \Delta\omega_B = I_B^{-1}\ell_B\,(n\times P) . \f]
/// One push and one twist serve both bodies: fewer operations than the two
/// rows applied one after the other.
inline void applyRoundFrictionImpulse(SolverBody& a, SolverBody& b, const Vec3 (&t)[2], Real leverA, Real leverB,
                                      Real lambda1, Real lambda2) {
    const Vec3 push = lambda1 * t[0] + lambda2 * t[1];
    const Vec3 twist = lambda1 * t[1] - lambda2 * t[0];
    a.velocity -= a.inverseMass * push;
    b.velocity += b.inverseMass * push;
    a.angularVelocity -= (a.inverseInertia * leverA) * twist;
    b.angularVelocity += (b.inverseInertia * leverB) * twist;
}

/// @brief K = J·M⁻¹·Jᵀ along a tangent of a round contact (|u| = 1): m_A⁻¹ + m_B⁻¹ + ℓ_A²·I_A⁻¹ + ℓ_B²·I_B⁻¹, 1/kg.
/// Along the normal the arms vanish and K = m_A⁻¹ + m_B⁻¹.
inline Real roundTangentInverseMass(const SolverBody& a, const SolverBody& b, Real leverA, Real leverB) {
    return a.inverseMass + b.inverseMass + leverA * leverA * a.inverseInertia + leverB * leverB * b.inverseInertia;
}
///@}

}  // namespace stepwise
