/// @file expectations.hpp
/// @brief Self-checking scenes: what an `Expect` record states, and the monitor that checks it while a World runs.
///
/// An assignment is a scene plus the outcomes it must reach. Each `Expect`
/// record (docs/config-format.md, section "Expect") names one body, one
/// quantity of it, a target with a tolerance (or a one-sided bound), and
/// *when* it must hold:
///
///     Expect, Object=ball, Time=2, PositionY=0.5, Tolerance=0.01      at one moment
///     Expect, Object=ball, Apex=3, PositionY=0.6, Tolerance=0.02      at the ball's 3rd apex
///     Expect, Object=box, From=0, Until=10, AtRest=true               at every step of a window
///     Expect, Until=5, EnergyChange=0, Tolerance=0.05                 the whole scene's energy
///
/// The ExpectationMonitor observes the World *between* steps: it reads the
/// bodies' state after each World::step() and never changes it, so a scene
/// with expectations follows exactly the trajectory it follows without them.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace stepwise {

class World;

/// @brief The quantity an Expect record measures.
enum class ExpectQuantity : std::uint8_t {
    Position,         ///< The centre, m: one component (PositionY) or the distance from a target point (Position).
    Velocity,         ///< The centre's velocity, m/s: one component, or the distance from a target velocity.
    Speed,            ///< |v| of the centre, m/s.
    AngularSpeed,     ///< |ω|, rad/s.
    TiltDeg,          ///< Angle between the body's own y axis and the world's up, degrees (0 = upright).
    EnergyChange,     ///< (E − E₀)/|E₀|, E = kinetic + potential of the body (or of all bodies and soft bodies).
    AtRest,           ///< Fastest point speed |v| + |ω|·r_max (a soft body: fastest node) ≤ Tolerance (default kDefaultRestSpeed).
    Asleep,           ///< Is the body asleep (its island still for the World's TimeToSleep)? Needs Sleep=true.
    NotThroughPlane,  ///< Signed distance of the centre from a named plane stays ≥ −Tolerance (default 0).
    Volume,           ///< A soft body's enclosed volume V, m³ (SoftBody::volume).
    Pressure,         ///< A soft body's gas pressure P = nRT/V, Pa (SoftBody::pressure).
};

/// @brief How a measured value is compared with the target.
enum class ExpectCompare : std::uint8_t {
    Within,   ///< |measured − target| ≤ Tolerance.
    AtLeast,  ///< measured ≥ target.
    AtMost,   ///< measured ≤ target.
};

/// @brief When an expectation is checked.
enum class ExpectWhen : std::uint8_t {
    Throughout,  ///< At every observation with From ≤ t ≤ Until (the whole run by default).
    Instant,     ///< At the observation nearest to Time.
    Apex,        ///< At the body's Apex-th apex (highest point of a rise).
};

/// @brief A body at rest moves no point faster than this, m/s, unless the Expect record gives a Tolerance.
///
/// 1 cm/s: a resting box's corners jitter by far less (the position
/// correction keeps them within round-off), while a body that is sliding,
/// tipping or rolling visibly in a viewer moves faster.
inline constexpr Real kDefaultRestSpeed = Real(0.01);

/// @brief A rise smaller than this does not make an apex, m: resting on a floor is not bouncing.
inline constexpr Real kMinApexRise = Real(0.001);

/// @brief Object name of an expectation about every dynamic body (EnergyChange only).
inline constexpr const char* kAllBodies = "";

/// @brief One Expect record: a quantity of one body, a target, and when it must hold.
struct Expectation {
    int line = 0;                             ///< Line of the record in its file (0 when built in code).
    std::string object = kAllBodies;          ///< The DynamicObject or SoftBody it is about; "" = all of them (EnergyChange).
    ExpectQuantity quantity = ExpectQuantity::Position; ///< What is measured.
    int component = -1;                       ///< Position and Velocity: 0, 1, 2 for X, Y, Z; −1 for the whole vector.
    Real target = 0;                          ///< Target of a single number (or of the chosen component).
    Vec3 targetVector{0, 0, 0};               ///< Target point or velocity when the whole vector is given.
    bool flag = true;                         ///< AtRest / Asleep: the expected answer.
    std::string plane;                        ///< NotThroughPlane: the CollisionPlane's name.
    ExpectCompare compare = ExpectCompare::Within; ///< How measured and target are compared.
    Real tolerance = 0;                       ///< Within: allowed |measured − target|; AtRest: speed limit; NotThroughPlane: allowed depth.
    ExpectWhen when = ExpectWhen::Throughout; ///< When it is checked.
    Real time = 0;                            ///< Instant: the moment, s.
    Real from = 0;                            ///< Throughout: start of the window, s.
    Real until = -1;                          ///< Throughout: end of the window, s; < 0 means the end of the run.
    int apex = 0;                             ///< Apex: which apex, from 1.
};

