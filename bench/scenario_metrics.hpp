/// @file scenario_metrics.hpp
/// @brief What the scaling and side-by-side benchmarks measure, from body states alone.
///
/// Each engine (Stepwise's World, or Bullet in bench/bullet/) copies its
/// bodies' states into a std::vector<BodyState> after every step; the meters
/// below read only that, so both engines are judged by the same code. The
/// expected values come from physics (e^(2n) apexes, a = g·sinθ/(1+k)), never
/// from an engine's output.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "objects/game_object.hpp"
#include "overlap_depth.hpp"
#include "world/scene.hpp"
#include "world/world.hpp"

namespace stepwise::bench {

/// @brief One dynamic body's state after a step, in world space, SI units.
struct BodyState {
    Vec3 position{0, 0, 0};         ///< Centre of mass, m.
    Quat orientation{1, 0, 0, 0};   ///< Body to world rotation.
    Vec3 velocity{0, 0, 0};         ///< Linear velocity, m/s.
    Vec3 angularVelocity{0, 0, 0};  ///< ω, rad/s.
    Vec3 angularMomentum{0, 0, 0};  ///< L = I_world·ω about the centre of mass, kg·m²/s.
};

/// @brief Copies the states of @p world's dynamic bodies into @p out (resized, no allocation once grown).
void statesOf(const World& world, std::vector<BodyState>& out);

/// @brief Stepwise behind the same two calls as bench/bullet/BulletWorld, so one driver runs either engine.
struct StepwiseEngine {
    World world;
    void step() { world.step(); }
    void states(std::vector<BodyState>& out) const { statesOf(world, out); }
};

/// @brief @p scene with `Threads=1`. The timed benchmarks measure what one
/// core does, as Bullet's default world does; without this the narrowphase
/// would take the scene's default, a thread per core, and a second thread's
/// hand-offs would be in the CPU time. The threaded narrowphase has its own
/// benchmark (bench/threads/main.cpp).
Scene onOneThread(Scene scene);

/// @brief Worst overlap of equal spheres (with each other, planes and static boxes) and how many left the box.
///
/// The overlap of two spheres of radius r is 2r − |x_i − x_j| when positive;
/// of a sphere and a plane, r − n·(x − p); of a sphere and a static box,
/// r − d(x) with d the signed distance from the box (sphereBoxOverlap()). Pairs are found with a uniform
/// grid of cells 2r wide (a sphere can only touch spheres in the 27 cells
/// around its own), rebuilt on every observe(): O(n) per step.
class RainMeter {
public:
    /// @param planes the container's planes (every sphere starts on their open side)
    /// @param radius the spheres' common radius, m
    /// @param walls  the container's static boxes, if it is built of boxes (staticBoxesOf())
    RainMeter(std::vector<CollisionPlane> planes, Real radius, std::vector<OrientedBox> walls = {});

    /// @brief Measures the overlaps of one step's states and keeps the worst.
    void observe(std::span<const BodyState> bodies);
    /// @brief Spheres whose centre is behind a plane (escaped through it) or has left
    /// the level of static boxes (outsideLevel()), in @p bodies.
    std::size_t escaped(std::span<const BodyState> bodies) const;
    Real worstOverlap() const { return worstOverlap_; }  ///< Deepest overlap seen so far, m.

private:
    std::vector<CollisionPlane> planes_;
    std::vector<OrientedBox> walls_;
    Real radius_;
    Real worstOverlap_ = 0;
    std::vector<std::uint32_t> cellOf_;     ///< Each body's cell.
    std::vector<std::uint32_t> cellStart_;  ///< Counting sort: first entry of each cell in order_.
    std::vector<std::uint32_t> order_;      ///< Bodies sorted by cell.
    std::vector<std::uint32_t> fill_;       ///< Counting sort: next free entry of each cell.
};

/// @brief How far a stack's bodies move from where they started, and when it falls.
class StackMeter {
public:
    /// @brief Counts the stack as fallen when a body has moved farther than this, m:
    /// half the edge of the lessons' 1 m boxes, so a box has left its place.
    static constexpr Real kFallenDistance = Real(0.5);

