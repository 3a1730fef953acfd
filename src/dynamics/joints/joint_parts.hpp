/// @file joint_parts.hpp
/// @brief What the five joint files share: a joint's geometry at a pose, impulses, effective masses, soft rows.
///
/// Internal to src/dynamics/joints/: joint.cpp dispatches on JointKind to the
/// per-type functions declared at the end, each defined in its own file with
/// its derivation (distance_joint.cpp, rope.cpp, ball_joint.cpp,
/// hinge_joint.cpp, angular_motor.cpp). A `switch`, not a virtual call: the
/// joints are one contiguous array of one struct.
#pragma once

#include <span>

#include "dynamics/joints/joint.hpp"

namespace stepwise {

/// @brief Shorter than this, m, the direction between two anchors is undefined (a rod or rope of length ~0).
inline constexpr Real kDegenerateJointLength = Real(1e-9);

/// @brief Where a joint's anchors are with its bodies at given poses (the world counts as a body at rest at the origin).
struct JointFrame {
    Vec3 rA{0, 0, 0};  ///< Lever arm of A's anchor, world frame: q_A·(local anchor), m.
    Vec3 rB{0, 0, 0};  ///< The same for B (zero for the world), m.
    Vec3 pA{0, 0, 0};  ///< A's anchor, x_A + r_A, m.
    Vec3 pB{0, 0, 0};  ///< B's anchor, x_B + r_B (the fixed point for the world), m.
};

/// @brief The frame of @p joint with A at @p poseA and B at @p poseB (ignored when B is the world).
inline JointFrame frameAt(const Joint& joint, const Pose& poseA, const Pose& poseB);

/// @brief The frame of a prepared joint at the recorded @p poses.
inline JointFrame frameAt(const SolverJoint& j, std::span<const Pose> poses);

/// @brief How a joint's two bodies are turned: what the hinge and the motor carry their axes by.
///
/// Apart from JointFrame because only those two need it: the point and
/// axial rows use the lever arms alone.
struct JointOrientations {
    Quat a{1, 0, 0, 0};  ///< q_A.
    Quat b{1, 0, 0, 0};  ///< q_B (identity for the world).
};

/// @brief The orientations of a prepared joint's bodies at the recorded @p poses.
JointOrientations orientationsAt(const SolverJoint& j, std::span<const Pose> poses);

/// @brief The unit axis @p n from p_A to p_B and their distance @p length (m); false when they coincide (no axis).
bool jointAxis(const JointFrame& f, Vec3& n, Real& length);

/// @brief [r]×, the matrix with [r]×·v = r × v.
Mat3 skew(const Vec3& r);

/// @brief A symmetric 3×3 matrix by its six distinct entries: an inverse inertia, a ball joint's K.
///
/// K = J·M⁻¹·Jᵀ is symmetric for any J, because M⁻¹ is: of its nine entries
/// only six need computing, and K·x = b has a cheaper solve than a general
/// matrix's inverse (solveSymmetric()).
struct SymmetricMat3 {
    Real xx = 0;  ///< Row x, column x.
    Real yy = 0;  ///< Row y, column y.
    Real zz = 0;  ///< Row z, column z.
    Real xy = 0;  ///< Row x, column y (= row y, column x).
    Real xz = 0;  ///< Row x, column z (= row z, column x).
    Real yz = 0;  ///< Row y, column z (= row z, column y).
};

/// @brief The entries of @p m on and above its diagonal (@p m symmetric, as R·I⁻¹·Rᵀ is up to round-off).
inline SymmetricMat3 symmetricPart(const Mat3& m);

/// @brief The sum @p m + @p n.
inline SymmetricMat3 operator+(const SymmetricMat3& m, const SymmetricMat3& n);

/// @brief The product @p m · @p v.
inline Vec3 operator*(const SymmetricMat3& m, const Vec3& v);

/// @brief The quadratic form v·M·v (for M = I⁻¹ and a unit axis v: the inverse moment of inertia about v).
inline Real quadraticForm(const SymmetricMat3& m, const Vec3& v);

/// @brief [r]×ᵀ·M·[r]× = −[r]×·M·[r]× for a symmetric M (its definition below has it entry by entry).
///
/// With M = I⁻¹ and r a lever arm, this is how much a point at r gives way
/// by turning the body: an impulse P there changes its velocity by
/// −r × (I⁻¹(r × P)) = [r]×ᵀ I⁻¹ [r]× · P. Symmetric, and positive semi-definite.
inline SymmetricMat3 leverArmTerm(const SymmetricMat3& m, const Vec3& r);

/// @brief Solves K·@p x = @p b for a symmetric @p K, by K⁻¹ = adj(K)/det(K).
/// @return false, leaving @p x unchanged, when det(K) ≤ 0 (K is not positive definite: nothing to solve).
inline bool solveSymmetric(const SymmetricMat3& K, const Vec3& b, Vec3& x);

/// @brief Velocity of B's anchor minus A's anchor: (v_B + ω_B×r_B) − (v_A + ω_A×r_A), m/s.
inline Vec3 relativeAnchorVelocity(const SolverJoint& j, const JointFrame& f);

/// @brief Angular velocity of A relative to B: ω_A − ω_B, rad/s.
inline Vec3 relativeAngularVelocity(const SolverJoint& j);

/// @brief Linear impulse @p impulse on B at its anchor and −@p impulse on A at its anchor (N·s).
inline void applyLinearImpulse(SolverJoint& j, const JointFrame& f, const Vec3& impulse);

/// @brief Angular impulse @p impulse on A and −@p impulse on B (N·m·s).
inline void applyAngularImpulse(SolverJoint& j, const Vec3& impulse);

/// @brief K⁻¹ of a row along unit direction @p n through the anchors:
/// 1 / (m_A⁻¹ + m_B⁻¹ + (r_A×n)·I_A⁻¹(r_A×n) + (r_B×n)·I_B⁻¹(r_B×n)), kg.
Real axialMass(const SolverJoint& j, const JointFrame& f, const Vec3& n);

/// @brief I_A⁻¹ + I_B⁻¹, by its six distinct entries: an angular impulse L on A and −L on B changes ω_A − ω_B by it times L.
SymmetricMat3 relativeInverseInertia(const SolverJoint& j);

/// @brief K⁻¹ of an angular row about unit axis @p a: 1 / (a·(I_A⁻¹ + I_B⁻¹)·a), kg·m².
/// @param inverseInertia I_A⁻¹ + I_B⁻¹ (relativeInverseInertia())
Real angularMass(const SymmetricMat3& inverseInertia, const Vec3& a);

/// @brief The soft terms of one row in one pass: Ċ is driven to −bias, the
/// effective mass is scaled by massScale and impulseScale·λ_acc leaks (softness.hpp).
struct RowSoftness {
    Real biasRate = 0;      ///< b, 1/s (0: no position feedback).
    Real massScale = 1;     ///< s_m.
    Real impulseScale = 0;  ///< s_i.
};

/// @brief An equality row (C = 0): soft in the biased pass, rigid velocities-only in the relax pass.
RowSoftness equalityRow(const JointSolverSettings& settings, bool useBias);

/// @brief The bias velocity and scales of a one-sided row that wants C ≥ 0.
///
/// Like a contact: while C > 0 (slack) the row is *speculative*, bias C/h_s:
/// the bodies may close the gap within this substep but not pass it, and no
/// impulse acts unless they would. At or past the limit (C ≤ 0) it is an
/// equality row. The accumulated impulse is then clamped to ≥ 0.
/// @param[out] bias the velocity bias to add to Ċ, m/s or rad/s
RowSoftness inequalityRow(Real C, const JointSolverSettings& settings, bool useBias, Real& bias);

// The types, one file each. warmStart* applies the joint's accumulated impulses
// (at the start of a substep); solve* makes one Gauss–Seidel iteration.

/// @brief Distance and rope: the accumulated axial impulse along the current axis (distance_joint.cpp).
void warmStartAxial(SolverJoint& j, const JointFrame& f);
/// @brief Rigid rod: C = |p_B − p_A| − L = 0 (distance_joint.cpp).
void solveDistanceJoint(SolverJoint& j, const JointFrame& f, const JointSolverSettings& settings, bool useBias);
/// @brief Rope: C = |p_B − p_A| − L ≤ 0, one-sided (rope.cpp).
void solveRope(SolverJoint& j, const JointFrame& f, const JointSolverSettings& settings, bool useBias);
/// @brief Ball joint: the accumulated point impulse (ball_joint.cpp).
void warmStartBallJoint(SolverJoint& j, const JointFrame& f);
/// @brief Ball joint: C = p_B − p_A = 0, a 3×3 block (ball_joint.cpp). The hinge reuses it for its point.
void solveBallJoint(SolverJoint& j, const JointFrame& f, const JointSolverSettings& settings, bool useBias);
/// @brief Hinge: point, alignment, limit and motor impulses (hinge_joint.cpp).
void warmStartHingeJoint(SolverJoint& j, const JointFrame& f, const JointOrientations& q);
/// @brief Hinge: motor, limits, axis alignment (2 rows), then the point (hinge_joint.cpp).
void solveHingeJoint(SolverJoint& j, const JointFrame& f, const JointOrientations& q, const JointSolverSettings& settings,
                     bool useBias);
/// @brief Angular motor: the accumulated motor impulse about the axis (angular_motor.cpp).
void warmStartAngularMotor(SolverJoint& j, const JointOrientations& q);
/// @brief Angular motor: (ω_A − ω_B)·a → target, |λ_acc| ≤ τ_max·h_s (angular_motor.cpp).
void solveAngularMotor(SolverJoint& j, const JointOrientations& q, const JointSolverSettings& settings);

/// @brief One clamped motor row about unit axis @p a (shared by the hinge and the angular motor):
/// λ = −K⁻¹((ω_A − ω_B)·a − target), accumulated impulse kept within ±maxMotorTorque·h_s.
/// @param mass K⁻¹ of the row, angularMass() about @p a, kg·m²
void solveMotorRow(SolverJoint& j, const Vec3& a, Real mass, Real substep);

// ------------------------------------------------------------------ inline definitions
// The pieces every row of every pass calls, defined here so that the compiler
// builds them into the row that calls them (no call, the frame kept in registers).

inline JointFrame frameAt(const Joint& joint, const Pose& poseA, const Pose& poseB) {
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

inline JointFrame frameAt(const SolverJoint& j, std::span<const Pose> poses) {
    const Joint& joint = *j.joint;
    const Pose& poseA = poses[joint.bodyA];
    return frameAt(joint, poseA, joint.bodyB == kWorldAnchor ? poseA : poses[joint.bodyB]);
}

inline SymmetricMat3 symmetricPart(const Mat3& m) {
    // GLM indexes m[column][row]: m[1][0] is row x, column y.
    return {m[0][0], m[1][1], m[2][2], m[1][0], m[2][0], m[2][1]};
}

inline SymmetricMat3 operator+(const SymmetricMat3& m, const SymmetricMat3& n) {
    return {m.xx + n.xx, m.yy + n.yy, m.zz + n.zz, m.xy + n.xy, m.xz + n.xz, m.yz + n.yz};
}

inline Vec3 operator*(const SymmetricMat3& m, const Vec3& v) {
    return {m.xx * v.x + m.xy * v.y + m.xz * v.z,  //
            m.xy * v.x + m.yy * v.y + m.yz * v.z,  //
            m.xz * v.x + m.yz * v.y + m.zz * v.z};
}

inline Real quadraticForm(const SymmetricMat3& m, const Vec3& v) {
    // v·M·v = Σ M_ii v_i² + 2 Σ_{i<j} M_ij v_i v_j
    return m.xx * v.x * v.x + m.yy * v.y * v.y + m.zz * v.z * v.z +
           Real(2) * (m.xy * v.x * v.y + m.xz * v.x * v.z + m.yz * v.y * v.z);
}

inline SymmetricMat3 leverArmTerm(const SymmetricMat3& m, const Vec3& r) {
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

inline bool solveSymmetric(const SymmetricMat3& K, const Vec3& b, Vec3& x) {
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

inline Vec3 relativeAnchorVelocity(const SolverJoint& j, const JointFrame& f) {
    const Vec3 velocityA = j.a->velocity + glm::cross(j.a->angularVelocity, f.rA);
    const Vec3 velocityB = j.b ? j.b->velocity + glm::cross(j.b->angularVelocity, f.rB) : Vec3(0);
    return velocityB - velocityA;
}

inline Vec3 relativeAngularVelocity(const SolverJoint& j) {
    return j.a->angularVelocity - (j.b ? j.b->angularVelocity : Vec3(0));
}

// Both impulse functions change v, L and ω together, ω through the inverse
// inertia taken at the start of the substep (warmStartJoints()); the body
// turns by ω·h_s within it, and finishJoints() makes ω = I⁻¹(q)·L exact again.

inline void applyLinearImpulse(SolverJoint& j, const JointFrame& f, const Vec3& impulse) {
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

inline void applyAngularImpulse(SolverJoint& j, const Vec3& impulse) {
    j.a->angularMomentum += impulse;
    j.a->angularVelocity += j.inverseInertiaA * impulse;
    if (j.b) {
        j.b->angularMomentum -= impulse;
        j.b->angularVelocity -= j.inverseInertiaB * impulse;
    }
}

}  // namespace stepwise
