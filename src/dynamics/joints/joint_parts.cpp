/// @file joint_parts.cpp
/// @brief The pieces every joint type is built from (see joint_parts.hpp).
#include "dynamics/joints/joint_parts.hpp"

namespace stepwise {

JointFrame frameAt(const Joint& joint, const Pose& poseA, const Pose& poseB) {
    JointFrame f;
    f.orientationA = poseA.orientation;
    f.rA = poseA.orientation * joint.localAnchorA;
    f.pA = poseA.position + f.rA;
    if (joint.bodyB == kWorldAnchor) {
        f.pB = joint.localAnchorB;  // a fixed point of the world
    } else {
        f.orientationB = poseB.orientation;
        f.rB = poseB.orientation * joint.localAnchorB;
        f.pB = poseB.position + f.rB;
    }
    return f;
}

JointFrame frameAt(const SolverJoint& j, std::span<const Pose> poses) {
    const Joint& joint = *j.joint;
    const Pose& poseA = poses[joint.bodyA];
    return frameAt(joint, poseA, joint.bodyB == kWorldAnchor ? poseA : poses[joint.bodyB]);
}

bool jointAxis(const JointFrame& f, Vec3& n, Real& length) {
    const Vec3 d = f.pB - f.pA;
    length = glm::length(d);
    if (length < kDegenerateJointLength) return false;
    n = d / length;
    return true;
}

Mat3 skew(const Vec3& r) {
    // GLM matrices are built from columns: these are the columns of
    // [[0, −r_z, r_y], [r_z, 0, −r_x], [−r_y, r_x, 0]].
    return Mat3(Vec3(0, r.z, -r.y), Vec3(-r.z, 0, r.x), Vec3(r.y, -r.x, 0));
}

Vec3 relativeAnchorVelocity(const SolverJoint& j, const JointFrame& f) {
    const Vec3 velocityA = j.a->velocity + glm::cross(j.a->angularVelocity, f.rA);
    const Vec3 velocityB = j.b ? j.b->velocity + glm::cross(j.b->angularVelocity, f.rB) : Vec3(0);
    return velocityB - velocityA;
}

Vec3 relativeAngularVelocity(const SolverJoint& j) {
    return j.a->angularVelocity - (j.b ? j.b->angularVelocity : Vec3(0));
}

// Both impulse functions change v, L and ω together, ω through the inverse
// inertia fixed at the start of the step (as the contact solver does);
// finishJoints() makes ω = I⁻¹(q)·L exact again.

void applyLinearImpulse(SolverJoint& j, const JointFrame& f, const Vec3& impulse) {
    const Vec3 turnA = glm::cross(f.rA, impulse);
    j.a->velocity -= j.inverseMassA * impulse;
    j.a->angularMomentum -= turnA;
    j.a->angularVelocity -= j.inverseInertiaA * turnA;
    if (j.b) {
        const Vec3 turnB = glm::cross(f.rB, impulse);
        j.b->velocity += j.inverseMassB * impulse;
        j.b->angularMomentum += turnB;
        j.b->angularVelocity += j.inverseInertiaB * turnB;
    }
}

void applyAngularImpulse(SolverJoint& j, const Vec3& impulse) {
    j.a->angularMomentum += impulse;
    j.a->angularVelocity += j.inverseInertiaA * impulse;
    if (j.b) {
        j.b->angularMomentum -= impulse;
        j.b->angularVelocity -= j.inverseInertiaB * impulse;
    }
}

Real axialMass(const SolverJoint& j, const JointFrame& f, const Vec3& n) {
    const Vec3 turnA = glm::cross(f.rA, n);
    const Vec3 turnB = glm::cross(f.rB, n);
    const Real inverse = j.inverseMassA + j.inverseMassB + glm::dot(turnA, j.inverseInertiaA * turnA) +
                         glm::dot(turnB, j.inverseInertiaB * turnB);
    return inverse > 0 ? Real(1) / inverse : Real(0);
}

Real angularMass(const SolverJoint& j, const Vec3& a) {
    const Real inverse = glm::dot(a, (j.inverseInertiaA + j.inverseInertiaB) * a);
    return inverse > 0 ? Real(1) / inverse : Real(0);
}

RowSoftness equalityRow(const JointSolverSettings& settings, bool useBias) {
    if (!useBias || !settings.positionCorrection) return {};
    return {settings.softness.biasRate, settings.softness.massScale, settings.softness.impulseScale};
}

RowSoftness inequalityRow(Real C, const JointSolverSettings& settings, bool useBias, Real& bias) {
    if (C > 0) {
        bias = C / settings.substep;  // speculative: may close the gap in this substep, not more
        return {};
    }
    const RowSoftness soft = equalityRow(settings, useBias);
    bias = soft.biasRate * C;
    return soft;
}

void solveMotorRow(SolverJoint& j, const Vec3& a, Real substep) {
    Joint& joint = *j.joint;
    // Ċ = (ω_A − ω_B)·a − target; rigid (no bias, no softness): a motor is a
    // velocity constraint, its strength is its torque bound, not a spring.
    const Real Cdot = glm::dot(relativeAngularVelocity(j), a) - joint.motorSpeed;
    const Real maxImpulse = joint.maxMotorTorque * substep;
    const Real old = joint.motorImpulse;
    joint.motorImpulse = glm::clamp(old - angularMass(j, a) * Cdot, -maxImpulse, maxImpulse);
    applyAngularImpulse(j, (joint.motorImpulse - old) * a);
}

}  // namespace stepwise
