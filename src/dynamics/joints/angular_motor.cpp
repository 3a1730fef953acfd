/// @file angular_motor.cpp
/// @brief AngularMotor: drives the angular velocity of A relative to B about one axis, with a bounded torque.
///
/// A motor is a *velocity* constraint: it has no position C, only a target
/// for the relative angular speed about the unit axis a (fixed in B, or in
/// the world when B is the world):
/// \f[ \dot C = (\omega_A - \omega_B)\cdot a - \omega_\text{target} = J\,v - \omega_\text{target}, \qquad
///     J = \begin{bmatrix} 0 & a^T & 0 & -a^T \end{bmatrix}. \f]
/// The effective mass of that row is the moment of inertia the motor feels,
/// \f[ K = J M^{-1} J^T = a\cdot(I_A^{-1} + I_B^{-1})\,a , \f]
/// and each iteration applies λ = −K⁻¹·Ċ, an angular impulse λ·a on A and
/// −λ·a on B. The motor's strength is its torque, not a spring: the
/// accumulated impulse of a substep stays within ±τ_max·h_s. So a wheel of
/// inertia I driven from rest spins up at τ_max/I until it reaches the
/// target (after I·ω_target/τ_max seconds), then holds it (tests/test_joints.cpp).
///
/// Not soft, solved in both passes (as Box2D solves its motors); the
/// other rotations of A are left free. For a motor that also holds an axle,
/// use a HingeJoint with MotorSpeed (hinge_joint.cpp), which shares
/// solveMotorRow() with this file.
///
/// References: Catto, "Modeling and Solving Constraints" (GDC 2009), motors;
/// Box2D v3 `motor_joint.c` and the revolute joint's motor.
#include "dynamics/joints/joint_parts.hpp"

namespace stepwise {

void warmStartAngularMotor(SolverJoint& j, const JointOrientations& q) {
    applyAngularImpulse(j, j.joint->motorImpulse * (q.b * j.joint->localAxisB));
}

void solveAngularMotor(SolverJoint& j, const JointOrientations& q, const JointSolverSettings& settings) {
    const Vec3 axis = q.b * j.joint->localAxisB;
    solveMotorRow(j, axis, angularMass(relativeInverseInertia(j), axis), settings.substep);
}

}  // namespace stepwise
