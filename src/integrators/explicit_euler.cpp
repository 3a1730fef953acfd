/// @file explicit_euler.cpp
/// @brief Explicit (forward) Euler: the simplest integrator, and the lesson in why not to stop there.
///
/// From the Taylor series x(t+h) = x(t) + h·ẋ(t) + O(h²), keeping the first
/// two terms for both position and velocity:
/// \f[ x_{n+1} = x_n + h\,v_n, \qquad v_{n+1} = v_n + h\,a_n. \f]
/// Each step makes an error of O(h²); over the 1/h steps of a fixed time the
/// errors add to a global error of O(h): halve the step, halve the error.
///
/// On an undamped oscillator (a = −ω²x) one step multiplies the energy by
/// exactly (1 + h²ω²): the orbit spirals outwards, always. That is the
/// behaviour the lecture makes students see (lectures/01-explicit-euler.md).
///
/// With constant gravity the position lags: after n steps
/// x_n = x_0 + v_0·t + ½g·t² − ½g·h·t, off by ½·g·h·t.
///
/// ## Rotation: the Lie-group explicit Euler
/// The orientation lives on the sphere of unit quaternions, not in a vector
/// space, so "q + h·q̇" would leave it; the Lie-group form of the same idea
/// turns the body by the old angular velocity for the whole step:
/// \f[ \omega_n = I_\text{world}(q_n)^{-1} L_n, \qquad
///     q_{n+1} = \exp\!\left(\tfrac12 h\,\hat\omega_n\right) q_n, \qquad
///     L_{n+1} = L_n + h\,\tau_n . \f]
/// With no torque L is never changed, so |L| is kept exactly. The energy is
/// not: ω_n is right at the start of the step and stale by its end (the
/// body has turned, so I_world and with it the true ω have changed). In the
/// body frame the step turns Π = Rᵀ·L about ω_n, by −h·|ω_n|: a turn about
/// ω_n keeps Π's component along ω_n, so ω_n·ΔΠ = 0 for ΔΠ = Π_{n+1} − Π_n.
/// With E = ½·Π·I⁻¹·Π and I⁻¹·Π_n = ω_n, exactly,
/// \f[ E_{n+1} - E_n = \omega_n\cdot\Delta\Pi + \tfrac12\,\Delta\Pi\cdot I^{-1}\Delta\Pi
///                   = \tfrac12\,\Delta\Pi\cdot I^{-1}\Delta\Pi \;\ge\; 0, \qquad
///     \Delta\Pi \approx h\,\Pi\times\omega : \f]
/// every step *adds* energy, the rotational twin of the oscillator's factor
/// 1 + h²ω², and over a fixed time the error is O(h). With |L| fixed, more
/// energy means a spin closer to the axis of least inertia: a box spun about
/// its intermediate axis stops flipping and ends up wobbling about its long
/// axis (tests/test_rotation.cpp, lectures/04-inertia-and-rotation.md).
/// A sphere is the exception: its ω is constant, so this turn is its exact motion.
///
/// References: Hairer, Lubich & Wanner, *Geometric Numerical Integration*, §I.1
/// and §IV.8 (Lie-group methods).
#include "objects/inertia.hpp"
#include "integrators/integrators.hpp"

namespace stepwise {

void integrateExplicitEuler(std::span<DynamicObject> bodies, Real h) {
    for (DynamicObject& body : bodies) {
        if (body.asleep) continue;  // a sleeping body keeps its state until its island wakes
        // The position uses the velocity at the *start* of the step, so
        // this line must come before the velocity update.
        body.position += h * body.velocity;
        body.velocity += h * body.acceleration;
        if (skipsRotation(body)) continue;  // a still sphere: the update below would change nothing

        // Rotation, the same way round: turn by ω_n = I_world(q_n)⁻¹·L_n, computed
        // from the *old* orientation and momentum, then update L with τ_n.
        updateAngularVelocity(body);
        body.orientation = rotateByAngularVelocity(body.orientation, body.angularVelocity, h);  // normalised
        body.angularMomentum += h * body.torque;
        updateAngularVelocity(body);  // ω_{n+1} for the next step, the contacts and the output
    }
}

}  // namespace stepwise
