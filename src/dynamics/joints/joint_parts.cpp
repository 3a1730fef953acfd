/// @file joint_parts.cpp
/// @brief The pieces every joint type is built from (see joint_parts.hpp).
#include "dynamics/joints/joint_parts.hpp"

namespace stepwise {

JointFrame frameAt(const Joint& joint, const Pose& poseA, const Pose& poseB) {
    JointFrame f;
    f.rA = poseA.orientation * joint.localAnchorA;
    f.pA = poseA.position + f.rA;
    if (joint.bodyB == kWorldAnchor) {
        f.pB = joint.localAnchorB;  // a fixed point of the world
    } else {
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

SymmetricMat3 symmetricPart(const Mat3& m) {
    // GLM indexes m[column][row]: m[1][0] is row x, column y.
    return {m[0][0], m[1][1], m[2][2], m[1][0], m[2][0], m[2][1]};
}

SymmetricMat3 operator+(const SymmetricMat3& m, const SymmetricMat3& n) {
    return {m.xx + n.xx, m.yy + n.yy, m.zz + n.zz, m.xy + n.xy, m.xz + n.xz, m.yz + n.yz};
}

Vec3 operator*(const SymmetricMat3& m, const Vec3& v) {
    return {m.xx * v.x + m.xy * v.y + m.xz * v.z,  //
            m.xy * v.x + m.yy * v.y + m.yz * v.z,  //
            m.xz * v.x + m.yz * v.y + m.zz * v.z};
}

Real quadraticForm(const SymmetricMat3& m, const Vec3& v) {
    // v·M·v = Σ M_ii v_i² + 2 Σ_{i<j} M_ij v_i v_j
    return m.xx * v.x * v.x + m.yy * v.y * v.y + m.zz * v.z * v.z +
           Real(2) * (m.xy * v.x * v.y + m.xz * v.x * v.z + m.yz * v.y * v.z);
}

SymmetricMat3 leverArmTerm(const SymmetricMat3& m, const Vec3& r) {
    // The columns of [r]× are c_x = (0, z, −y), c_y = (−z, 0, x), c_z = (y, −x, 0)
    // (r = (x, y, z)), and entry (i, j) of [r]×ᵀ·M·[r]× is c_i·M·c_j:
    //   (x, x) = M_yy z² − 2 M_yz y z + M_zz y²
    //   (y, y) = M_xx z² − 2 M_xz x z + M_zz x²
    //   (z, z) = M_xx y² − 2 M_xy x y + M_yy x²
    //   (x, y) = −M_xy z² + M_yz x z + M_xz y z − M_zz x y
    //   (x, z) = −M_xz y² + M_xy y z + M_yz x y − M_yy x z
    //   (y, z) = −M_yz x² + M_xy x z + M_xz x y − M_xx y z
    const Real xx = r.x * r.x, yy = r.y * r.y, zz = r.z * r.z;
    const Real xy = r.x * r.y, xz = r.x * r.z, yz = r.y * r.z;
    SymmetricMat3 t;
    t.xx = m.yy * zz - Real(2) * m.yz * yz + m.zz * yy;
    t.yy = m.xx * zz - Real(2) * m.xz * xz + m.zz * xx;
    t.zz = m.xx * yy - Real(2) * m.xy * xy + m.yy * xx;
    t.xy = -m.xy * zz + m.yz * xz + m.xz * yz - m.zz * xy;
    t.xz = -m.xz * yy + m.xy * yz + m.yz * xy - m.yy * xz;
    t.yz = -m.yz * xx + m.xy * xz + m.xz * xy - m.xx * yz;
    return t;
}

bool solveSymmetric(const SymmetricMat3& K, const Vec3& b, Vec3& x) {
    // The adjugate (the transposed cofactors) of a symmetric matrix is symmetric: six cofactors.
    const Real cxx = K.yy * K.zz - K.yz * K.yz;
    const Real cyy = K.xx * K.zz - K.xz * K.xz;
    const Real czz = K.xx * K.yy - K.xy * K.xy;
    const Real cxy = K.xz * K.yz - K.xy * K.zz;
    const Real cxz = K.xy * K.yz - K.xz * K.yy;
    const Real cyz = K.xy * K.xz - K.xx * K.yz;
    const Real det = K.xx * cxx + K.xy * cxy + K.xz * cxz;  // expanded along the first row
    if (!(det > 0)) return false;
    x = (SymmetricMat3{cxx, cyy, czz, cxy, cxz, cyz} * b) / det;
    return true;
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
