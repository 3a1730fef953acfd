/// @file joint_parts.cpp
/// @brief The pieces every joint type is built from (see joint_parts.hpp).
#include "dynamics/joints/joint_parts.hpp"

namespace stepwise {

JointOrientations orientationsAt(const SolverJoint& j, std::span<const Pose> poses) {
    JointOrientations q;
    q.a = poses[j.joint->bodyA].orientation;
    if (j.joint->bodyB != kWorldAnchor) q.b = poses[j.joint->bodyB].orientation;
    return q;
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

Real axialMass(const SolverJoint& j, const JointFrame& f, const Vec3& n) {
    const Vec3 turnA = glm::cross(f.rA, n);
    const Vec3 turnB = glm::cross(f.rB, n);
    const Real inverse = j.inverseMassA + j.inverseMassB + glm::dot(turnA, j.inverseInertiaA * turnA) +
                         glm::dot(turnB, j.inverseInertiaB * turnB);
    return inverse > 0 ? Real(1) / inverse : Real(0);
}

SymmetricMat3 relativeInverseInertia(const SolverJoint& j) {
    return symmetricPart(j.inverseInertiaA) + symmetricPart(j.inverseInertiaB);
}

Real angularMass(const SymmetricMat3& inverseInertia, const Vec3& a) {
    const Real inverse = quadraticForm(inverseInertia, a);
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

void solveMotorRow(SolverJoint& j, const Vec3& a, Real mass, Real substep) {
    Joint& joint = *j.joint;
    // Ċ = (ω_A − ω_B)·a − target; rigid (no bias, no softness): a motor is a
    // velocity constraint, its strength is its torque bound, not a spring.
    const Real Cdot = glm::dot(relativeAngularVelocity(j), a) - joint.motorSpeed;
    const Real maxImpulse = joint.maxMotorTorque * substep;
    const Real old = joint.motorImpulse;
    joint.motorImpulse = glm::clamp(old - mass * Cdot, -maxImpulse, maxImpulse);
    applyAngularImpulse(j, (joint.motorImpulse - old) * a);
}

}  // namespace stepwise
