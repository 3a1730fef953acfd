/// @file hinge_joint.cpp
/// @brief HingeJoint (revolute): a ball joint that also keeps an axis of A aligned with an axis of B,
/// so only the turn about that axis is free; optional angle limits and a torque-limited motor.
///
/// **The point.** p_B − p_A = 0, three rows: exactly the ball joint
/// (ball_joint.cpp), solved by solveBallJoint().
///
/// **The axis, two rows.** Let a_A = q_A·(A's local axis) and
/// a_B = q_B·(B's local axis) be the hinge axis as each body carries it,
/// and p₁, p₂ two unit vectors perpendicular to a_B that turn with B
/// (Joint::localPerpendicularB). The axes are aligned when a_A has no
/// component along p₁ or p₂:
/// \f[ C_i = a_A\cdot p_i = 0, \qquad i = 1, 2 . \f]
/// Differentiating, with ȧ_A = ω_A × a_A and ṗ_i = ω_B × p_i,
/// \f[ \dot C_i = (\omega_A\times a_A)\cdot p_i + a_A\cdot(\omega_B\times p_i)
///             = (\omega_A - \omega_B)\cdot(a_A\times p_i), \f]
/// so with d_i = a_A × p_i the Jacobian rows are J_i = [0, d_iᵀ, 0, −d_iᵀ]:
/// no linear part, an angular impulse λ_i·d_i on A and −λ_i·d_i on B. The
/// effective mass is the 2×2 matrix
/// \f[ K_{ij} = d_i\cdot(I_A^{-1} + I_B^{-1})\,d_j , \f]
/// and the two rows are solved as a block (Cramer's rule), soft like the point:
/// λ = −s_m K⁻¹(Ċ + b·C) − s_i λ_acc. (d₁, d₂ are nearly p₂ and −p₁ while the
/// axes are nearly aligned, so K is well conditioned.)
///
/// **The angle.** The rotation of A relative to B since the start is
/// r = q_B⁻¹·q_A·q_ref⁻¹ (q_ref = q_B⁻¹·q_A at the start), expressed in
/// B's frame; with the axes aligned it is a turn about B's local axis â, and
/// its angle is θ = 2·atan2(r_xyz·â, r_w) (hingeAngle()). Its rate is
/// θ̇ = (ω_A − ω_B)·a_B.
///
/// **Limits**, one-sided rows like a contact (joint_parts.hpp, inequalityRow()):
/// lower C = θ − θ_min ≥ 0 with J = [0, a_Bᵀ, 0, −a_Bᵀ]; upper
/// C = θ_max − θ ≥ 0 with the opposite sign; K = a_B·(I_A⁻¹ + I_B⁻¹)·a_B;
/// each accumulated impulse ≥ 0. Beyond the limit the row is soft; before it,
/// speculative (bias C/h_s), so the hinge stops at the limit without bouncing.
///
/// **Motor**: Ċ = (ω_A − ω_B)·a_B − ω_target with the same K, not soft,
/// its accumulated impulse kept within ±τ_max·h_s (solveMotorRow()): it reaches
/// its speed when the torque allows, otherwise it accelerates at τ_max/I.
///
/// **Order** within one iteration (Box2D's): motor, limits, axis, point. The
/// point comes last because it matters most: a hinge that lets its bodies
/// drift apart is worse than one that turns a little too fast.
///
/// References: Catto, "Modeling and Solving Constraints" (GDC 2009), the
/// revolute joint; Box2D v3 `revolute_joint.c` (motor, limits, soft point);
/// Baraff, "Physically Based Modeling: Constrained Dynamics".
#include <algorithm>
#include <cmath>

#include "dynamics/joints/joint_parts.hpp"

