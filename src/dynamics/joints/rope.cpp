/// @file rope.cpp
/// @brief Rope: the anchors may come closer than L but never farther apart. A slack rope does nothing.
///
/// **Position constraint**, one-sided, written so that "satisfied" is ≥ 0 as
/// for a contact: with d = p_B − p_A,
/// \f[ C = L - |d| \ge 0 . \f]
///
/// **Velocity constraint.** With n = d/|d| the same axis as the distance
/// joint's (distance_joint.cpp), only with the sign turned round:
/// \f[ \dot C = -n\cdot\big(v_B + \omega_B\times r_B - v_A - \omega_A\times r_A\big), \qquad
///     J = \begin{bmatrix} n^T & (r_A\times n)^T & -n^T & -(r_B\times n)^T \end{bmatrix}, \f]
/// and the same effective mass K (the sign of J cancels in J M⁻¹ Jᵀ).
///
/// **One-sided impulse.** A rope can only pull: the accumulated impulse
/// λ_acc ≥ 0 (it pulls B towards A by λ along −n). Each iteration computes
/// λ = −s_m K⁻¹(Ċ + bias) − s_i λ_acc, then clamps the *total*,
/// λ_acc ← max(λ_acc + λ, 0), exactly as a contact clamps its normal
/// impulse (contact_solver.hpp), so an overshoot of an early iteration can be
/// taken back by a later one.
///
/// **Slack is speculative.** While the rope is slack (C > 0) the bias is
/// C/h_s: the anchors may separate by the remaining slack within this
/// substep but not more, so a falling body is caught exactly when the rope
/// becomes taut, and nothing acts before (tests/test_joints.cpp: the body
/// falls freely until then). Taut (C ≤ 0) it is soft like the rod.
/// Joint::axialImpulse keeps the impulse as the rod does (along +n on B), so
/// it is −λ_acc ≤ 0 here and the distance joint's warm start serves both.
///
/// References: Catto, "Modeling and Solving Constraints" (GDC 2009);
/// Box2D v3 `distance_joint.c` (its maximum-length limit is this rope).
#include <algorithm>

#include "dynamics/joints/joint_parts.hpp"

namespace stepwise {

void solveRope(SolverJoint& j, const JointFrame& f, const JointSolverSettings& settings, bool useBias) {
    Joint& joint = *j.joint;
    Vec3 n;
    Real length = 0;
    if (!jointAxis(f, n, length)) return;  // anchors together: the rope is slack anyway

    const Real C = joint.length - length;                          // ≥ 0: slack, m
    const Real Cdot = -glm::dot(relativeAnchorVelocity(j, f), n);  // m/s
    Real bias = 0;
    const RowSoftness soft = inequalityRow(C, settings, useBias, bias);
    const Real pull = -joint.axialImpulse;  // λ_acc ≥ 0
    const Real impulse = -soft.massScale * axialMass(j, f, n) * (Cdot + bias) - soft.impulseScale * pull;
    const Real newPull = std::max(pull + impulse, Real(0));
    joint.axialImpulse = -newPull;
    applyLinearImpulse(j, f, -(newPull - pull) * n);
}

}  // namespace stepwise
