/// @file drag.cpp
/// @brief Effect=Drag: F = −c·v (linear) or −c·|v|·v (quadratic), τ = −c_ω·ω or −c_ω·|ω|·ω.
#include "forces/drag.hpp"

#include <algorithm>

namespace stepwise {

Vec3 dragForce(DragLaw law, Real coefficient, const Vec3& relativeVelocity) {
    switch (law) {
        case DragLaw::Linear: return -coefficient * relativeVelocity;
        case DragLaw::Quadratic: return -coefficient * glm::length(relativeVelocity) * relativeVelocity;
    }
    return Vec3(0);
}

Vec3 dragTorque(DragLaw law, Real angularCoefficient, const Vec3& angularVelocity) {
    return dragForce(law, angularCoefficient, angularVelocity);  // the same two laws, about the centre of mass
}

namespace {

/// Scales @p push down so that, acting for @p seconds on a body of "inverse mass" @p inverse
/// (1/m, or the largest principal 1/I for a torque), it changes the motion by at most |motion|:
/// drag may stop a body relative to the fluid within a substep, never throw it backwards.
Vec3 capAtStop(const Vec3& push, const Vec3& motion, Real inverse, Real seconds) {
    const Real change = glm::length(push) * inverse * seconds;  // |Δv| = |F|·h/m
    const Real limit = glm::length(motion);
    if (change <= limit || change == 0) return push;
    return push * (limit / change);
}

}  // namespace

void addDrag(DynamicObject& body, const Region& region, const Vec3& fluidVelocity, Real share, Real substepTime) {
    const Vec3 relative = body.velocity - fluidVelocity;
    const Vec3 force = capAtStop(share * dragForce(region.law, region.coefficient, relative), relative,
                                 body.inverseMass, substepTime);
    body.acceleration += force * body.inverseMass;  // a = F/m
    if (region.angularCoefficient > 0) {
        const Real largestInverseMoment =
            std::max({body.inverseInertiaBody.x, body.inverseInertiaBody.y, body.inverseInertiaBody.z});
        body.torque += capAtStop(share * dragTorque(region.law, region.angularCoefficient, body.angularVelocity),
                                 body.angularVelocity, largestInverseMoment, substepTime);
    }
}

}  // namespace stepwise
