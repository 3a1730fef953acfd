/// @file exact_solutions.hpp
/// @brief The answers the reference problems are checked against: closed forms and one careful integration.
///
/// Every one comes from physics, never from the engine: the projectile's
/// parabola, the oscillator's cosine, Kepler's equation for an orbit, and
/// Euler's equations for a free rigid body integrated by classical
/// Runge–Kutta at a step thousands of times finer than any the benchmark
/// sweeps.
#pragma once

#include <utility>
#include <vector>

#include "core/types.hpp"

/// @brief The benchmark programs (bench/): reference problems, exact solutions, timing.
namespace stepwise::bench {

/// @brief Double precision whatever Real is: references must be more accurate than what they judge.
using DVec3 = glm::dvec3;

/// @brief Position and velocity of a body at some time.
struct PointState {
    DVec3 position{0, 0, 0};  ///< m
    DVec3 velocity{0, 0, 0};  ///< m/s
};

/// @brief Constant acceleration: x(t) = x₀ + v₀t + ½gt², v(t) = v₀ + gt.
PointState projectileAt(const PointState& start, const DVec3& gravity, double t);

/// @brief Harmonic oscillator u¨ = −ω²u: u(t) = u₀cos ωt + (u̇₀/ω) sin ωt.
/// @return (u, u̇) at time @p t.
std::pair<double, double> oscillatorAt(double u0, double rate0, double omega, double t);

/// @brief The complete elliptic integral of the first kind, K(k) = ∫₀^{π/2} dφ / √(1 − k² sin²φ), for 0 ≤ k < 1.
///
/// By Gauss's arithmetic–geometric mean (Abramowitz & Stegun 17.6):
/// \f[ K(k) = \frac{\pi}{2\,\mathrm{AGM}(1, \sqrt{1 - k^2})}, \f]
/// where AGM(a, b) iterates a ← (a + b)/2, b ← √(ab) until they agree; the
/// number of correct digits doubles every iteration, so a handful reach
/// double precision.
/// @throws std::invalid_argument when k is outside [0, 1).
double completeEllipticK(double k);

/// @brief Period of a simple pendulum of length @p length in gravity @p g released from rest at @p theta0 (rad), s.
///
/// The exact period at any amplitude below π (Landau & Lifshitz, *Mechanics*, §11):
/// \f[ T = 4\sqrt{L/g}\;K\big(\sin(\theta_0/2)\big), \f]
/// which tends to the small-angle 2π√(L/g) as θ₀ → 0 and grows without bound as θ₀ → π.
double pendulumPeriod(double length, double g, double theta0);

/// @brief The two-body (Kepler) problem about a fixed centre of gravitational parameter μ.
///
/// Bound orbits only (energy < 0). The state at any time follows from the
/// start by Lagrange's f and g functions of the change ΔE of eccentric
/// anomaly, which solves Kepler's equation in its universal form for
/// ellipses (Curtis, *Orbital Mechanics for Engineering Students*, §3.7;
/// Vallado, *Fundamentals of Astrodynamics*, §2.3):
/// \f[ n\,\Delta t = \Delta E - \Big(1 - \frac{r_0}{a}\Big)\sin\Delta E
///     + \frac{\sigma_0}{\sqrt a}\,(1 - \cos\Delta E), \qquad
///     \sigma_0 = \frac{r_0\cdot v_0}{\sqrt\mu},\quad n = \sqrt{\mu/a^3}, \f]
/// solved by Newton's method, then r = f·r₀ + g·v₀ and v = ḟ·r₀ + ġ·v₀.
class KeplerOrbit {
public:
    /// @brief The orbit through @p start (relative to the centre) about a centre of parameter @p mu.
    /// @throws std::invalid_argument when the orbit is not bound.
    KeplerOrbit(const PointState& start, double mu);

    /// @brief The state @p t seconds after the start.
    PointState at(double t) const;

    double semiMajorAxis() const { return a_; }  ///< a = −μ/(2ε), m.
    double period() const;                      ///< T = 2π√(a³/μ), s.
    double eccentricity() const;                ///< |e| of the eccentricity vector.
    double specificEnergy() const;              ///< ε = ½v² − μ/r, J/kg (constant along the orbit).

private:
    PointState start_;
    double mu_;
    double a_;
};

/// @brief Flip times of a torque-free rigid body spun near its intermediate axis (the Dzhanibekov effect).
///
/// Euler's equations in the principal body frame, I·ω̇ = (I·ω) × ω, are
/// integrated by classical Runge–Kutta (4th order, global error ∝ dt⁴) at
/// step @p dt. A flip is a sign change of the body-frame angular momentum
/// along the intermediate axis; its time is found by linear interpolation
/// between the two steps around it.
/// @param moments     principal moments I₁, I₂, I₃, kg·m²
/// @param omegaBody   starting angular velocity in the body frame, rad/s
/// @param axis        index (0–2) of the axis whose sign changes are counted
/// @param duration    how long to integrate, s
/// @param dt          Runge–Kutta step, s
std::vector<double> flipTimes(const DVec3& moments, const DVec3& omegaBody, int axis, double duration, double dt);

}  // namespace stepwise::bench
