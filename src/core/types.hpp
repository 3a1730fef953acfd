/// @file types.hpp
/// @brief The one place that fixes Stepwise's numeric precision and maths types.
///
/// Every quantity in the engine is in SI units: metres, kilograms, seconds,
/// radians. Switching `Real` to `float` (define `STEPWISE_SINGLE_PRECISION`)
/// switches the whole engine, because every other file spells its types
/// through these aliases.
#pragma once

#include <cmath>
#include <cstdint>

#define GLM_FORCE_XYZW_ONLY  // vectors have only x, y, z (no r, g, b aliases)
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

/// @brief Everything in Stepwise: the engine, its stages and its object model.
namespace stepwise {

#ifdef STEPWISE_SINGLE_PRECISION
using Real = float;   ///< Scalar type of the engine (single precision build).
#else
using Real = double;  ///< Scalar type of the engine; double by default so
                      ///< that error measurements show the method's error,
                      ///< not round-off.
#endif

using Vec3 = glm::vec<3, Real, glm::defaultp>;   ///< 3-vector (m, m/s, N, …).
using Quat = glm::qua<Real, glm::defaultp>;      ///< Unit quaternion (orientation).
using Mat3 = glm::mat<3, 3, Real, glm::defaultp>; ///< 3×3 matrix (rotation, inertia).

/// Standard gravity at the Earth's surface, m/s² (CGPM 1901 conventional value,
/// rounded to the precision a scene file usually states).
inline constexpr Real kStandardGravity = Real(9.81);

/// π, spelled once.
inline constexpr Real kPi = Real(3.14159265358979323846);

// Inline: the World checks every body's state after every stage (World::checkFinite),
// several times per substep, and a call per vector cost more than the test itself.

/// @brief True when every component of @p v is a finite number (not NaN, not ±∞).
inline bool isFinite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// @brief True when every component of @p q is a finite number.
inline bool isFinite(const Quat& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

/// @brief The *finite probe* of @p v: x·0 is 0 for a finite x and NaN for ±∞ or NaN, and a
/// sum of zeros cannot overflow, so a sum of probes is zero exactly when every number in it
/// is finite. Branch-free: a loop that writes numbers can add their probes as it goes and
/// test the one sum at the end (World::checkFinite()).
inline Real zeroIfFinite(const Vec3& v) { return v.x * Real(0) + v.y * Real(0) + v.z * Real(0); }

/// @brief The finite probe of the four components of @p q.
inline Real zeroIfFinite(const Quat& q) { return q.w * Real(0) + q.x * Real(0) + q.y * Real(0) + q.z * Real(0); }

}  // namespace stepwise
