/// @file ball_joint.cpp
/// @brief BallJoint (ball-and-socket): one point of A and one point of B stay together; every rotation is free.
///
/// **Position constraint**, three rows at once:
/// \f[ C = p_B - p_A = (x_B + r_B) - (x_A + r_A) = 0 \in \mathbb{R}^3 . \f]
///
/// **Velocity constraint.** Since ω × r = −[r]×ω, with [r]× the matrix of
/// the cross product (skew()),
/// \f[ \dot C = v_B + \omega_B\times r_B - v_A - \omega_A\times r_A = J\,v, \qquad
///     J = \begin{bmatrix} -E & [r_A]_\times & E & -[r_B]_\times \end{bmatrix}, \f]
/// E the 3×3 identity.
///
/// **Effective mass**, a 3×3 matrix: an impulse P at the anchors (P on B,
/// −P on A) changes the anchors' relative velocity by K·P with
/// \f[ K = J M^{-1} J^T = (m_A^{-1} + m_B^{-1})\,E
///       - [r_A]_\times I_A^{-1} [r_A]_\times - [r_B]_\times I_B^{-1} [r_B]_\times . \f]
/// (−[r]×I⁻¹[r]× = [r]×ᵀI⁻¹[r]× is positive semi-definite: turning the body
/// only ever makes the point give way more.) K is symmetric and positive
/// definite whenever one body has finite mass.
///
/// **Impulse, soft, as a block.** The three rows are solved together, not
/// one after the other: they share both bodies, and solving them in turn
/// would take many iterations to agree (the block solve is exact for the
/// linearised point in one go):
/// \f[ P = -s_m K^{-1}(\dot C + b\,C) - s_i P_\text{acc} . \f]
/// K is rebuilt at every iteration from the lever arms at the current poses.
///
/// **Computing it.** K is symmetric, so only its six distinct entries are
/// built: each body's term [r]×ᵀ I⁻¹ [r]× entry by entry (leverArmTerm(),
/// which writes them out), not as two products of 3×3 matrices. And K⁻¹ is
/// never formed: K·x = Ċ + b·C is solved as x = adj(K)·(Ċ + b·C)/det(K), the
/// adjugate of a symmetric matrix being symmetric too (solveSymmetric()).
///
/// References: Catto, "Modeling and Solving Constraints" (GDC 2009), the
/// point-to-point constraint; Box2D v3 `revolute_joint.c` (its point part,
/// there 2×2); Baraff, "Physically Based Modeling: Constrained Dynamics".
#include "dynamics/joints/joint_parts.hpp"

namespace stepwise {

void warmStartBallJoint(SolverJoint& j, const JointFrame& f) { applyLinearImpulse(j, f, j.joint->linearImpulse); }

void solveBallJoint(SolverJoint& j, const JointFrame& f, const JointSolverSettings& settings, bool useBias) {
    Joint& joint = *j.joint;
    const Vec3 C = f.pB - f.pA;                      // m
    const Vec3 Cdot = relativeAnchorVelocity(j, f);  // m/s
    const RowSoftness soft = equalityRow(settings, useBias);

    // K = (m_A⁻¹ + m_B⁻¹) E + [r_A]×ᵀ I_A⁻¹ [r_A]× + [r_B]×ᵀ I_B⁻¹ [r_B]×
    SymmetricMat3 K = leverArmTerm(symmetricPart(j.inverseInertiaA), f.rA);
    if (j.b) K = K + leverArmTerm(symmetricPart(j.inverseInertiaB), f.rB);
    const Real inverseMass = j.inverseMassA + j.inverseMassB;
    K.xx += inverseMass;
    K.yy += inverseMass;
    K.zz += inverseMass;
    Vec3 x;  // K⁻¹(Ċ + b·C), N·s
    if (!solveSymmetric(K, Cdot + soft.biasRate * C, x)) return;  // K singular: no impulse moves the anchors
    const Vec3 impulse = -soft.massScale * x - soft.impulseScale * joint.linearImpulse;
    joint.linearImpulse += impulse;
    applyLinearImpulse(j, f, impulse);
}

}  // namespace stepwise
