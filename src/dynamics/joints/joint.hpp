/// @file joint.hpp
/// @brief Joints of the sequential-impulse solver: the data, and the four calls the step makes.
///
/// A joint removes degrees of freedom: a function of the two bodies' poses,
/// the *position constraint* C(x) (a number or a vector), must stay zero (or,
/// for a rope or a limit, on one side of zero). The solver works with its
/// time derivative, which is linear in the velocities,
/// \f[ \dot C = J\,v, \qquad v = (v_A, \omega_A, v_B, \omega_B), \f]
/// J being the *Jacobian*, one row per removed degree of freedom. An impulse
/// along the constraint, P = Jᵀλ, changes the velocities by M⁻¹Jᵀλ and so
/// changes Ċ by K·λ with the *effective mass* (its inverse, really)
/// \f[ K = J\,M^{-1}J^T . \f]
/// One Gauss–Seidel iteration asks for the λ that makes Ċ what the position
/// error wants it to be, −b·C (a soft spring pulling C back, softness.hpp):
/// \f[ \lambda = -s_m K^{-1}(J v + b\,C) - s_i\,\lambda_\text{acc}, \f]
/// and the joint keeps λ_acc, the impulse accumulated over the iterations,
/// to clamp (a rope pulls, never pushes) and to warm-start the next substep.
/// Each type's file derives its C, J, K and bias:
///
/// | type | file | rows | C |
/// |------|------|------|---|
/// | DistanceJoint | distance_joint.cpp | 1 | \|p_B − p_A\| − L = 0 |
/// | Rope | rope.cpp | 1, one-sided | \|p_B − p_A\| − L ≤ 0 |
/// | BallJoint | ball_joint.cpp | 3 | p_B − p_A = 0 |
/// | HingeJoint | hinge_joint.cpp | 3 + 2 (+ limit, motor) | p_B − p_A = 0, a_A·p_i = 0 |
/// | AngularMotor | angular_motor.cpp | 1, clamped | (ω_A − ω_B)·a = target (a velocity constraint) |
///
/// **Conventions.** p_A = x_A + r_A is the anchor on A (r_A = q_A·(local
/// anchor)), p_B likewise; B may be the world (kWorldAnchor: m_B⁻¹ = 0,
/// I_B⁻¹ = 0, p_B a fixed point). A linear impulse P acts as +P on B at p_B
/// and −P on A at p_A; an angular impulse L as +L on A and −L on B
/// ("A relative to B"). Accumulated impulses are per substep (N·s), so the
/// joint's force is |λ_acc|/h_s.
///
/// **In the step** (World::stepWithSequentialImpulses()): prepareJoints()
/// once, then each substep warmStartJoints(), solveJoints(useBias = true)
/// before the contacts (Box2D's order: joints first, so the contacts, which
/// cannot pull, get the last word), the drift, solveJoints(useBias = false)
/// in the relax pass; after the substeps finishJoints() breaks the joints
/// that pulled harder than their MaxForce. C is measured at the poses the
/// contact solver records (SolverWorkspace::poses): the start of the
/// substep in the solve, so that the bias means "C after this substep"
/// exactly as in Box2D, and where the drift left the bodies in the relax.
///
/// **Motors are not soft**: they are velocity constraints with a bounded
/// impulse, |λ_acc| ≤ τ_max·h_s, solved in both passes.
///
/// **The World's switches** act on joints as on contacts: `Iterations` and
/// `RelaxIterations` set the passes, `WarmStarting=false` restarts every
/// impulse from 0 each step, `PositionCorrection=false` drops the bias (the
/// joints then hold velocities only, and drift apart). One-sided rows always
/// clamp the accumulated impulse (`AccumulateImpulses` switches the contacts only).
///
/// References: Witkin, "Constrained Dynamics" and Baraff, "Physically Based
/// Modeling: Constrained Dynamics" (SIGGRAPH course notes, 1997–2001) for C,
/// J and K; Catto, "Modeling and Solving Constraints" (GDC 2009) for the
/// sequential-impulse form of each joint; Catto, "Solver2D" and "Soft Step"
/// (box2d.org, 2024) and Box2D v3's joint files for soft joints in substeps.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "dynamics/contact_solver.hpp"
#include "dynamics/islands.hpp"
#include "dynamics/joints/joint_def.hpp"
#include "dynamics/softness.hpp"
#include "objects/body_set.hpp"
#include "core/world_settings.hpp"