/// @brief The verdict on one expectation after a run.
struct ExpectationResult {
    bool passed = false;   ///< Did the expectation hold?
    bool measured = false; ///< Was a value measured at all (false: not reached, or not measurable)?
    Real value = 0;        ///< The value that decided: the one sample, or the worst sample of a window.
    Real time = 0;         ///< Simulated time of that sample, s.
    std::string reason;    ///< Why it failed without a value ("not reached: …"), or "" .
};

/// @brief "ball: PositionY = 0.6 ± 0.02 m at apex 3": one expectation in words, for tables and messages.
std::string describe(const Expectation& expectation);

/// @brief The unit of the quantity an expectation measures ("m", "m/s", "deg", "" for a fraction).
const char* unitOf(const Expectation& expectation);

/// @brief "0.5861 m at t = 4.117 s", or the reason there is no value.
std::string describeMeasurement(const Expectation& expectation, const ExpectationResult& result);

/// @brief Checks a list of expectations against a running World, one observation after each step.
///
/// Usage: construct it on the World before the first step, call observe()
/// once then (t = 0) and once after every World::step(), and read results()
/// at the end. An observation costs a few dot products per expectation and
/// allocates nothing. Names are looked up once, ignoring case; an expectation
/// about a body or plane the World does not have fails with that reason
/// (this is how `stepwise grade --expect` reports a student scene that
/// renamed a body).
class ExpectationMonitor {
public:
    /// @brief Prepares to check @p expectations against @p world.
    ExpectationMonitor(const World& world, std::vector<Expectation> expectations);

    /// @brief Samples every expectation whose moment or window includes the World's current time.
    void observe(const World& world);

    /// @brief The verdicts, in the order of the expectations; an unmet moment or window fails as "not reached".
    std::vector<ExpectationResult> results(const World& world) const;

    /// @brief The expectations being checked.
    const std::vector<Expectation>& expectations() const { return expectations_; }

private:
    /// What the monitor remembers about one expectation between observations.
    struct Track {
        int body = -1;                 ///< Index into World::dynamics(); −1 = all bodies, or a soft body.
        int soft = -1;                 ///< Index into World::softBodies(), or −1.
        int plane = -1;                ///< Index into World::planes() (NotThroughPlane).
        std::string problem;           ///< Set when the expectation cannot be measured at all.
        Real startEnergy = 0;          ///< E₀, J (EnergyChange).
        bool sampled = false;          ///< Has a sample been taken?
        bool failed = false;           ///< Did any sample fail?
        Real worstValue = 0;           ///< The sample that decides the verdict.
        Real worstTime = 0;            ///< Its time, s.
        Real worstBadness = 0;         ///< How far the worst sample is from passing (larger is worse).
        int apexesSeen = 0;            ///< Apexes counted so far (Apex).
        bool havePrevious = false;     ///< Is there a previous observation (Apex)?
        Real previousUp = 0;           ///< Upward velocity at the previous observation, m/s.
        Real previousHeight = 0;       ///< Height (along up) at the previous observation, m.
        Real previousValue = 0;        ///< The quantity at the previous observation.
        Real previousTime = 0;         ///< Time of the previous observation, s.
        Real lowestSinceApex = 0;      ///< Lowest height since the last apex, m.
    };

    Real measure(const World& world, const Expectation& e, const Track& track) const;
    Real energyOfTrack(const World& world, const Track& track) const;
    void sample(const Expectation& e, Track& track, Real value, Real time) const;

    std::vector<Expectation> expectations_;
    std::vector<Track> tracks_;
    Vec3 up_{0, 1, 0};  ///< Unit vector against gravity (+y when there is no gravity).
    Real slack_ = 0;    ///< Half a time step, s: how close an observation must be to a moment.
};

}  // namespace stepwise
