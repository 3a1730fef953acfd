/// @file verlet.cpp
/// @brief YOUR velocity Verlet (lecture 2): a student template (lectures/student-template/README.md).
///
/// Copied to student/integrators/verlet.cpp, it replaces
/// src/integrators/verlet.cpp in the student preset's build. It defines the
/// function src/integrators/integrators.hpp declares:
///
///     void integrateVerlet(std::span<DynamicObject> bodies, Real h,
///                          const AccelerationFunction& accelerations);
///
/// Every body arrives with a_n in body.acceleration (stage 1, apply forces).
/// Velocity Verlet is "kick h/2, drift h, kick h/2" (lecture 2, "Velocity Verlet"):
///
///     x_{n+1} = x_n + h v_n + h^2 a_n / 2       first loop
///     v      += h a_n / 2                       first loop
///     accelerations(bodies)                     writes a_{n+1} = a(x_{n+1}), given
///     v      += h a_{n+1} / 2                   second loop
///
/// Write the two translational parts between the YOUR CODE lines. The
/// rotational half kicks and the force call are given (lecture 4 derives the
/// rotation). Until you write them, the stage stops with
/// "student stage not written yet: stepwise::integrateVerlet".
/// Test it: ctest --preset student -L verlet
#include "core/student_todo.hpp"
#include "objects/inertia.hpp"
#include "integrators/integrators.hpp"

namespace stepwise {

void integrateVerlet(std::span<DynamicObject> bodies, Real h, const AccelerationFunction& accelerations) {
    for (DynamicObject& body : bodies) {
        if (body.asleep) continue;  // a sleeping body keeps its state until its island wakes

        // ==== YOUR CODE BEGINS: lecture 2, "Velocity Verlet" (the drift and the first half kick) ====
        body.position += h * body.velocity + Real(0.5) * h * h * body.acceleration;
        // Half the velocity update now, with a_n; the other half needs a_{n+1}.
        body.velocity += Real(0.5) * h * body.acceleration;
        // ==== YOUR CODE ENDS ====

        if (skipsRotation(body)) continue;  // a still sphere: the rotation below would change nothing
        // Rotation, given: half kick with tau_n, then the torque-free turn (lecture 4).
        body.angularMomentum += Real(0.5) * h * body.torque;
        body.orientation = rotateTorqueFree(body.orientation, body.angularMomentum, body.inverseInertiaBody, h);
        updateAngularVelocity(body);  // the force model may read omega at the new orientation
    }
    accelerations(bodies);  // a_{n+1} = a(x_{n+1}) and tau_{n+1}, written into each body
    for (DynamicObject& body : bodies) {
        if (body.asleep) continue;

        // ==== YOUR CODE BEGINS: lecture 2, "Velocity Verlet" (the second half kick) ====
        body.velocity += Real(0.5) * h * body.acceleration;
        // ==== YOUR CODE ENDS ====

        if (skipsRotation(body)) continue;  // tau_{n+1} = 0 and L = 0: nothing to kick
        body.angularMomentum += Real(0.5) * h * body.torque;  // the other half kick, with tau_{n+1}
        updateAngularVelocity(body);
    }
}

}  // namespace stepwise
