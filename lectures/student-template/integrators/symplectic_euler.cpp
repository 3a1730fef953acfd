/// @file symplectic_euler.cpp
/// @brief YOUR symplectic Euler: the student template (lectures/student-template/README.md).
///
/// This file replaces src/integrators/symplectic_euler.cpp when the engine is
/// configured with -DSTEPWISE_STUDENT_DIR pointing at the folder that holds
/// it (cmake --preset student uses student/ at the top of the repository).
/// It must define the same function, declared in src/integrators/integrators.hpp:
///
///     void integrateSymplecticEuler(std::span<DynamicObject> bodies, Real h);
///
/// Every dynamic body arrives with its acceleration for this step already in
/// body.acceleration (stage 1, apply-forces). Your job: advance its velocity
/// and position by one step of length h, the symplectic way (lecture 2):
///
///     v_{n+1} = v_n + h a_n
///     x_{n+1} = x_n + h v_{n+1}
///
/// The rotational half is given (lecture 4 derives it). Until you write the
/// two lines, no body moves, and `ctest --preset student -L symplectic-euler`
/// says which physics each test expected.
#include "objects/inertia.hpp"
#include "integrators/integrators.hpp"

namespace stepwise {

void integrateSymplecticEuler(std::span<DynamicObject> bodies, Real h) {
    for (DynamicObject& body : bodies) {
        // TODO: the velocity, then the position with the NEW velocity.

        // Rotation, as the engine does it: kick the angular momentum with the torque,
        // then turn the body torque-free with the new momentum (src/integrators/free_rotation.cpp).
        body.angularMomentum += h * body.torque;
        body.orientation = rotateTorqueFree(body.orientation, body.angularMomentum, body.inverseInertiaBody, h);
        updateAngularVelocity(body);
    }
}

}  // namespace stepwise
