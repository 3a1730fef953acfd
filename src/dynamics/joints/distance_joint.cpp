/// @file distance_joint.cpp
/// @brief DistanceJoint: a rigid, massless rod of length L between two anchors.
///
/// **Position constraint.** With the anchors p_A = x_A + r_A and
/// p_B = x_B + r_B, and d = p_B − p_A,
/// \f[ C = |d| - L = 0 . \f]
///
/// **Velocity constraint.** With the unit axis n = d/|d| and ṗ = v + ω × r,
/// \f[ \dot C = n\cdot(\dot p_B - \dot p_A)
///           = n\cdot\big(v_B + \omega_B\times r_B - v_A - \omega_A\times r_A\big) = J\,v, \f]
/// and since n·(ω × r) = (r × n)·ω,
/// \f[ J = \begin{bmatrix} -n^T & -(r_A\times n)^T & n^T & (r_B\times n)^T \end{bmatrix}. \f]
///
/// **Effective mass.** An impulse λ along J (λn on B at p_B, −λn on A at p_A) changes Ċ by K·λ with
/// \f[ K = J M^{-1} J^T = m_A^{-1} + m_B^{-1} + (r_A\times n)\cdot I_A^{-1}(r_A\times n)
///       + (r_B\times n)\cdot I_B^{-1}(r_B\times n) . \f]
/// The terms with r are the rod turning the bodies: an anchor off the
/// centre gives way more easily than one at the centre.
///
/// **Impulse, soft.** In the biased pass (softness.hpp, b = biasRate)
/// \f[ \lambda = -s_m K^{-1}(\dot C + b\,C) - s_i\,\lambda_\text{acc}, \f]
/// and in the relax pass λ = −K⁻¹·Ċ. No clamp: a rod pushes as well as
/// pulls. The axis n is recomputed at every iteration from the poses, because
/// the constraint is non-linear: as the pendulum swings, n turns with it.
///
/// **Pendulum check** (tests/test_joints.cpp): a bob on a 1 m rod, released
/// at 5°, swings with the period 2π√(L/g)·(1 + θ₀²/16 + …) and keeps its
/// length to well under a millimetre.
///
/// References: Catto, "Modeling and Solving Constraints" (GDC 2009), the
/// distance constraint; Box2D v3 `distance_joint.c` (rigid branch).
#include "dynamics/joints/joint_parts.hpp"

namespace stepwise {

void warmStartAxial(SolverJoint& j, const JointFrame& f) {
    Vec3 n;
    Real length = 0;
    if (jointAxis(f, n, length)) applyLinearImpulse(j, f, j.joint->axialImpulse * n);
}

void solveDistanceJoint(SolverJoint& j, const JointFrame& f, const JointSolverSettings& settings, bool useBias) {
    Joint& joint = *j.joint;
    Vec3 n;
    Real length = 0;
    if (!jointAxis(f, n, length)) return;

    const Real C = length - joint.length;                        // m
    const Real Cdot = glm::dot(relativeAnchorVelocity(j, f), n);  // m/s
    const RowSoftness soft = equalityRow(settings, useBias);
    const Real impulse = -soft.massScale * axialMass(j, f, n) * (Cdot + soft.biasRate * C) -
                         soft.impulseScale * joint.axialImpulse;
    joint.axialImpulse += impulse;
    applyLinearImpulse(j, f, impulse * n);
}

}  // namespace stepwise
