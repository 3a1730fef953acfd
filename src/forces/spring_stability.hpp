/// @file spring_stability.hpp
/// @brief Will this spring blow up at this time step? The amplification factor of each integrator.
///
/// A spring of angular frequency ω = √(k/m_eff) and damping ratio
/// ζ = c/(2√(k·m_eff)) is, along its own line, the damped oscillator
/// \f[ \ddot u = -\omega^2 u - 2\zeta\omega\,\dot u . \f]
/// Every integrator here is *linear* on it: one step maps the state (u, u̇)
/// to M·(u, u̇) with a 2×2 *amplification matrix* M that depends only on h·ω
/// and ζ. After n steps the state is Mⁿ·(u₀, u̇₀), so the motion stays
/// bounded when M's eigenvalues have modulus ρ ≤ 1 and grows like ρⁿ when
/// ρ > 1. For the undamped spring:
///
/// | integrator        | M                                           | ρ                 | stable when |
/// |-------------------|---------------------------------------------|-------------------|-------------|
/// | explicit Euler    | [[1, h], [−hω², 1]]                         | √(1 + h²ω²) > 1   | never       |
/// | symplectic Euler  | [[1 − h²ω², h], [−hω², 1]]                  | 1 (det M = 1)     | h·ω ≤ 2     |
/// | velocity Verlet   | [[1 − ½h²ω², h], [−hω²(1 − ¼h²ω²), 1 − ½h²ω²]] | 1 (det M = 1)  | h·ω ≤ 2     |
///
/// For the two symplectic methods det M = 1 and trace M = 2 − h²ω², so the
/// eigenvalues are e^{±iθ} with cos θ = 1 − ½h²ω² while that lies in [−1, 1],
/// i.e. h·ω ≤ 2; past it they are real, one of them below −1, and the
/// spring's swing flips sign and grows every step. Damping lowers the
/// limit: for symplectic Euler it is h·ω < 2(√(1 + ζ²) − ζ).
///
/// Reference: Hairer, Lubich & Wanner, *Geometric Numerical Integration*,
/// §I.5 and §V.1 (linear stability of the harmonic oscillator);
/// Millington, *Game Physics Engine Development*, §6.2 (stiff springs).
#pragma once

#include <span>

#include "forces/spring.hpp"
#include "core/world_settings.hpp"

namespace stepwise {

/// @brief Spectral radius ρ of one step of @p integrator on the damped oscillator above.
///
/// The amplitude of the spring's swing is multiplied by about ρ every step;
/// ρ > 1 means exponential growth.
/// @param integrator   the World's integrator
/// @param h            time step, s
/// @param omega        undamped angular frequency ω, rad/s
/// @param dampingRatio ζ = c/(2√(k·m_eff)), ≥ 0 (1 is critical damping)
Real amplificationPerStep(IntegratorKind integrator, Real h, Real omega, Real dampingRatio);

/// @brief What a spring's stability comes down to, at the bodies' starting poses.
struct SpringStability {
    Real effectiveMass = 0;       ///< m_eff along the spring, kg (springEffectiveMass()).
    Real omega = 0;               ///< ω = √(k/m_eff), rad/s.
    Real dampingRatio = 0;        ///< ζ = c/(2√(k·m_eff)).
    Real growthPerStep = 1;       ///< ρ = amplificationPerStep(): amplitude factor per step.
    Real largestStableStep = 0;   ///< Largest h with ρ ≤ 1, s; 0 when no step is stable (undamped explicit Euler).
};

/// @brief Stability of @p spring stepped by @p integrator at step @p h.
///
/// The bodies' mass properties must be set (initialiseMassProperties()).
/// A body held by several springs oscillates faster than any one of them
/// alone (two equal springs on one body: ω² = 2k/m), so a step near the
/// limit of one spring may still be too long for the whole system.
SpringStability analyseSpring(const Spring& spring, std::span<const DynamicObject> bodies,
                              IntegratorKind integrator, Real h);

}  // namespace stepwise
