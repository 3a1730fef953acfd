/// @file rotation_lanes.hpp
/// @brief rotateByAngularVelocity() on four bodies at once (SIMD lanes), to the bit.
///
/// On the packed substeps every ball turns once a step, in the last substep's
/// drift (packed_drift.cpp): 1 000 turns a step in the 1k sphere
/// rain, each a short chain of multiplications (a series for cos φ
/// and sin φ / φ, a quaternion product, a Newton step back to unit length)
/// that a scalar loop does one ball at a time. The same formulas on Lanes
/// (lanes.hpp) turn four balls with the instructions of one.
///
/// **The same numbers.** Every line below is the scalar turn's
/// (integrators/rotation_update.cpp), written on Lanes in the same order of operations,
/// with glm's orders for the dot products and the quaternion product; IEEE 754
/// rounds each lane as the scalar operation, so a lane gives the scalar turn's
/// bits. The rare lanes the series or the Newton step do not cover (a turn
/// of more than 0.2 rad in one substep, a quaternion far from unit length,
/// a non-finite ω) are handed back to the scalar function, which also treats
/// every edge case the same way as before. The test `[lanes]` holds the two
/// to the bit.
///
/// Reference: Shoemake, "Animating rotation with quaternion curves"
/// (SIGGRAPH 1985) for q ← exp(½h·ω̂)·q; the series are in rotation_series.hpp.
#pragma once

// Lanes pass by value between always-inlined functions (see lanes.hpp).
#if defined(__GNUC__)  // GCC, and clang, which reads GCC's pragmas
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

#include "fast/lanes.hpp"
#include "integrators/rotation_series.hpp"

namespace stepwise {

/// @brief Four quaternions, stored by component.
struct QuatLanes {
    Lanes w;  ///< The four real parts.
    Lanes x;  ///< The four i components.
    Lanes y;  ///< The four j components.
    Lanes z;  ///< The four k components.
};

/// @brief p ⊗ q in each lane, each component summed in glm's order (qua::operator*=).
STEPWISE_LANES_INLINE QuatLanes operator*(const QuatLanes& p, const QuatLanes& q) {
    return {p.w * q.w - p.x * q.x - p.y * q.y - p.z * q.z,
            p.w * q.x + p.x * q.w + p.y * q.z - p.z * q.y,
            p.w * q.y + p.y * q.w + p.z * q.x - p.x * q.z,
            p.w * q.z + p.z * q.w + p.x * q.y - p.y * q.x};
}

/// @brief The turned orientations, and which lanes the scalar turn must redo.
struct TurnLanes {
    QuatLanes orientation;  ///< exp(½h·ω̂)·q in every lane the series covers.
    /// Per lane, all bits set where the lane needs rotateByAngularVelocity() instead
    /// (φ past the series, |q|² too far from 1 for the Newton step, or a non-finite ω).
    decltype(Lanes{} < Lanes{}) needsScalar;
};

/// @brief rotateByAngularVelocity(q, ω, h) in each lane, except where TurnLanes::needsScalar says.
STEPWISE_LANES_INLINE TurnLanes rotateByAngularVelocity(const QuatLanes& q, const Vec3Lanes& omega, Real h) {
    const Lanes speedSquared = dot(omega, omega);  // rad²/s²
    const auto negligible = speedSquared * h * h < splat(kNegligibleRotationAngle * kNegligibleRotationAngle);
    const Lanes p = splat(Real(0.25)) * speedSquared * h * h;  // φ²
    const Lanes cosine = Real(1) + p * (kCosine[0] + p * (kCosine[1] + p * (kCosine[2] + p * (kCosine[3] + p * kCosine[4]))));
    const Lanes sinc = Real(1) + p * (kSinc[0] + p * (kSinc[1] + p * (kSinc[2] + p * kSinc[3])));
    const Lanes scale = Real(0.5) * h * sinc;
    const QuatLanes turn{cosine, scale * omega.x, scale * omega.y, scale * omega.z};
    const QuatLanes turned = turn * q;
    const Lanes lengthSquared = (turned.w * turned.w + turned.x * turned.x) + (turned.y * turned.y + turned.z * turned.z);
    const Lanes offUnit = lengthSquared - Real(1);
    const Lanes newton = (Real(3) - lengthSquared) * Real(0.5);
    // The scalar turn leaves the series for φ > kSeriesHalfAngle (and for a NaN, which
    // fails every comparison), and the Newton step for | |q|² − 1 | > kNearUnitLength.
    const auto inSeries = p <= splat(kSeriesHalfAngle * kSeriesHalfAngle);
    const auto farFromUnit = (offUnit > splat(kNearUnitLength)) | (offUnit < splat(-kNearUnitLength));
    TurnLanes result;
    result.orientation = {select(negligible, q.w, turned.w * newton), select(negligible, q.x, turned.x * newton),
                          select(negligible, q.y, turned.y * newton), select(negligible, q.z, turned.z * newton)};
    result.needsScalar = ~negligible & (~inSeries | farFromUnit);
    return result;
}

}  // namespace stepwise

#if defined(__GNUC__)  // GCC, and clang, which reads GCC's pragmas
#pragma GCC diagnostic pop
#endif
