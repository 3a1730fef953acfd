/// @file symplectic_euler.cpp
/// @brief Symplectic (semi-implicit) Euler: one line swapped, energy tamed.
///
/// Update the velocity first, then move with the *new* velocity:
/// \f[ v_{n+1} = v_n + h\,a_n, \qquad x_{n+1} = x_n + h\,v_{n+1}. \f]
/// Still first order (global error O(h)), but the map preserves phase-space
/// area (it is symplectic), so on an oscillator the energy oscillates about
/// the true value with an amplitude O(h) instead of growing without bound.
/// This is the integrator most game engines use (Box2D, Bullet): it is as
/// cheap as explicit Euler and stable for stiff springs up to h·ω < 2.
///
/// With constant gravity the position leads by ½·g·h·t (the mirror image of
/// explicit Euler's lag).
///
/// Reference: Hairer, Lubich & Wanner, *Geometric Numerical Integration*, §I.1.2;
/// Millington, *Game Physics Engine Development*, §3.3.
#include "integrators/integrators.hpp"

namespace stepwise {

void integrateSymplecticEuler(std::span<DynamicObject> bodies, Real h) {
    for (DynamicObject& body : bodies) {
        body.velocity += h * body.acceleration;
        body.position += h * body.velocity;  // the new velocity: that is the whole difference
        body.orientation = rotateByAngularVelocity(body.orientation, body.angularVelocity, h);
    }
}

}  // namespace stepwise