    /// @param initial the bodies' states before the first step
    explicit StackMeter(std::span<const BodyState> initial);
    /// @brief Updates the worst displacement with the states at time @p time (s).
    void observe(std::span<const BodyState> bodies, Real time);
    Real worstDrift() const { return worstDrift_; }               ///< Largest displacement of any body, m.
    std::optional<Real> fallTime() const { return fallTime_; }    ///< First time past kFallenDistance, s.

private:
    std::vector<Vec3> start_;
    Real worstDrift_ = 0;
    std::optional<Real> fallTime_;
};

/// @brief Drift of a torque-free body's angular momentum (vector) and kinetic energy.
///
/// With no torque, L (world frame) and T = ½·ω·L are constant (Euler's
/// equations); the meter keeps the worst |L − L₀|/|L₀| and |T − T₀|/T₀.
class FreeBodyMeter {
public:
    /// @param initial the body's state before the first step
    explicit FreeBodyMeter(const BodyState& initial);
    /// @brief Updates the worst drifts with the body's state after a step.
    void observe(const BodyState& body);
    double worstMomentumDrift() const { return worstMomentum_; }  ///< max |L − L₀|/|L₀|.
    double worstEnergyDrift() const { return worstEnergy_; }      ///< max |T − T₀|/T₀.
    double finalMomentumDrift() const { return lastMomentum_; }   ///< |L − L₀|/|L₀| after the last step.
    double finalEnergyDrift() const { return lastEnergy_; }       ///< (T − T₀)/T₀ after the last step (negative: lost).

private:
    glm::dvec3 l0_;
    double e0_;
    double worstMomentum_ = 0;
    double worstEnergy_ = 0;
    double lastMomentum_ = 0;
    double lastEnergy_ = 0;
};

/// @brief Apexes of a ball bouncing on a floor, as heights of its lowest point.
///
/// A bounce is the vertical velocity turning from down to up; an apex is
/// the highest sample between a bounce and the velocity turning down again.
/// Sampling once per step misses the true apex by at most g·h²/8 (0.34 mm at
/// h = 1/60 s). Apexes under kSmallestApex are resting jitter, not bounces.
class BounceMeter {
public:
    /// @brief Apexes lower than this, m, are not counted.
    static constexpr Real kSmallestApex = Real(0.01);

    /// @param floorHeight height of the floor, m
    /// @param radius      the ball's radius, m
    BounceMeter(Real floorHeight, Real radius);
    /// @brief Follows the ball after one step.
    void observe(const BodyState& ball);
    const std::vector<Real>& apexes() const { return apexes_; }  ///< Lowest-point apex heights, m, in order.

private:
    Real floor_;
    Real radius_;
    Real previousVy_ = 0;
    bool rising_ = false;
    Real highest_ = 0;
    std::vector<Real> apexes_;
};

/// @brief The analytic acceleration along an incline of a body released at rest on it, m/s².
///
/// A sphere (I = k·m·r², k = 2/5 solid or 2/3 hollow) rolls without slipping
/// with a = g·sinθ/(1+k) when μ ≥ k/(1+k)·tanθ (Millington ch. 15), and
/// otherwise slides with a = g·(sinθ − μ·cosθ); a box slides with that when
/// μ < tanθ and stays put otherwise.
/// @param body  the body as loaded (its shape, friction and hollowness)
/// @param slope the incline
/// @param gravity the world's gravity, m/s²
Real inclineAcceleration(const DynamicObject& body, const CollisionPlane& slope, const Vec3& gravity);

/// @brief The unit vector down @p slope under @p gravity (gravity's part along the plane, normalised).
Vec3 downSlope(const CollisionPlane& slope, const Vec3& gravity);

/// @brief Median of @p values (reordered in place); 0 for none.
double median(std::vector<double>& values);

/// @brief Times steps one by one, in CPU time and in wall-clock time.
///
/// The machine these figures come from is shared (load average above 10 on
/// 2 cores while other people build): a step's wall-clock time then counts
/// the time other processes held the core. The process's CPU time
/// (CLOCK_PROCESS_CPUTIME_ID, every thread of the process) counts only the
/// work done, so it is the figure compared; the wall-clock median is shown too.
class StepTimer {
public:
    /// @param steps how many steps will be timed (reserved up front)
    explicit StepTimer(std::size_t steps);
    void start();  ///< Before a step.
    void stop();   ///< After it.
    double medianCpu();   ///< Median CPU time per step, s.
    double meanCpu() const;  ///< Mean CPU time per step, s.
    double medianWall();  ///< Median wall-clock time per step, s.

private:
    std::vector<double> cpu_, wall_;
    double cpuStart_ = 0, wallStart_ = 0;
};

}  // namespace stepwise::bench
