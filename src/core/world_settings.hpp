/// @file world_settings.hpp
/// @brief The simulation parameters a scene's `World` record sets.
#pragma once

#include <numbers>

#include "core/types.hpp"

namespace stepwise {

/// @brief Which time integrator advances the bodies (see src/integrators/).
enum class IntegratorKind : std::uint8_t {
    ExplicitEuler,    ///< x ← x + h·v, v ← v + h·a, both from the old state. First order; gains energy.
    SymplecticEuler,  ///< v ← v + h·a, then x ← x + h·v_new. First order; energy bounded.
    Verlet,           ///< Velocity Verlet. Second order; energy bounded; exact for constant a.
};

/// @brief Scene-file spelling of an integrator ("Euler", "SymplecticEuler", "Verlet").
const char* toString(IntegratorKind kind);

/// @brief Which collision response runs (`World, Solver=…`).
enum class SolverKind : std::uint8_t {
    /// The foundation's scheme: integrate, find the overlaps, resolve them
    /// with impulses, push the bodies apart (src/dynamics/impulse_resolver.cpp).
    Impulse,
    /// Catto's soft step: contacts and joints found at the start of the step
    /// and held through substeps by soft, warm-started sequential impulses
    /// (src/dynamics/contact_solver.hpp, src/dynamics/joints/).
    SequentialImpulse,
};

/// @brief Scene-file spelling of a solver ("Impulse", "SequentialImpulse").
const char* toString(SolverKind kind);
/// @brief Which broadphase finds the candidate pairs (src/collision/broadphase.hpp).
///
/// Every broadphase returns the same pairs in the same order, so the choice
/// changes how long a step takes, never the trajectory.
enum class BroadphaseKind : std::uint8_t {
    Auto,           ///< Chosen from the scene on the first step (chooseBroadphase(), which says why).
    BruteForce,     ///< Every pair of bodies, O(n²): the reference.
    SweepAndPrune,  ///< Sort the boxes along the axis of greatest spread and sweep.
    AabbTree,       ///< Dynamic tree of fattened boxes, inserted by the surface-area heuristic.
    Grid,           ///< Uniform grid, cells sized from the bodies.
    Octree,         ///< Loose octree: each body at the depth of its size, in the cell of its centre.
};

/// @brief Scene-file spelling of a broadphase ("Auto", "BruteForce", "SweepAndPrune", "AabbTree", "Grid", "Octree").
const char* toString(BroadphaseKind kind);

/// @brief Which algorithm finds the contacts of two convex shapes (`World, Narrowphase=…`).
///
/// Spheres against spheres and anything against a plane always take their
/// closed forms; the choice is for every other convex pair.
enum class NarrowphaseKind : std::uint8_t {
    Auto,    ///< SAT for box–box, closest points of segments for capsules and spheres, GJK + EPA for the rest.
    GjkEpa,  ///< GJK (distance, overlap) then EPA (depth and normal) for every such pair, boxes too.
    Mpr,     ///< Minkowski portal refinement (Snethen) for every such pair, boxes too.
};

/// @brief Scene-file spelling of a narrowphase ("Auto", "GjkEpa", "Mpr").
const char* toString(NarrowphaseKind kind);

/// @brief The order a sequential-impulse pass takes its contacts in (`World, ContactOrder=…`;
/// dynamics/contact_colours.hpp says why it matters).
enum class ContactOrder : std::uint8_t {
    Colours,  ///< Colour by colour (greedy graph colouring), each colour in the order found: solvable in lanes and on threads.
    Found,    ///< In the order the narrowphase found them.
};

/// @brief Scene-file spelling of a contact order ("Colours", "Found").
const char* toString(ContactOrder order);

/// @brief How a contact mixes the friction (or the restitution) of its two sides
/// (`World, FrictionCombine=…, ElasticityCombine=…`; src/objects/materials.hpp).
enum class CombineRule : std::uint8_t {
    Product,        ///< a·b: a side of 1 lets the other decide (the default; Bullet's rule).
    Min,            ///< min(a, b): the slipperier (or deader) side wins.
    Max,            ///< max(a, b): the grippier (or bouncier) side wins (Box2D's and Jolt's restitution).
    Average,        ///< (a + b)/2.
    GeometricMean,  ///< √(a·b) (Box2D's and Jolt's friction).
};

/// @brief Scene-file spelling of a combine rule ("Product", "Min", "Max", "Average", "GeometricMean").
const char* toString(CombineRule rule);

/// @brief Default time step, s: 60 steps per second, the usual display rate.
inline constexpr Real kDefaultTimeStep = Real(1) / Real(60);
/// @brief Default run length of `stepwise run`, s.
inline constexpr Real kDefaultDuration = Real(10);
/// @brief Default number of passes over all contacts in the impulse stage.
/// One pass settles a lone contact whose impulses do not couple (a sphere:
/// its normal passes through the centre); an off-centre contact, or a box on
/// a plane (four contacts on one body), needs several for its impulses to agree.
inline constexpr int kDefaultImpulseIterations = 10;

/// @brief Default substeps of the sequential-impulse solver. Collision runs
/// once per step, so sixteen substeps cost far less than sixteen steps; they
/// are what lets the contacts be stiff (see kDefaultContactHertz), a 20-box
/// tower stand and a 100:1 mass ratio hold (tests/test_solver.cpp; measured
/// worst box drift in 10 s: tower 3 mm, 100 kg on 1 kg 1.5 mm; with 12
/// substeps at 180 Hz 6 mm and 15 mm, with 8 at 120 Hz 15 mm and 6 mm).
inline constexpr int kDefaultSubsteps = 16;
/// @brief Default contact stiffness, Hz: overlaps close like a spring of this
/// frequency. Capped at a quarter of the substep rate when used (240 Hz is
/// that cap at 1/60 s and 16 substeps; stiffer than the cap, the tower sways).
/// A soft contact carries a load W by overlapping about W/(m_eff·ω²), ω = 2πf;
/// a tower of n boxes sinks by the sum over its contacts, so the stiffness
/// sets how far a tall stack settles (about 3 mm for 20 unit boxes at 240 Hz,
/// 3 cm at 60 Hz, where the soft base also lets it topple).
inline constexpr Real kDefaultContactHertz = 240;
/// @brief Default contact damping ratio: critically damped, so an overlap
/// closes without overshooting into a bounce.
inline constexpr Real kDefaultContactDampingRatio = 1;
/// @brief Default joint stiffness, Hz (capped at a quarter of the substep rate).
inline constexpr Real kDefaultJointHertz = 60;
/// @brief Default joint damping ratio.
inline constexpr Real kDefaultJointDampingRatio = 2;
/// @brief A body slower than this, m/s, counts as still for sleeping.
inline constexpr Real kDefaultSleepLinearSpeed = Real(0.05);
/// @brief A body turning slower than this, rad/s (≈ 2.9°/s), counts as still.
inline constexpr Real kDefaultSleepAngularSpeed = Real(0.05);
/// @brief A body whose velocity changed by less than this over a step, divided by the step,
/// m/s², is in equilibrium: the forces and constraint impulses on it balance. A body that is
/// slow but not balanced is at the turning point of an oscillation, and would move on if
/// left awake. A harmonic oscillator of angular frequency ω whose amplitude A passes this test
/// at its turning point has ω²·A below it: 0.01 m/s² keeps a 1 kg ball on a 100 N/m spring
/// (ω = 10 rad/s) awake until it is within 0.1 mm of its rest position.
inline constexpr Real kDefaultSleepLinearAcceleration = Real(0.01);
/// @brief The same for the angular velocity, rad/s².
inline constexpr Real kDefaultSleepAngularAcceleration = Real(0.01);
/// @brief An island whose bodies have all been still this long, s, falls asleep.
inline constexpr Real kDefaultTimeToSleep = Real(0.5);

/// @brief `Threads=0`: as many threads as the machine has hardware threads
/// (std::thread::hardware_concurrency). The results are bit-identical whatever
/// the number, so only the time a step takes depends on it.
inline constexpr int kAutoThreads = 0;

/// @brief Whether a World takes the fast path when nothing says otherwise (`World, FastPath=…`).
///
/// On in the release and ci builds. The debug and student builds are for
/// stepping through the engine in a debugger, so they are configured with
/// STEPWISE_FAST_PATH=OFF (CMakePresets.json), and there every step takes the
/// plain path a student reads; `FastPath=true` in a scene still turns it on.
/// Either way the numbers are the same, bit for bit (src/fast/fast_path.hpp).
#if defined(STEPWISE_FAST_PATH_BY_DEFAULT) && !STEPWISE_FAST_PATH_BY_DEFAULT
inline constexpr bool kFastPathByDefault = false;
#else
inline constexpr bool kFastPathByDefault = true;
#endif

/// @brief Global simulation settings: one per World.
struct WorldSettings {
    Vec3 gravity{0, -kStandardGravity, 0};             ///< Uniform gravitational acceleration, m/s².
    Real timeStep = kDefaultTimeStep;                  ///< Fixed step h, s; > 0.
    IntegratorKind integrator = IntegratorKind::SymplecticEuler; ///< Time integrator.
    Real duration = kDefaultDuration;                  ///< Default run length, s; > 0.
    int impulseIterations = kDefaultImpulseIterations; ///< Passes over the contacts per step, ≥ 1.
    bool warmStarting = true;                          ///< Start each persisting contact from last step's impulses.
    SolverKind solver = SolverKind::SequentialImpulse; ///< Collision response and joints.
    int substeps = kDefaultSubsteps;                   ///< Sequential impulse: substeps per step, ≥ 1.
    /// Sequential impulse: each island of a step gets the substeps it needs, at most `substeps`
    /// (src/dynamics/substep_rule.hpp); false: every island runs `substeps`.
    bool substepsPerIsland = false;
    int velocityIterations = 1;                        ///< Sequential impulse: solve passes per substep, ≥ 1.
    int relaxIterations = 1;                           ///< Sequential impulse: relax passes per substep, ≥ 0.
    /// Sequential impulse: the relax passes solve a ball contact's friction too (false: its normal row only;
    /// a box's contacts always get both). contact_solver.hpp, "Friction in the relax".
    bool relaxBallFriction = false;
    ContactOrder contactOrder = ContactOrder::Colours; ///< Sequential impulse: the order of a pass's contacts.
    bool accumulateImpulses = true;                    ///< Clamp accumulated impulses (true) or each increment.
    bool positionCorrection = true;                    ///< Soft push-out of overlaps and joint drift.
    Real contactHertz = kDefaultContactHertz;          ///< Contact softness frequency, Hz.
    Real contactDampingRatio = kDefaultContactDampingRatio; ///< Contact softness damping ratio.
    Real jointHertz = kDefaultJointHertz;              ///< Joint softness frequency, Hz.
    Real jointDampingRatio = kDefaultJointDampingRatio; ///< Joint softness damping ratio.
    bool sleeping = true;                              ///< Islands at rest fall asleep (sequential impulse only).
    Real sleepLinearSpeed = kDefaultSleepLinearSpeed;  ///< Still below this speed, m/s.
    Real sleepAngularSpeed = kDefaultSleepAngularSpeed; ///< Still below this angular speed, rad/s.
    Real sleepLinearAcceleration = kDefaultSleepLinearAcceleration;   ///< Still only if |Δv|/h is below this, m/s².
    Real sleepAngularAcceleration = kDefaultSleepAngularAcceleration; ///< Still only if |Δω|/h is below this, rad/s².
    Real timeToSleep = kDefaultTimeToSleep;            ///< Still for this long → asleep, s.
    BroadphaseKind broadphase = BroadphaseKind::Auto;  ///< Which broadphase finds the candidate pairs.
    NarrowphaseKind narrowphase = NarrowphaseKind::Auto;  ///< Which algorithm collides two convex shapes.
    bool stepPlan = true;                              ///< Skip the stages the scene cannot need (src/world/step_plan.hpp).
    bool fastPath = kFastPathByDefault;                ///< Let the step plan send the substeps to the fast path (src/fast/).
    bool continuousCollision = true;                   ///< Fast bodies stop where their path first touches (src/collision/continuous.hpp).
    int threads = kAutoThreads;                        ///< Threads for the narrowphase and the fast path's passes, ≥ 0 (kAutoThreads: one per hardware thread).
    CombineRule frictionCombine = CombineRule::Product;   ///< How a contact mixes its two sides' friction.
    CombineRule elasticityCombine = CombineRule::Product; ///< How a contact mixes its two sides' elasticity.
};

/// @brief The step the integrator takes, s: TimeStep, or TimeStep/Substeps under
/// SequentialImpulse (which integrates every substep). Stability limits such as
/// a spring's h·ω < 2 apply to this step.
inline Real integrationStep(const WorldSettings& settings) {
    return settings.solver == SolverKind::SequentialImpulse ? settings.timeStep / Real(settings.substeps)
                                                            : settings.timeStep;
}

/// @brief A soft constraint's frequency is capped at this fraction of the
/// solver's rate 1/h_s: stiffer than that, the implicit spring's response is
/// faster than a substep can resolve (Catto caps contacts at a quarter).
inline constexpr Real kMaxHertzPerSubstepRate = Real(0.25);

/// @brief The contact frequency the sequential-impulse solver really uses, Hz:
/// ContactHertz, capped at a quarter of the substep rate substeps/h.
inline Real contactHertzInUse(const WorldSettings& settings) {
    const Real cap = kMaxHertzPerSubstepRate * Real(settings.substeps) / settings.timeStep;
    return settings.contactHertz < cap ? settings.contactHertz : cap;
}

/// @brief How far a body resting on a rigid support sinks into it under its own weight
/// with the soft contacts of @p settings, m: g/ω² with ω = 2π·contactHertzInUse()
/// (a soft contact is a spring of that frequency; 4 µm at 240 Hz).
inline Real restingSag(const WorldSettings& settings) {
    const Real omega = Real(2) * std::numbers::pi_v<Real> * contactHertzInUse(settings);
    return glm::length(settings.gravity) / (omega * omega);
}

}  // namespace stepwise