namespace stepwise {

/// @brief One joint as the World keeps it: anchors and axes in the bodies' own frames, and its accumulated impulses.
struct Joint {
    std::string name;                    ///< From the scene.
    JointKind kind = JointKind::Ball;    ///< Constraint type.
    std::uint32_t bodyA = 0;             ///< Index of body A in World::dynamics().
    std::uint32_t bodyB = kWorldAnchor;  ///< Index of body B, or kWorldAnchor (fixed to the world).
    Vec3 localAnchorA{0, 0, 0};          ///< Anchor in A's body frame, m.
    Vec3 localAnchorB{0, 0, 0};          ///< Anchor in B's body frame, or the world point when B is the world, m.
    Vec3 localAxisA{0, 0, 1};            ///< Hinge axis in A's body frame (unit).
    Vec3 localAxisB{0, 0, 1};            ///< Hinge or motor axis in B's frame (the world's when B is the world).
    Vec3 localPerpendicularB[2] = {{1, 0, 0}, {0, 1, 0}}; ///< Two unit vectors ⟂ localAxisB (hinge alignment rows).
    Quat referenceRotation{1, 0, 0, 0};  ///< q_B⁻¹·q_A at the start: the hinge angle is 0 there.
    Real length = 0;                     ///< Distance: rod length; Rope: maximum length, m.
    Real lowerAngle = 0;                 ///< Hinge lower limit, rad (used when hasLowerLimit).
    Real upperAngle = 0;                 ///< Hinge upper limit, rad (used when hasUpperLimit).
    bool hasLowerLimit = false;          ///< Hinge: the lower limit is on.
    bool hasUpperLimit = false;          ///< Hinge: the upper limit is on.
    bool motor = false;                  ///< Hinge: the motor is on (AngularMotor: always).
    Real motorSpeed = 0;                 ///< Target angular velocity of A relative to B about the axis, rad/s.
    Real maxMotorTorque = kUnlimitedTorque; ///< Motor torque bound, N·m.
    Real maxForce = kUnbreakable;        ///< Breaking force, N.
    bool collideConnected = false;       ///< A and B still collide with each other (else their pair is dropped).

    // What the solver accumulates, kept from step to step for warm starting (N·s per substep).
    Vec3 linearImpulse{0, 0, 0};         ///< Ball, Hinge: the point rows' impulse on B (−it on A), N·s.
    Real axialImpulse = 0;               ///< Distance, Rope: impulse along the unit axis from p_A to p_B, on B, N·s.
    Real alignImpulse[2] = {0, 0};       ///< Hinge: the two axis-alignment rows, N·m·s.
    Real lowerImpulse = 0;               ///< Hinge lower limit (≥ 0), N·m·s.
    Real upperImpulse = 0;               ///< Hinge upper limit (≥ 0), N·m·s.
    Real motorImpulse = 0;               ///< Motor (|·| ≤ maxMotorTorque·h_s), N·m·s.

