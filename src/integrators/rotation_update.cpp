/// @file rotation_update.cpp
/// @brief The integrators' rotation updates: the exact turn by ω·h, and Catto's small-angle turn.
#include <cmath>

#include "integrators/integrators.hpp"
#include "integrators/rotation_series.hpp"

namespace stepwise {

namespace {

/// q / |q| for a quaternion that rounding has nudged off unit length. One
/// Newton step for 1/√x at x = |q|² near 1 gives 1/√x ≈ (3 − x)/2, with an
/// error of order (x − 1)²: exact to rounding here, without the square root
/// and the division of a full normalisation (which a quaternion farther
/// from unit length still gets).
Quat renormalise(const Quat& q) {
    const Real x = glm::dot(q, q);
    if (std::abs(x - 1) > kNearUnitLength) return glm::normalize(q);
    return q * ((Real(3) - x) * Real(0.5));
}

}  // namespace

Quat rotateByAngularVelocity(const Quat& orientation, const Vec3& omega, Real h) {
    const Real speedSquared = glm::dot(omega, omega);  // rad²/s²
    if (speedSquared * h * h < kNegligibleRotationAngle * kNegligibleRotationAngle) return orientation;
    // The turn by angle |ω|·h about ω/|ω| is the quaternion (cos φ, sin φ · ω/|ω|)
    // with φ = |ω|·h/2, and sin φ · ω/|ω| = (h/2)·(sin φ / φ)·ω: no division, and
    // for small φ no square root either, since both series are in φ².
    const Real p = Real(0.25) * speedSquared * h * h;  // φ²
    Real cosine = 0;
    Real sinc = 0;  // sin φ / φ
    if (p <= kSeriesHalfAngle * kSeriesHalfAngle) {
        // Horner form of 1 − φ²/2! + φ⁴/4! − … − φ¹⁰/10! and 1 − φ²/3! + φ⁴/5! − … + φ⁸/9!,
        // in powers of p = φ² with the coefficients ±1/n! rounded once at compile time:
        // multiplications only (a division by 12 or 30 is not a multiplication to the
        // compiler, whose reciprocal is inexact, and costs several times as much).
        cosine = 1 + p * (kCosine[0] + p * (kCosine[1] + p * (kCosine[2] + p * (kCosine[3] + p * kCosine[4]))));
        sinc = 1 + p * (kSinc[0] + p * (kSinc[1] + p * (kSinc[2] + p * kSinc[3])));
    } else {
        const Real halfAngle = std::sqrt(p);
        cosine = std::cos(halfAngle);
        sinc = std::sin(halfAngle) / halfAngle;
    }
    const Vec3 axisPart = (Real(0.5) * h * sinc) * omega;
    // World-frame angular velocity: the step's rotation multiplies on the left.
    const Quat turn(cosine, axisPart.x, axisPart.y, axisPart.z);
    return renormalise(turn * orientation);
}

Quat turnBySmallAngle(const Quat& orientation, const Vec3& omega, Real h) {
    // q̇ = ½·(0, ω)⊗q for a world-frame ω; one explicit Euler step of it is
    // q + ½h·(0, ω)⊗q = (1, φ·n)⊗q with φ = |ω|·h/2 and n = ω/|ω|, which after
    // normalising is a turn by 2·atan φ = |ω|·h − (|ω|·h)³/12 + …: the exact
    // turn to third order in the angle, for a quaternion product and no series.
    const Vec3 half = (Real(0.5) * h) * omega;
    return renormalise(orientation + Quat(0, half.x, half.y, half.z) * orientation);
}

}  // namespace stepwise
