/// @file joint_metrics.hpp
/// @brief How well joints hold: the gap between a joint's two anchors, a hinge's axis error, and energy.
///
/// A joint record (docs/config-format.md, "Joints") gives its anchor and axis
/// in world space at the start. The meter turns them into each body's own
/// frame from the bodies' start poses, a = Rᵀ·(p − x), as the engine does,
/// and after each step puts them back into the world with the state of that
/// step, p = x + R·a. Both engines are then judged by the same code:
///
/// - a BallJoint or HingeJoint holds the two anchors together: its error is
///   |p_A − p_B|, m;
/// - a DistanceJoint holds them `Length` apart: ||p_A − p_B| − L|; a Rope
///   at most L apart: max(0, |p_A − p_B| − L);
/// - a HingeJoint also keeps its axis, fixed in each body, common: its axis
///   error is the angle between R_A·k_A and R_B·k_B, rad.
/// An end on the world (no BodyB) is the fixed point itself, its axis the world's.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "scenario_metrics.hpp"

namespace stepwise::bench {

/// @brief The worst joint error of a run, over every joint of the scene.
class JointMeter {
public:
    /// @brief Sets up the scene's joints from its bodies' start poses.
    /// @throws std::invalid_argument when a joint names a body the scene does not have.
    explicit JointMeter(const Scene& scene);

    /// @brief Measures every joint in one step's states and keeps the worst.
    void observe(std::span<const BodyState> bodies);
    Real worstSeparation() const { return worstGap_; }       ///< Largest anchor error seen, m.
    Real worstAxisAngle() const { return worstAngle_; }      ///< Largest hinge-axis angle seen, rad.
    Real lastSeparation() const { return lastGap_; }         ///< Largest anchor error of the last step, m.
    /// @brief Largest sum of every joint's anchor error in one step, m: how much longer a chain has grown.
    Real worstStretch() const { return worstSum_; }
    std::size_t jointCount() const { return joints_.size(); }  ///< Joints measured (motors are not).

private:
    /// One joint in its bodies' frames.
    struct Held {
        JointKind kind;
        std::size_t a, b;   ///< Body indices; b == kWorld for the world.
        Vec3 anchorA, anchorB;  ///< In A's frame; in B's frame (or the world point).
        Vec3 axisA, axisB;      ///< Hinge axis in A's frame; in B's frame (or the world direction).
        Real length;            ///< Distance, Rope: the length, m.
    };
    static constexpr std::size_t kWorld = static_cast<std::size_t>(-1);
    std::vector<Held> joints_;
    Real worstGap_ = 0, worstAngle_ = 0, lastGap_ = 0, worstSum_ = 0;
};

/// @brief Total mechanical energy of the bodies, J: Σ ½·m·|v|² + ½·ω·L − m·g·x.
///
/// Masses come from @p scene (in its body order), g from its World record.
/// Without damping, friction or collisions this stays constant; a joint's
/// softness (its damping) or a solver's loss shows as the energy falling.
double mechanicalEnergy(std::span<const BodyState> bodies, const Scene& scene);

}  // namespace stepwise::bench
