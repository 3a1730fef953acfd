/// @file symplectic_euler.cpp
/// @brief YOUR symplectic Euler (lecture 2): a student template (lectures/student-template/README.md).
///
/// Copied to student/integrators/symplectic_euler.cpp, it replaces
/// src/integrators/symplectic_euler.cpp in the student preset's build. It
/// defines the function src/integrators/integrators.hpp declares:
///
///     void integrateSymplecticEuler(std::span<DynamicObject> bodies, Real h);
///
/// Every body arrives with this step's acceleration in body.acceleration
/// (stage 1, apply forces). Move it by one step h, the velocity first, then
/// the position with the NEW velocity (lecture 2, "Symplectic (semi-implicit) Euler"):
///
///     v_{n+1} = v_n + h a_n
///     x_{n+1} = x_n + h v_{n+1}
///
/// Write it between the two YOUR CODE lines. The rotational half is given
/// (lecture 4 derives it). Until you write it, the stage stops with
/// "student stage not written yet: stepwise::integrateSymplecticEuler".
/// Test it: ctest --preset student -L symplectic-euler
#include "core/student_todo.hpp"
#include "objects/inertia.hpp"
#include "integrators/integrators.hpp"

namespace stepwise {

void integrateSymplecticEuler(std::span<DynamicObject> bodies, Real h) {
    for (DynamicObject& body : bodies) {
        if (body.asleep) continue;  // a sleeping body keeps its state until its island wakes

        // ==== YOUR CODE BEGINS: lecture 2, "Symplectic (semi-implicit) Euler" ====
        // TODO: the velocity v += h*a, then the position x += h*v with the NEW velocity.
        studentTodo("stepwise::integrateSymplecticEuler (integrators/symplectic_euler.cpp): "
                    "write v += h*a, then x += h*v with the new v (lecture 2, Symplectic Euler)",
                    body, h);
        // ==== YOUR CODE ENDS ====

        if (skipsRotation(body)) continue;  // a still sphere: the rotation below would change nothing
        // Rotation, given: kick the angular momentum with the torque, then turn the body
        // torque-free with the new momentum (lecture 4; src/integrators/free_rotation.cpp).
        body.angularMomentum += h * body.torque;
        body.orientation = rotateTorqueFree(body.orientation, body.angularMomentum, body.inverseInertiaBody, h);
        updateAngularVelocity(body);
    }
}

}  // namespace stepwise
