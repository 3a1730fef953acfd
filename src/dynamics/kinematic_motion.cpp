/// @file kinematic_motion.cpp
/// @brief Stage 3: prescribed motion of kinematic bodies (the maths is in kinematic_motion.hpp).
#include "dynamics/kinematic_motion.hpp"

#include "integrators/integrators.hpp"

namespace stepwise {

void moveKinematics(std::span<KinematicsObject> bodies, Real h) {
    for (KinematicsObject& body : bodies) {
        body.position += h * body.velocity;
        body.orientation = rotateByAngularVelocity(body.orientation, body.angularVelocity, h);
    }
}

}  // namespace stepwise
