/// @file apply_forces.cpp
/// @brief YOUR stage 1, apply forces (lecture 1): a student template (lectures/student-template/README.md).
///
/// Copied to student/forces/apply_forces.cpp, it replaces
/// src/forces/apply_forces.cpp in the student preset's build. It defines the
/// functions src/forces/apply_forces.hpp declares; you write the first:
///
///     void applyUniformForces(std::span<DynamicObject> bodies, const Vec3& gravity);
///
/// Newton's second law with F = m g + m a_obj gives, for every body
/// (lecture 1, "The math", where the acceleration comes from):
///
///     a   = g + a_obj     (body.acceleration; a_obj is body.constantAcceleration)
///     tau = 0             (body.torque: a uniform field pulls at the centre of mass)
///
/// Both are written from nothing every step: springs and attractors add to
/// them afterwards (SceneForces below, given). Until you write it, the stage
/// stops with "student stage not written yet: stepwise::applyUniformForces".
/// Test it: ctest --preset student -L forces
#include "core/student_todo.hpp"
#include "forces/apply_forces.hpp"

namespace stepwise {

void applyUniformForces(std::span<DynamicObject> bodies, const Vec3& gravity) {
    for (DynamicObject& body : bodies) {
        // ==== YOUR CODE BEGINS: lecture 1, "The math" (where the acceleration comes from) ====
        // TODO: body.acceleration = gravity plus the body's own constant acceleration; body.torque = zero.
        studentTodo("stepwise::applyUniformForces (forces/apply_forces.cpp): "
                    "write a = g + a_obj and tau = 0 for every body (lecture 1, The math)",
                    body, gravity);
        // ==== YOUR CODE ENDS ====
    }
}

AccelerationFunction uniformForces(const Vec3& gravity) {
    return [gravity](std::span<DynamicObject> bodies) { applyUniformForces(bodies, gravity); };
}

void SceneForces::operator()(std::span<DynamicObject> bodies) const {
    applyUniformForces(bodies, gravity);  // sets a = g + a_obj and tau = 0
    applySprings(bodies, springs);        // adds F/m and r x F at each anchor (spring.cpp)
    applyAttractors(bodies, attractors);  // adds -mu r/|r|^3 (attractor.cpp)
    applyRegions(bodies, regions);        // adds drag, wind, buoyancy, ... on the bodies inside (region.cpp)
}

}  // namespace stepwise
