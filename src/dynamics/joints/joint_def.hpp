/// @file joint_def.hpp
/// @brief A joint as a scene describes it: which bodies, and where, in world space at the start.
///
/// A scene file (docs/config-format.md, "Joints") or a test says where a joint
/// is in the *world*, because that is how one thinks of a pendulum: the bob
/// is here, the pivot there. When the World is built (makeJoints(),
/// joint.hpp) every point and axis is turned into each body's own frame,
/// which is what the solver needs: an anchor is a point of the body's
/// material and moves with it. A Scene keeps JointDefs; the World keeps Joints.
#pragma once

#include <limits>
#include <optional>
#include <string>

#include "core/types.hpp"

namespace stepwise {

/// @brief The five constraint types (one source file each in src/dynamics/joints/).
enum class JointKind : std::uint8_t {
    Distance,      ///< Rigid rod: the anchors stay `length` apart (distance_joint.cpp).
    Rope,          ///< The anchors are at most `length` apart; a slack rope does nothing (rope.cpp).
    Ball,          ///< The anchors coincide; any rotation is free (ball_joint.cpp).
    Hinge,         ///< A ball joint that also keeps one axis of each body aligned; limits and motor (hinge_joint.cpp).
    AngularMotor,  ///< Drives the relative angular velocity about one axis, torque-limited (angular_motor.cpp).
};

/// @brief Scene-file spelling of a joint type ("DistanceJoint", "Rope", "BallJoint", "HingeJoint", "AngularMotor").
const char* toString(JointKind kind);

/// @brief MaxForce of a joint that never breaks, N.
inline constexpr Real kUnbreakable = std::numeric_limits<Real>::infinity();
/// @brief MaxMotorTorque of a motor that always reaches its speed, N·m.
inline constexpr Real kUnlimitedTorque = std::numeric_limits<Real>::infinity();

/// @brief One joint between dynamic body A and dynamic body B (or the world), in world space at the start.
///
/// Which fields a type reads: Distance and Rope read anchorA, anchorB and
/// length; Ball reads anchorA (the one shared point); Hinge reads anchorA,
/// axis, the limits and the motor; AngularMotor reads axis and the motor
/// (its anchors are the bodies' centres).
/// "A relative to B": angles and angular speeds are those of A as seen
/// from B (from the world when B is the world), so a motor with positive
/// speed turns A counter-clockwise about the axis (right-hand rule).
struct JointDef {
    std::string name;                 ///< Unique name, used in output.
    JointKind kind = JointKind::Ball; ///< Constraint type.
    std::string bodyA;                ///< Name of a DynamicObject.
    std::string bodyB;                ///< Name of a DynamicObject, or "" for the world (a fixed point).
    Vec3 anchorA{0, 0, 0};            ///< World point attached to A at the start, m (Ball, Hinge: the joint's one point).
    Vec3 anchorB{0, 0, 0};            ///< World point attached to B (or fixed in the world) at the start, m (Distance, Rope).
    Vec3 axis{0, 0, 1};               ///< Hinge or motor axis, world direction at the start (normalised by makeJoints()).
    std::optional<Real> length;       ///< Distance: rod length; Rope: maximum length, m. Empty: the distance at the start.
    std::optional<Real> lowerAngle;   ///< Hinge: least angle of A relative to B, rad (the start is 0). Empty: no lower limit.
    std::optional<Real> upperAngle;   ///< Hinge: greatest angle, rad. Empty: no upper limit.
    bool motor = false;               ///< Hinge: has a motor (always true for AngularMotor).
    Real motorSpeed = 0;              ///< Target angular velocity of A relative to B about the axis, rad/s.
    Real maxMotorTorque = kUnlimitedTorque; ///< Largest torque the motor may apply, N·m.
    Real maxForce = kUnbreakable;     ///< The joint breaks when its force exceeds this, N.
    bool collideConnected = false;    ///< Do A and B still collide with each other? (Box2D's default: no.)
};

}  // namespace stepwise
