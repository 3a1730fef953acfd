/// @file limits.hpp
/// @brief The limits a scene's values must keep: one list, for the loader and the World.
///
/// A scene file that `stepwise check` accepts must run: the loader refuses a
/// value outside these limits at its line and column (src/config/), and the
/// World refuses the same value in a scene built in code, naming the object
/// (World::World, makeJoints()). Both read the constants below, so the two
/// cannot disagree. Each limit keeps the arithmetic of a step finite: a size
/// of 1e200 m has a moment of inertia that overflows, a count of 2^31 wraps,
/// a direction of length 1e200 normalises to zero.
#pragma once

#include <cmath>

#include "core/types.hpp"

namespace stepwise {

/// @brief The smallest and largest size of a body: a box's edge or a sphere's diameter, m.
/// A micrometre to a thousand kilometres: inside that, m·r² and r² stay far from overflow and underflow.
inline constexpr Real kMinBodySize = Real(1e-6);
inline constexpr Real kMaxBodySize = Real(1e6);  ///< See kMinBodySize.

/// @brief The smallest and largest mass of a body, kg. The ratio of two masses the solver can
/// hold where they press on each other is much smaller than this range: see kMaxMassRatio.
inline constexpr Real kMinMass = Real(1e-12);
inline constexpr Real kMaxMass = Real(1e12);  ///< See kMinMass.

/// @brief The largest ratio of two masses pressing on each other that the sequential-impulse
/// solver holds: a box under one kMaxMassRatio times heavier sinks millimetres into the floor,
/// one under 10 times that is pushed through it. The reason is the Gauss–Seidel sweep: each
/// contact is solved as if the others were fixed, and the heavy body's weight reaches the floor
/// contact only a fraction m_light/m_heavy per pass (Catto, "Iterative Dynamics", GDC 2005).
/// The loader warns about a scene whose heaviest and lightest bodies exceed it.
inline constexpr Real kMaxMassRatio = Real(1000);

/// @brief The shortest length a direction (a plane's normal, a joint's axis) may have before it
/// is normalised: shorter, it has no direction to speak of.
inline constexpr Real kMinDirectionLength = Real(1e-9);

/// @brief Whether @p v can be normalised: its length is finite (its squares do not overflow)
/// and at least kMinDirectionLength.
inline bool usableDirection(const Vec3& v) {
    const Real length = glm::length(v);
    return std::isfinite(length) && length >= kMinDirectionLength;
}

/// @brief The shortest rod or rope a DistanceJoint or Rope may be, m.
inline constexpr Real kMinJointLength = Real(1e-6);

/// @brief The most substeps, solve passes, relax passes or impulse passes a step may have.
/// Past a thousand, more passes buy nothing a smaller time step would not, and a step could run for hours.
inline constexpr int kMaxRepetitions = 1024;

/// @brief The most threads the narrowphase may use (`Threads`, `--threads`).
inline constexpr int kMaxThreads = 256;

}  // namespace stepwise