namespace stepwise {

namespace {

/// Below this determinant, 1/(kg·m²)², the 2×2 alignment block is singular (axes at 90°): skip it this iteration.
constexpr Real kSingularAlignment = Real(1e-12);

/// The hinge's axes in the world at its bodies' orientations.
struct HingeAxes {
    Vec3 axisA{0, 0, 1};    ///< a_A.
    Vec3 axisB{0, 0, 1};    ///< a_B.
    Vec3 perpendicular[2];  ///< p_i.
    Vec3 turnRow[2];        ///< d_i = a_A × p_i.
};

HingeAxes axesAt(const Joint& joint, const JointOrientations& q) {
    HingeAxes axes;
    axes.axisA = q.a * joint.localAxisA;
    axes.axisB = q.b * joint.localAxisB;  // identity for the world: the axis is fixed
    for (int i = 0; i < 2; ++i) {
        axes.perpendicular[i] = q.b * joint.localPerpendicularB[i];
        axes.turnRow[i] = glm::cross(axes.axisA, axes.perpendicular[i]);
    }
    return axes;
}

/// One limit row: C ≥ 0 wanted, Ċ = sign·(ω_A − ω_B)·a_B, accumulated impulse ≥ 0; @p mass is its K⁻¹.
void solveLimitRow(SolverJoint& j, const Vec3& axis, Real mass, Real sign, Real C, Real& accumulated,
                   const JointSolverSettings& settings, bool useBias) {
    const Vec3 row = sign * axis;
    Real bias = 0;
    const RowSoftness soft = inequalityRow(C, settings, useBias, bias);
    const Real Cdot = glm::dot(relativeAngularVelocity(j), row);
    const Real impulse = -soft.massScale * mass * (Cdot + bias) - soft.impulseScale * accumulated;
    const Real total = std::max(accumulated + impulse, Real(0));
    applyAngularImpulse(j, (total - accumulated) * row);
    accumulated = total;
}

}  // namespace

Real hingeAngle(const Joint& joint, const Quat& orientationA, const Quat& orientationB) {
    Quat r = glm::conjugate(orientationB) * orientationA * glm::conjugate(joint.referenceRotation);
    if (r.w < 0) r = -r;  // q and −q are the same rotation; this one has the angle in [−π, π]
    return Real(2) * std::atan2(glm::dot(Vec3(r.x, r.y, r.z), joint.localAxisB), r.w);
}

void warmStartHingeJoint(SolverJoint& j, const JointFrame& f, const JointOrientations& q) {
    const Joint& joint = *j.joint;
    const HingeAxes axes = axesAt(joint, q);
    const Real aboutAxis = joint.motorImpulse + joint.lowerImpulse - joint.upperImpulse;
    applyAngularImpulse(j, joint.alignImpulse[0] * axes.turnRow[0] + joint.alignImpulse[1] * axes.turnRow[1] +
                               aboutAxis * axes.axisB);
    applyLinearImpulse(j, f, joint.linearImpulse);
}

void solveHingeJoint(SolverJoint& j, const JointFrame& f, const JointOrientations& q, const JointSolverSettings& settings,
                     bool useBias) {
    Joint& joint = *j.joint;
    const HingeAxes axes = axesAt(joint, q);
    const SymmetricMat3 W = relativeInverseInertia(j);  // I_A⁻¹ + I_B⁻¹, for every angular row

    if (joint.motor || joint.hasLowerLimit || joint.hasUpperLimit) {
        // The motor and both limits act about a_B: one K = a_B·W·a_B for the three.
        const Real axialMass = angularMass(W, axes.axisB);
        if (joint.motor) solveMotorRow(j, axes.axisB, axialMass, settings.substep);
        if (joint.hasLowerLimit || joint.hasUpperLimit) {
            const Real angle = hingeAngle(joint, q.a, q.b);
            if (joint.hasLowerLimit) {
                solveLimitRow(j, axes.axisB, axialMass, Real(1), angle - joint.lowerAngle, joint.lowerImpulse, settings,
                              useBias);
            }
            if (joint.hasUpperLimit) {
                solveLimitRow(j, axes.axisB, axialMass, Real(-1), joint.upperAngle - angle, joint.upperImpulse, settings,
                              useBias);
            }
        }
    }

    // The axis: two rows, one 2×2 block.
    const Vec3* d = axes.turnRow;
    const Vec3 Wd1 = W * d[1];
    const Real k00 = quadraticForm(W, d[0]);
    const Real k01 = glm::dot(d[0], Wd1);
    const Real k11 = glm::dot(d[1], Wd1);
    const Real det = k00 * k11 - k01 * k01;
    if (det > kSingularAlignment) {
        const RowSoftness soft = equalityRow(settings, useBias);
        const Vec3 w = relativeAngularVelocity(j);
        const Real rhs0 = glm::dot(w, d[0]) + soft.biasRate * glm::dot(axes.axisA, axes.perpendicular[0]);
        const Real rhs1 = glm::dot(w, d[1]) + soft.biasRate * glm::dot(axes.axisA, axes.perpendicular[1]);
        const Real x0 = (k11 * rhs0 - k01 * rhs1) / det;  // K⁻¹·rhs by Cramer's rule
        const Real x1 = (k00 * rhs1 - k01 * rhs0) / det;
        const Real impulse0 = -soft.massScale * x0 - soft.impulseScale * joint.alignImpulse[0];
        const Real impulse1 = -soft.massScale * x1 - soft.impulseScale * joint.alignImpulse[1];
        joint.alignImpulse[0] += impulse0;
        joint.alignImpulse[1] += impulse1;
        applyAngularImpulse(j, impulse0 * d[0] + impulse1 * d[1]);
    }

    solveBallJoint(j, f, settings, useBias);
}

}  // namespace stepwise
