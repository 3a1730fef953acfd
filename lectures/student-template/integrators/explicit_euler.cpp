/// @file explicit_euler.cpp
/// @brief YOUR explicit Euler (lecture 1): a student template (lectures/student-template/README.md).
///
/// Copied to student/integrators/explicit_euler.cpp, it replaces
/// src/integrators/explicit_euler.cpp in the student preset's build. It
/// defines the function src/integrators/integrators.hpp declares:
///
///     void integrateExplicitEuler(std::span<DynamicObject> bodies, Real h);
///
/// Every body arrives with this step's acceleration in body.acceleration
/// (stage 1, apply forces). Move it by one step h, both updates from the state
/// at the START of the step (lecture 1, "The math"):
///
///     x_{n+1} = x_n + h v_n
///     v_{n+1} = v_n + h a_n
///
/// Write it between the two YOUR CODE lines. The rotational half is given
/// (lecture 4 derives it). Until you write it, the stage stops with
/// "student stage not written yet: stepwise::integrateExplicitEuler".
/// Test it: ctest --preset student -L '^euler$'
#include "core/student_todo.hpp"
#include "objects/inertia.hpp"
#include "integrators/integrators.hpp"

namespace stepwise {

void integrateExplicitEuler(std::span<DynamicObject> bodies, Real h) {
    for (DynamicObject& body : bodies) {
        if (body.asleep) continue;  // a sleeping body keeps its state until its island wakes

        // ==== YOUR CODE BEGINS: lecture 1, "The math" ====
        // TODO: the position x += h*v with the OLD velocity, then the velocity v += h*a.
        studentTodo("stepwise::integrateExplicitEuler (integrators/explicit_euler.cpp): "
                    "write x += h*v with the old v, then v += h*a (lecture 1, The math)",
                    body, h);
        // ==== YOUR CODE ENDS ====

        if (skipsRotation(body)) continue;  // a still sphere: the rotation below would change nothing
        // Rotation, given, the same way round: turn by the OLD angular velocity
        // omega_n = I_world(q_n)^-1 L_n, then update L with the torque (lecture 4).
        updateAngularVelocity(body);
        body.orientation = rotateByAngularVelocity(body.orientation, body.angularVelocity, h);  // normalised
        body.angularMomentum += h * body.torque;
        updateAngularVelocity(body);  // omega_{n+1} for the next step, the contacts and the output
    }
}

}  // namespace stepwise
