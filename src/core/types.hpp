/// @file types.hpp
/// @brief The one place that fixes Stepwise's numeric precision and maths types.
///
/// Every quantity in the engine is in SI units: metres, kilograms, seconds,
/// radians. Switching `Real` to `float` (define `STEPWISE_SINGLE_PRECISION`)
/// switches the whole engine, because every other file spells its types
/// through these aliases.
#pragma once

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

/// @brief True when every component of @p v is a finite number (not NaN, not ±∞).
bool isFinite(const Vec3& v);

/// @brief True when every component of @p q is a finite number.
bool isFinite(const Quat& q);

}  // namespace stepwise
