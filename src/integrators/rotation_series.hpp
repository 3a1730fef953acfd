/// @file rotation_series.hpp
/// @brief The constants of the exact turn q ← exp(½h·ω̂)·q (rotateByAngularVelocity()): where its
/// series hold and when a quaternion is near enough unit length for one Newton step.
///
/// Shared by the scalar turn (rotation_update.cpp) and the four-at-a-time turn
/// of the packed substeps (src/fast/rotation_lanes.hpp), which must give the same bits.
#pragma once

#include "core/types.hpp"

namespace stepwise {

/// Below this angle (rad) a step's rotation is treated as none: the axis
/// ω/|ω| of a zero angular velocity is undefined.
inline constexpr Real kNegligibleRotationAngle = Real(1e-15);

/// Half-angles φ = |ω|·h/2 up to this (rad) take the Taylor series of cos φ
/// and sin φ / φ instead of the library's sine and cosine. At φ ≤ 0.1 the
/// first terms left out, φ¹⁰/11! ≈ 2.5·10⁻¹⁸ and φ¹²/12! ≈ 2·10⁻²¹, are below
/// half a unit in the last place of 1 in double precision, so the turn is
/// the same to rounding; and a body turns far less than 0.2 rad in a substep,
/// so the series is what nearly every call uses (a sine and a cosine cost
/// several times the five multiplications of each series).
inline constexpr Real kSeriesHalfAngle = Real(0.1);

/// How far |q|² may be from 1 for renormalise() to take its Newton step: the
/// step's error, (3/8)·(|q|² − 1)², is then below 4·10⁻¹³, and from a product
/// of unit quaternions (|q|² − 1 of a few ε) it is far below rounding.
inline constexpr Real kNearUnitLength = Real(1e-6);

/// The Taylor coefficients of cos φ after the 1, in powers of φ²: −1/2!, 1/4!, −1/6!, 1/8!, −1/10!.
inline constexpr Real kCosine[] = {Real(-1.0 / 2), Real(1.0 / 24), Real(-1.0 / 720), Real(1.0 / 40320), Real(-1.0 / 3628800)};
/// The same of sin φ / φ: −1/3!, 1/5!, −1/7!, 1/9!.
inline constexpr Real kSinc[] = {Real(-1.0 / 6), Real(1.0 / 120), Real(-1.0 / 5040), Real(1.0 / 362880)};

}  // namespace stepwise
