/// @file solver_body.hpp
/// @brief The sequential-impulse contact solver's view of a body: a small record in one contiguous array.
///
/// **Why a separate array.** A contact pass touches, for every contact point,
/// the velocity, angular velocity, angular momentum, inverse mass and world
/// inverse inertia of both bodies. A DynamicObject holds those among some
/// thirty other fields (name, colour, shape, forces, sleep state…), so
/// reading them through the object costs several cache lines per body, and
/// a world inverse inertia rebuilt per contact costs a quaternion-to-matrix
/// conversion each time. Catto's Box2D v3 solves on *solver bodies* instead:
/// the solver copies what it needs of each body it touches into a packed
/// array at the start of a pass (gather), the contacts refer to those
/// records by a 32-bit index, and the pass writes the velocities back at the
/// end (scatter). The world inverse inertia I⁻¹ = R·I_body⁻¹·Rᵀ is computed
/// once per body per step (the solver holds it fixed through the step, see
/// point_impulse.hpp), not once per contact.
///
/// Only bodies that are in a contact get a record, numbered in the order the
/// contacts first meet them, so neighbouring contacts tend to touch
/// neighbouring records. Record 0 is the *static body*: B of a contact with a
/// plane or a kinematic body. It has m⁻¹ = 0 and I⁻¹ = 0, so an impulse does
/// not move it, and its velocity stays zero; the velocity of a kinematic
/// surface is kept in the contact (SolverContact::staticVelocity). With it, a
/// contact pass needs no test "is B dynamic?" per contact.
///
/// The formulas are those of point_impulse.hpp, with the same operations in
/// the same order: the solver's results do not change.
///
/// Reference: Catto, Box2D v3 `solver.h` (b2BodyState, b2BodySim), 2024.
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace stepwise {

/// @brief Record 0 of the solver-body array: the immovable B of a contact with a plane or kinematic body.
inline constexpr std::uint32_t kStaticSolverBody = 0;

/// @brief What the contact solver reads and writes of one dynamic body during a pass.
struct SolverBody {
    Vec3 velocity{0, 0, 0};         ///< Linear velocity of the centre of mass, m/s.
    Vec3 angularVelocity{0, 0, 0};  ///< Angular velocity, world frame, rad/s.
    Vec3 angularMomentum{0, 0, 0};  ///< L about the centre of mass, world frame, kg·m²/s (changes with ω).
    Mat3 inverseInertia{0};         ///< World I⁻¹ at the start of the step, 1/(kg·m²) (zero: static).
    Real inverseMass = 0;           ///< 1/m, 1/kg (zero: static).
    std::uint32_t body = 0;         ///< Index of the body in the World's dynamic array.
};

/// @brief Velocity of B's surface minus A's at a contact point: (v_B + ω_B×r_B + v_static) − (v_A + ω_A×r_A), m/s.
///
/// v_static is the velocity of a kinematic B's surface (zero otherwise); the
/// static solver body contributes zero, so one formula serves every kind of B.
inline Vec3 relativeVelocity(const SolverBody& a, const SolverBody& b, const Vec3& rA, const Vec3& rB,
                             const Vec3& staticVelocity) {
    const Vec3 va = a.velocity + glm::cross(a.angularVelocity, rA);
    const Vec3 vb = b.velocity + glm::cross(b.angularVelocity, rB) + staticVelocity;
    return vb - va;
}

/// @brief Impulse P on B at the point and −P on A: Δv = ±P/m, ΔL = ±r×P, Δω = I⁻¹·ΔL (as point_impulse.hpp).
///
/// P and the lever arms are taken by value: a reference could point into a
/// body being written, and the compiler would have to reload it after every store.
inline void applyImpulse(SolverBody& a, SolverBody& b, const Vec3 rA, const Vec3 rB, const Vec3 P) {
    const Vec3 angularA = glm::cross(rA, P);
    a.velocity -= P * a.inverseMass;
    a.angularMomentum -= angularA;
    a.angularVelocity -= a.inverseInertia * angularA;
    const Vec3 angularB = glm::cross(rB, P);
    b.velocity += P * b.inverseMass;
    b.angularMomentum += angularB;
    b.angularVelocity += b.inverseInertia * angularB;
}

}  // namespace stepwise