    bool broken = false;                 ///< Broke: no longer acts, not drawn, not an island link.
    std::uint64_t brokenAtStep = 0;      ///< Step (counted from 1) at whose end it broke.
    Real brokenAtTime = 0;               ///< Simulated time at which it broke, s.
    Real brokenForce = 0;                ///< The force that broke it, N.
};

/// @brief JointWorkspace::bodies has no place for this body (the world, B of a joint to it).
inline constexpr std::uint32_t kNoJointBody = 0xffffffffu;

/// @brief One joint prepared for a step: its bodies, their masses and inverse inertias (taken each substep).
struct SolverJoint {
    Joint* joint = nullptr;              ///< The joint (its accumulated impulses are updated in place).
    DynamicObject* a = nullptr;          ///< Body A.
    DynamicObject* b = nullptr;          ///< Body B, or nullptr for the world.
    std::uint32_t placeA = 0;            ///< A's place in JointWorkspace::bodies (Joint::bodyA is its index among the dynamic bodies).
    std::uint32_t placeB = kNoJointBody; ///< B's, or kNoJointBody for the world.
    Real inverseMassA = 0;               ///< 1/m_A, 1/kg.
    Real inverseMassB = 0;               ///< 1/m_B, or 0, 1/kg.
    Mat3 inverseInertiaA{0};             ///< A's world inverse inertia at the start of the substep (warmStartJoints()), 1/(kg·m²).
    Mat3 inverseInertiaB{0};             ///< B's, or zero.
};

/// @brief What the joint solver needs of the World's settings for one substep.
struct JointSolverSettings {
    Real substep = 0;                    ///< h_s, s.
    Softness softness;                   ///< From jointHertzInUse() and JointDampingRatio at h_s.
    bool positionCorrection = true;      ///< Feed the position error back (false: velocities only, joints drift).
};

/// @brief The joints prepared for this step, reused from step to step.
struct JointWorkspace {
    std::vector<SolverJoint> joints;     ///< One per acting joint (not broken, not asleep).
    std::vector<DynamicObject*> bodies;  ///< Each body an acting joint holds, once (a chain's link is in two joints).
    std::vector<Mat3> inverseInertias;   ///< Theirs, in the same order, at the start of the substep (warmStartJoints()).
    std::vector<std::uint32_t> placeOf;  ///< prepareJoints()' scratch: a dynamic body's place in `bodies`, or kNoJointBody.
    std::vector<std::uint64_t> jointedPairs; ///< Sorted keys of body pairs that must not collide (dropJointedPairs()), nor be swept (continuous.hpp).
};

/// @brief Where a joint's anchors are now, world frame, m.
struct JointAnchors {
    Vec3 onA{0, 0, 0};  ///< p_A.
    Vec3 onB{0, 0, 0};  ///< p_B.
};

/// @brief How far a joint is from satisfying its constraint (for summaries, tests and the viewer).
struct JointError {
    Real distance = 0;  ///< Positional error, m: Distance |d| − L; Rope max(0, |d| − L); Ball and Hinge |p_B − p_A|.
    Real angle = 0;     ///< Hinge: angle between the two bodies' axes plus any limit overrun, rad.
    Real speed = 0;     ///< AngularMotor and a hinge motor: relative angular speed about the axis, rad/s.
};

/// @brief The joint frequency the solver really uses, Hz: JointHertz capped at a quarter of the substep rate.
Real jointHertzInUse(const WorldSettings& settings);

/// @brief The joint solver's settings for substeps of @p substep seconds.
JointSolverSettings jointSolverSettings(const WorldSettings& settings, Real substep);

/// @brief Builds the World's joints from the scene's: resolves body names, turns world points and axes into body frames.
/// @throws std::invalid_argument naming the joint when a body is missing, the solver is not SequentialImpulse,
///         an axis is zero, a distance joint or rope has zero length, or a limit is reversed.
std::vector<Joint> makeJoints(std::span<const JointDef> defs, std::span<const DynamicObject> bodies, SolverKind solver);

/// @brief The island links of the joints that are not broken (B may be kWorldAnchor).
void jointLinks(std::span<const Joint> joints, std::vector<BodyLink>& links);

/// @brief Drops the candidate pairs of two bodies joined by an intact joint without collideConnected.
///
/// A joint usually holds its bodies where their shapes touch or overlap (a
/// chain's links, a door in its frame, an elbow): left to collide, the
/// contacts would push apart what the joint holds together, and the two
/// would fight for ever. Box2D makes the same choice by default
/// (`collideConnected = false`). Bodies joined only to the world are unaffected.
void dropJointedPairs(std::span<const Joint> joints, JointWorkspace& workspace, std::vector<CandidatePair>& pairs);

/// @brief Prepares the acting joints (not broken, not asleep) for this step; without @p warmStart their impulses restart at 0.
void prepareJoints(const BodySet& bodies, std::span<Joint> joints, bool warmStart, JointWorkspace& workspace);

/// @brief Applies every joint's accumulated impulses, at the start of a substep (lever arms at @p poses),
/// after taking each body's world inverse inertia at its orientation now (SolverJoint::inverseInertiaA).
void warmStartJoints(JointWorkspace& workspace, std::span<const Pose> poses);

/// @brief One Gauss–Seidel pass over the joints, measuring C at @p poses.
/// @param useBias true for the solve (soft position feedback), false for the relax pass (velocities only).
void solveJoints(JointWorkspace& workspace, std::span<const Pose> poses, const JointSolverSettings& settings,
                 bool useBias);

/// @brief One joint pass between two contact passes (World::stepWithSequentialImpulses()).
///
/// A joint pass works on the objects' velocities, a contact pass on the solver
/// bodies' copies (solver_body.hpp): the velocities are handed across around
/// the joints. With no joint acting there is nothing to hand across, and the
/// copies stay as they are.
void solveJointsBetweenContactPasses(JointWorkspace& joints, SolverWorkspace& contacts,
                                     const JointSolverSettings& settings, bool useBias);

/// @brief The same for one group of islands (World::runIslandGroups()): only the solver records
/// @p records, the group's, are handed across. Every acting joint must hold bodies of that group.
void solveJointsBetweenContactPasses(JointWorkspace& joints, SolverWorkspace& contacts,
                                     std::span<const std::uint32_t> records, const JointSolverSettings& settings,
                                     bool useBias);

/// @brief After the substeps: breaks every joint whose force |λ_acc|/h_s exceeds its MaxForce (recorded with
/// @p step and @p time), refreshes @p links when one broke, and makes each body's ω agree with its L again.
/// @return the number of joints that broke in this step.
std::size_t finishJoints(JointWorkspace& workspace, std::span<Joint> joints, Real substep, std::uint64_t step,
                         Real time, std::vector<BodyLink>& links);

/// @brief Where @p joint's anchors are now on @p bodies.
JointAnchors jointAnchors(const Joint& joint, std::span<const DynamicObject> bodies);

/// @brief How far @p joint is from its constraint on @p bodies now.
JointError measureJoint(const Joint& joint, std::span<const DynamicObject> bodies);

/// @brief The hinge angle of A relative to B about the axis, rad in (−π, π]; 0 at the start.
Real hingeAngle(const Joint& joint, const Quat& orientationA, const Quat& orientationB);

}  // namespace stepwise
