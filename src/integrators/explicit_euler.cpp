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
/// Reference: Hairer, Lubich & Wanner, *Geometric Numerical Integration*, §I.1.
#include "integrators/integrators.hpp"

namespace stepwise {

void integrateExplicitEuler(std::span<DynamicObject> bodies, Real h) {
    for (DynamicObject& body : bodies) {
        // The position uses the velocity at the *start* of the step, so
        // this line must come before the velocity update.
        body.position += h * body.velocity;
        body.velocity += h * body.acceleration;
        body.orientation = rotateByAngularVelocity(body.orientation, body.angularVelocity, h);
    }
}

}  // namespace stepwise
