/// @file softness.hpp
/// @brief Soft constraints: how hard a constraint pulls its error back, as a spring of a chosen frequency.
#pragma once

#include <numbers>

#include "core/types.hpp"

namespace stepwise {

/// @brief The three numbers a soft constraint's impulse needs (Catto, "Soft Step", 2024).
///
/// A rigid constraint wants its error C to vanish *now*; pushing it out in one
/// step (a full Baumgarte bias C/h) adds as much speed as it removes overlap,
/// which is energy, and stacks jitter. A soft constraint instead behaves like
/// a damped spring of natural frequency f (ω = 2πf) and damping ratio ζ that
/// acts on the error, solved *implicitly* (backward Euler) so it never blows
/// up, whatever its stiffness. Working the implicit spring through the
/// constraint's effective mass m_eff gives the impulse
/// \f[ \lambda = -m_\text{eff}\,s_m\,(J v + b\,C) - s_i\,\lambda_\text{acc} \f]
/// with
/// \f[ b = \frac{\omega}{2\zeta + h\omega},\qquad
///     s_m = \frac{h\omega(2\zeta + h\omega)}{1 + h\omega(2\zeta + h\omega)},\qquad
///     s_i = \frac{1}{1 + h\omega(2\zeta + h\omega)}. \f]
/// b (1/s) is the *bias rate*: the fraction of the error fed back as a
/// velocity each second; s_m < 1 softens the effective mass; s_i leaks a
/// little of the accumulated impulse so the spring relaxes. As f → ∞ these
/// tend to b = 1/h, s_m = 1, s_i = 0: the rigid, full-Baumgarte constraint.
/// f = 0 means no position feedback at all (b = 0, s_m = 1, s_i = 0).
///
/// Rule of thumb: keep f at most a quarter of the solver rate 1/h, or the
/// implicit spring is stiffer than the step can show (kMaxHertzPerSubstepRate,
/// core/world_settings.hpp, is that cap).
struct Softness {
    Real biasRate = 0;      ///< b: error fed back as velocity, 1/s.
    Real massScale = 1;     ///< s_m: scales the effective mass (dimensionless, ≤ 1).
    Real impulseScale = 0;  ///< s_i: fraction of the accumulated impulse leaked each iteration.
};

/// @brief The soft-constraint coefficients for frequency @p hertz (Hz), damping ratio @p dampingRatio and step @p h (s).
inline Softness makeSoftness(Real hertz, Real dampingRatio, Real h) {
    if (hertz <= 0) return {};
    const Real omega = Real(2) * std::numbers::pi_v<Real> * hertz;
    const Real a1 = Real(2) * dampingRatio + h * omega;
    const Real a2 = h * omega * a1;
    const Real a3 = Real(1) / (Real(1) + a2);
    return {omega / a1, a2 * a3, a3};
}

}  // namespace stepwise
