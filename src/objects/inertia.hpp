/// @file inertia.hpp
/// @brief Inertia tensors: how mass is spread around the centre, and what that does to turning.
///
/// Newton's law for rotation about the centre of mass is τ = dL/dt with the
/// angular momentum L = I·ω. The inertia tensor I plays the part of mass,
/// but it is a 3×3 matrix: the same torque turns a long box more easily
/// about its long axis than across it. In the body's own principal axes
/// I is diagonal, I_body = diag(I₁, I₂, I₃); in the world it is
/// \f[ I_\text{world} = R\,I_\text{body}\,R^\mathsf{T}, \qquad
///     I_\text{world}^{-1} = R\,I_\text{body}^{-1}\,R^\mathsf{T}, \f]
/// with R the body's rotation matrix: rotate a world vector into the body
/// frame (Rᵀ), apply the diagonal tensor, rotate back (R).
///
/// References: Baraff, *Physically Based Modeling: Rigid Body Simulation*
/// (SIGGRAPH 2001 course notes), §2.5–2.9; Millington, *Game Physics Engine
/// Development*, ch. 10.
#pragma once

#include "objects/game_object.hpp"

namespace stepwise {

/// @brief Are the three principal moments @p diagonal exactly equal (a sphere, a cube)? Then
/// R·(s·E)·Rᵀ = s·R·Rᵀ = s·E in every orientation: the world tensor is the body's number.
bool equalMoments(const Vec3& diagonal);

/// @brief Principal moments of a solid ball: I = ⅖·m·r² about every axis, kg·m².
Vec3 solidSphereInertia(Real mass, Real radius);

/// @brief Principal moments of a thin spherical shell: I = ⅔·m·r² about every axis, kg·m².
Vec3 hollowSphereInertia(Real mass, Real radius);

/// @brief Principal moments of a solid box with full edge lengths @p size = (a, b, c):
/// I₁ = m(b² + c²)/12, I₂ = m(a² + c²)/12, I₃ = m(a² + b²)/12, kg·m².
Vec3 solidBoxInertia(Real mass, const Vec3& size);

/// @brief Parallel-axis (Huygens–Steiner) theorem: the inertia tensor about a
/// point displaced by @p offset from the centre of mass,
/// \f[ I_P = I_C + m\,(|d|^2 E - d\,d^\mathsf{T}). \f]
/// @param inertiaAboutCentre tensor about the centre of mass, kg·m²
/// @param mass               kg
/// @param offset             d, from the centre of mass to the new pivot, m
Mat3 parallelAxis(const Mat3& inertiaAboutCentre, Real mass, const Vec3& offset);

/// @brief World-frame inverse inertia R·diag(1/I)·Rᵀ of a body with the given orientation.
Mat3 worldInverseInertia(const Quat& orientation, const Vec3& inverseInertiaBody);

/// @brief World-frame inertia R·diag(I)·Rᵀ.
Mat3 worldInertia(const Quat& orientation, const Vec3& inertiaBody);

/// @brief Fills a body's principal moments from its shape, mass, size and `hollow` flag,
/// and its angular momentum from its angular velocity (L = I_world·ω).
void initialiseMassProperties(DynamicObject& body);

/// @brief Recomputes ω = I_world⁻¹·L after the orientation or L changed.
void updateAngularVelocity(DynamicObject& body);

/// @brief Applies impulse @p impulse (N·s) at world point @p point:
/// Δv = J/m and ΔL = (p − x) × J, then refreshes ω.
void applyImpulseAt(DynamicObject& body, const Vec3& impulse, const Vec3& point);

/// @brief Velocity of the body's material at world point @p point: v + ω × (p − x), m/s.
inline Vec3 velocityAt(const DynamicObject& body, const Vec3& point) {
    return body.velocity + glm::cross(body.angularVelocity, point - body.position);
}

}  // namespace stepwise
