/// @file continuous.hpp
/// @brief Continuous collision: a fast body is stopped where its path first touches something.
///
/// The stages find contacts at poses, once per step. A body that moves
/// farther in one step than its own half-thickness can start a step in front
/// of a thin wall and end it behind (or deep inside, past its middle, where
/// the push-out goes the wrong way): *tunnelling*. This stage runs after the
/// bodies have moved. For each *fast* body (one that moved more than
/// kFastMotionFraction of its inner radius) it sweeps the body's shape along
/// the straight line from its pose at the start of the step to its pose now,
/// finds the first time of impact t ∈ [0, 1] against every other body and
/// plane, and puts the body back at the pose of that time, touching. Its
/// velocity is kept, so the next narrowphase finds a touching contact moving
/// in, and the solver stops or bounces it as at any impact.
///
/// **The choice: conservative advancement on the exact shapes, translation only.**
/// A box is swept as a box, not as its bounding sphere: a box stopped where
/// its bounding sphere touches would still be a gap away from the wall, no
/// contact would be found, and the next step would stop it again at the same
/// place — held in the air at full speed. The time of impact comes from the
/// separation d(t) of the two shapes when A is moved by t·Δ (Δ its motion
/// this step) with its final orientation: each shape pair gives d and the
/// direction u in which d grows (separation()), so d′(t) = u·Δ. With both
/// shapes convex and A only translating, d(t) is convex in t, so its tangent
/// lies below it and the tangent's root t − d/d′ never passes the first
/// impact: advancing to it is *conservative advancement* (Mirtich 1996; Catto,
/// "Continuous Collision", GDC 2013), here with the tangent as the bound
/// instead of the maximum speed, so it converges like Newton's method. A slope
/// d′ ≥ 0 means the gap can only grow from there on (convexity): no impact.
/// Box against box uses the largest separation over the 15 separating axes
/// (Ericson, *Real-Time Collision Detection*, §4.4): a lower bound on the
/// distance that is 0 exactly when the boxes touch, and, a maximum of convex
/// functions, still convex. Rotation during the step is not swept (the body
/// turns as the integrator turned it, then slides along Δ), the usual
/// simplification for linear casts (Ericson §5.5); a spinning thin plate can
/// still clip a corner.
///
/// **Limits.** The time after the impact, (1 − t)·h, is lost: the body waits
/// at the wall until the next step (Bullet's motion clamping does the same;
/// Catto's talk discusses the trade). Other bodies are taken where they are
/// at the end of the step, so two fast bodies flying through each other can
/// still miss. A pair that already touches at the start is left to the
/// contact solver, which already holds it. Planes are not swept against: a
/// plane bounds a solid half-space, so a body carried however deep behind it
/// is pushed back out along its normal (lecture 3's bounce at h = 1/15 s
/// relies on it); with the sequential-impulse solver a body's contacts with
/// a plane are found as far ahead as it can move (below), so it stops at the
/// plane instead.
///
/// **With the sequential-impulse solver.** Its narrowphase finds a sphere's
/// contacts as far ahead as the sphere can move (GameObject::sweep:
/// *speculative* contacts). For a fast sphere that reach is long, and a
/// contact found across it acts as a plane through the closest point: a ball
/// passing a wall's edge 1 mm clear bounced off that plane (a *ghost
/// collision*, Catto, GDC 2013). With this stage on, a sphere's reach towards
/// another body is capped at kFastMotionFraction × its radius
/// (findContacts(), narrowphase.cpp) and this stage follows the rest of the
/// path with the exact shapes; towards a plane the full sweep is kept, for a
/// sphere and a box alike (a box's corners are tested against the plane
/// moved towards it by the sweep). Two boxes are tested as far apart as
/// each can move before it counts as fast (boxReachOf(), narrowphase.cpp):
/// each box's share of the reach is its sweep, capped at kFastMotionFraction
/// × its inner radius, so a box this stage leaves alone is stopped at the
/// other's face by its speculative contact, and a faster one is this stage's.
///
/// **Cost.** One pass over the bodies comparing |Δ| with their size. In a
/// step with a fast body, the bodies' boxes are sorted along one axis
/// (SweptBoxIndex, continuous_candidates.hpp: O(n) when the order holds from
/// the last step) and each fast body asks it for the boxes its swept box
/// overlaps, O(log n + k) instead of O(n); then at most
/// kMaxAdvancementIterations separation tests per overlapping candidate.
/// With nothing fast the stage costs the copy of the start positions and
/// that one pass (measured in docs/benchmarks.md).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "collision/continuous_candidates.hpp"
#include "collision/narrowphase.hpp"
#include "objects/body_set.hpp"

namespace stepwise {

/// A body is *fast* when it moved more than this fraction of its inner
/// radius (a sphere's radius, a box's smallest half extent) in one step.
/// Moved by less, it can sink into a surface it started in front of by less
/// than its inner radius: its centre stays in front, and the narrowphase's
/// push-out along the shortest way sends it back the way it came (lecture 3's
/// bounce relies on this, with the speed at touching rebuilt from the depth).
/// Moved by more, its centre can cross the surface and the push-out can go
/// out the far side. At 1, a ball bouncing at lesson-3 speeds (4.4 m/s, 0.1 m:
/// 0.07 m a step) is not fast, and its trajectory is untouched.
inline constexpr Real kFastMotionFraction = Real(1);

/// @brief A body's inner radius, m: the largest ball about its centre that it holds.
///
/// A sphere's or capsule's radius, a box's smallest half edge, a cylinder's
/// min(r, h/2) (h its full length), a hull's smallest face offset; for a
/// compound the smallest of its parts' (the thinnest part can tunnel first).
Real innerRadius(const DynamicObject& body);


/// Most separation tests per candidate pair. The tangent steps converge like
/// Newton's method (a head-on approach in one step, an oblique one in a few);
/// a grazing approach that has not converged is stopped at the last step,
/// which is still before the impact, and goes on from there next step.
inline constexpr int kMaxAdvancementIterations = 16;

/// The advancement stops when the shapes are this close, m: half the
/// narrowphase's touching tolerance, so the contact is surely found after
/// rounding (kTouchTolerance, src/collision/contact.hpp).
inline constexpr Real kTimeOfImpactTolerance = kTouchTolerance * Real(0.5);

/// @brief How far apart two shapes are, and which way that grows.
struct Separation {
    Real distance = 0;      ///< Signed gap, m (negative: overlap). A lower bound for box–box.
    Vec3 direction{0, 1, 0};///< Unit: moving A along it increases distance at rate 1 (for box–box, at that axis).
};

/// @brief The separation of shape A from shape B (A is a sphere, a box, a capsule, a cylinder
/// or a hull; B any shape). Capsules, cylinders and hulls are measured by GJK's distance
/// (EPA's depth when they overlap), and against a plane by their support point.
Separation separation(const Geometry& a, const Geometry& b);

/// @brief First time t ∈ [0, 1] at which shape A, moved from centre @p start to its
/// own centre (`a.centre`, the end of the step) with its final orientation, touches
/// B held still; nothing when it does not, or when they already touch at t = 0.
std::optional<Real> timeOfImpact(const Geometry& a, const Vec3& start, const Geometry& b);

/// @brief The key of an unordered pair of dynamic bodies @p a, @p b: the smaller index in the high
/// half. SweepWorkspace::unsweptPairs and JointWorkspace::jointedPairs hold such keys, sorted.
inline std::uint64_t bodyPairKey(std::uint32_t a, std::uint32_t b) {
    constexpr unsigned kHalf = 32;
    return (std::uint64_t(a < b ? a : b) << kHalf) | (a < b ? b : a);
}

/// @brief The continuous-collision stage's state: the dynamic bodies' positions at the start of
/// the step, and the reused arrays of its candidate search (no allocation once running).
struct SweepWorkspace {
    /// Sorted bodyPairKey()s of the pairs of dynamic bodies that are not swept against each
    /// other: those joined by a joint that does not let them collide (JointWorkspace::jointedPairs,
    /// set by the World before each call). Such a pair is not in the contacts either
    /// (dropJointedPairs()); were it swept, a fast link of a chain would be put back where its
    /// path met its neighbour's end, which its joint holds it against, and the joint would be torn
    /// open by the distance it lost (tests/test_joints.cpp, the swinging chain).
    std::span<const std::uint64_t> unsweptPairs;
    std::vector<Vec3> startPositions;      ///< One per dynamic body, m.
    std::vector<std::uint8_t> fast;        ///< 1 for each dynamic body that is fast this step.
    SweptBoxIndex index;                   ///< The bodies' boxes sorted along one axis (continuous_candidates.hpp).
    std::vector<std::uint32_t> candidates; ///< The current fast body's candidates (proxy numbers).
    std::size_t lastClamped = 0;           ///< Bodies put back at their time of impact in the last step.
};

/// @brief Records where every dynamic body is before it moves (call at the start of the step).
void recordStartPositions(const BodySet& bodies, SweepWorkspace& workspace);

/// @brief Moves every fast body back to its first time of impact along its path
/// this step (velocities unchanged).
///
/// A fast body's path is tested only against the bodies whose boxes overlap
/// its swept box, found with SweptBoxIndex (continuous_candidates.hpp) in
/// O(log n + k) instead of a loop over all n bodies.
/// @return the number of bodies moved back
std::size_t stopFastBodiesAtImpact(const BodySet& bodies, SweepWorkspace& workspace);

/// @brief The same stage with each fast body's swept box tested against every other
/// body, O(n) per fast body: the reference stopFastBodiesAtImpact() must match bit for bit (tests).
/// @return the number of bodies moved back
std::size_t stopFastBodiesAtImpactBruteForce(const BodySet& bodies, SweepWorkspace& workspace);

}  // namespace stepwise
