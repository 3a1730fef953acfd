/// @file expectations.cpp
/// @brief Measuring an Expect record's quantity between steps, and judging it.
///
/// Every quantity is read from the state a step left, the state that
/// `stepwise run --csv` writes:
///
/// | quantity          | measured value                                              | unit  |
/// |-------------------|-------------------------------------------------------------|-------|
/// | PositionX/Y/Z     | x, y or z of the centre                                     | m     |
/// | Position          | \f$|x - x_\text{target}|\f$, the distance from the target point | m  |
/// | VelocityX/Y/Z     | a component of the centre's velocity                        | m/s   |
/// | Velocity          | \f$|v - v_\text{target}|\f$                                 | m/s   |
/// | Speed             | \f$|v|\f$                                                   | m/s   |
/// | AngularSpeed      | \f$|\omega|\f$                                              | rad/s |
/// | TiltDeg           | \f$\arccos(R\,\hat y \cdot \hat u)\f$, û = −g/|g| (or +y)   | deg   |
/// | EnergyChange      | \f$(E - E_0)/|E_0|\f$, E = ½m|v|² + ½ω·L − m(g + a)·x        | —     |
/// | AtRest            | \f$|v| + |\omega|\,r_\text{max}\f$: no point of a rigid body moves faster | m/s |
/// | NotThroughPlane   | \f$(x - p)\cdot n\f$, the centre's signed distance from the plane | m |
/// | Volume            | V, the volume a soft body's surface encloses                | m³    |
/// | Pressure          | P = nRT/V of a soft body's gas                              | Pa    |
///
/// A SoftBody is measured at its centre of mass (SoftBody::position, its
/// velocity SoftBody::velocity); AtRest is its fastest node's speed, the
/// largest speed of any point of its surface; its energy is the nodes'
/// ½m|v|² and −m·g·x, the springs' ½k(l − L₀)² and the gas's −nRT·ln(V/1 m³)
/// (energyOf(const SoftBody&, const Vec3&)). It has no single rotation, so
/// no AngularSpeed or TiltDeg (the loader refuses them).
///
/// The fastest point of a rigid body moving with (v, ω) is at most
/// |v| + |ω|·r_max from the centre, r_max being the distance of its farthest
/// point (a sphere's radius, a box's half diagonal, shapeReach() for every
/// shape): v_P = v + ω × r, so
/// |v_P| ≤ |v| + |ω||r| (triangle inequality).
///
/// An apex is where the body stops rising: its velocity along û changes
/// from positive to zero or negative between two observations. The higher
/// of those two observations is the sample. On a ballistic arc, that
/// sample's height is at most g·h²/8 below the true apex (the apex lies
/// within half a step of an observation, where the body is at most
/// ½·g·(h/2)² lower): 0.5 mm at h = 1/60 s.
#include "world/expectations.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>

#include "collision/aabb.hpp"
#include "world/measurements.hpp"
#include "world/world.hpp"

namespace stepwise {

namespace {

/// Starting energies smaller than this, J, cannot be the denominator of a relative change.
constexpr Real kMinStartEnergy = Real(1e-12);
/// Degrees per radian.
constexpr Real kDegreesPerRadian = Real(180) / kPi;
/// Percent per unit fraction, for messages.
constexpr double kPercent = 100.0;

bool sameName(const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

/// Distance of the body's farthest point from its centre, m (src/collision/aabb.hpp).
Real farthestPointDistance(const DynamicObject& body) { return shapeReach(body); }

/// Did one sample pass, and how bad is it? Larger badness is further from
/// passing; a window's verdict is given by its worst sample.
struct Verdict {
    bool passed;
    Real badness;
};

Verdict judge(const Expectation& e, Real value) {
    switch (e.quantity) {
        case ExpectQuantity::AtRest:
            if (e.flag) return {value <= e.tolerance, value};
            return {value > e.tolerance, -value};
        case ExpectQuantity::NotThroughPlane:
            return {value >= -e.tolerance, -value};
        case ExpectQuantity::Asleep: {  // value 1 asleep, 0 awake
            const bool asleep = value > Real(0.5);
            return {asleep == e.flag, asleep == e.flag ? Real(0) : Real(1)};
        }
        default:
            break;
    }
    const bool wholeVector =
        (e.quantity == ExpectQuantity::Position || e.quantity == ExpectQuantity::Velocity) && e.component < 0;
    if (wholeVector) return {value <= e.tolerance, value};  // value is already the distance from the target
    switch (e.compare) {
        case ExpectCompare::AtLeast: return {value >= e.target, e.target - value};
        case ExpectCompare::AtMost: return {value <= e.target, value - e.target};
        case ExpectCompare::Within: break;
    }
    const Real off = std::abs(value - e.target);
    return {off <= e.tolerance, off};
}

/// Position, Velocity or Speed of a centre at @p position moving at @p velocity, the same for a rigid
/// body and a soft body's centre of mass; nothing for the other quantities.
std::optional<Real> measureCentre(const Vec3& position, const Vec3& velocity, const Expectation& e) {
    switch (e.quantity) {
        case ExpectQuantity::Position:
            return e.component >= 0 ? position[e.component] : glm::length(position - e.targetVector);
        case ExpectQuantity::Velocity:
            return e.component >= 0 ? velocity[e.component] : glm::length(velocity - e.targetVector);
        case ExpectQuantity::Speed: return glm::length(velocity);
        default: return std::nullopt;
    }
}

/// A soft body's quantity @p e, at its centre of mass (the table above); @p plane for NotThroughPlane.
Real measureSoft(const SoftBody& body, const Expectation& e, const CollisionPlane* plane) {
    if (const std::optional<Real> centre = measureCentre(body.position, body.velocity, e)) return *centre;
    switch (e.quantity) {
        case ExpectQuantity::AtRest: {  // the fastest point of the surface is a node
            Real fastest2 = 0;
            for (const Vec3& v : body.nodeVelocities) fastest2 = std::max(fastest2, glm::dot(v, v));
            return std::sqrt(fastest2);
        }
        case ExpectQuantity::NotThroughPlane: return plane != nullptr ? plane->signedDistance(body.position) : Real(0);
        case ExpectQuantity::Asleep: return body.asleep ? Real(1) : Real(0);
        case ExpectQuantity::Volume: return body.volume;
        case ExpectQuantity::Pressure: return body.pressure;
        default: return 0;  // AngularSpeed, TiltDeg: refused by the loader and by the monitor's constructor
    }
}

std::string number(Real value) {
    char text[48];
    std::snprintf(text, sizeof text, "%.6g", double(value));
    return text;
}

std::string vectorText(const Vec3& v) { return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")"; }

std::string quantityName(const Expectation& e) {
    static const char* const kAxes[] = {"X", "Y", "Z"};
    const std::string axis = e.component >= 0 && e.component < 3 ? kAxes[e.component] : "";
    switch (e.quantity) {
        case ExpectQuantity::Position: return "Position" + axis;
        case ExpectQuantity::Velocity: return "Velocity" + axis;
        case ExpectQuantity::Speed: return "Speed";
        case ExpectQuantity::AngularSpeed: return "AngularSpeed";
        case ExpectQuantity::TiltDeg: return "TiltDeg";
        case ExpectQuantity::EnergyChange: return "EnergyChange";
        case ExpectQuantity::AtRest: return "AtRest";
        case ExpectQuantity::Asleep: return "Asleep";
        case ExpectQuantity::NotThroughPlane: return "NotThroughPlane";
        case ExpectQuantity::Volume: return "Volume";
        case ExpectQuantity::Pressure: return "Pressure";
    }
    return "?";
}

std::string whenText(const Expectation& e) {
    switch (e.when) {
        case ExpectWhen::Instant: return "at t = " + number(e.time) + " s";
        case ExpectWhen::Apex: return "at apex " + std::to_string(e.apex);
        case ExpectWhen::Throughout: break;
    }
    if (e.until >= 0) return "from " + number(e.from) + " s to " + number(e.until) + " s";
    if (e.from > 0) return "from " + number(e.from) + " s to the end";
    return "throughout the run";
}

}  // namespace

const char* unitOf(const Expectation& e) {
    switch (e.quantity) {
        case ExpectQuantity::Position: return "m";
        case ExpectQuantity::Velocity: return "m/s";
        case ExpectQuantity::Speed: return "m/s";
        case ExpectQuantity::AngularSpeed: return "rad/s";
        case ExpectQuantity::TiltDeg: return "deg";
        case ExpectQuantity::EnergyChange: return "";
        case ExpectQuantity::AtRest: return "m/s";
        case ExpectQuantity::Asleep: return "";
        case ExpectQuantity::NotThroughPlane: return "m";
        case ExpectQuantity::Volume: return "m^3";
        case ExpectQuantity::Pressure: return "Pa";
    }
    return "";
}

std::string describe(const Expectation& e) {
    const std::string subject = e.object.empty() ? std::string("all bodies") : e.object;
    const std::string unit = *unitOf(e) ? std::string(" ") + unitOf(e) : std::string();
    std::string what;
    switch (e.quantity) {
        case ExpectQuantity::AtRest:
            what = e.flag ? "at rest (no point faster than " + number(e.tolerance) + " m/s)"
                          : "moving (some point faster than " + number(e.tolerance) + " m/s)";
            break;
        case ExpectQuantity::Asleep: what = e.flag ? "asleep" : "awake"; break;
        case ExpectQuantity::NotThroughPlane:
            what = "centre stays in front of plane " + e.plane;
            if (e.tolerance > 0) what += " (or at most " + number(e.tolerance) + " m behind)";
            break;
        default: {
            const bool wholeVector = e.component < 0 && (e.quantity == ExpectQuantity::Position ||
                                                         e.quantity == ExpectQuantity::Velocity);
            if (wholeVector) {
                what = quantityName(e) + " within " + number(e.tolerance) + unit + " of " + vectorText(e.targetVector);
            } else if (e.compare == ExpectCompare::AtLeast) {
                what = quantityName(e) + " >= " + number(e.target) + unit;
            } else if (e.compare == ExpectCompare::AtMost) {
                what = quantityName(e) + " <= " + number(e.target) + unit;
            } else {
                what = quantityName(e) + " = " + number(e.target) + " +- " + number(e.tolerance) + unit;
            }
        }
    }
    return subject + ": " + what + " " + whenText(e);
}

std::string describeMeasurement(const Expectation& e, const ExpectationResult& r) {
    if (!r.measured) return r.reason;
    std::string text = number(r.value);
    if (*unitOf(e)) text += std::string(" ") + unitOf(e);
    if (e.quantity == ExpectQuantity::EnergyChange) {
        char percent[48];
        std::snprintf(percent, sizeof percent, " (%+.3g %%)", kPercent * double(r.value));
        text += percent;
    }
    text += " at t = " + number(r.time) + " s";
    if (!r.reason.empty()) text += "; " + r.reason;
    return text;
}

ExpectationMonitor::ExpectationMonitor(const World& world, std::vector<Expectation> expectations)
    : expectations_(std::move(expectations)), tracks_(expectations_.size()) {
    const Real g = glm::length(world.settings().gravity);
    if (g > 0) up_ = -world.settings().gravity / g;
    slack_ = world.settings().timeStep / 2;

    for (std::size_t i = 0; i < expectations_.size(); ++i) {
        const Expectation& e = expectations_[i];
        Track& track = tracks_[i];
        if (!e.object.empty()) {
            const auto& bodies = world.dynamics();
            const auto& softBodies = world.softBodies();
            const auto found = std::find_if(bodies.begin(), bodies.end(),
                                            [&](const DynamicObject& b) { return sameName(b.name, e.object); });
            const auto foundSoft = std::find_if(softBodies.begin(), softBodies.end(),
                                                [&](const SoftBody& b) { return sameName(b.name, e.object); });
            const bool softOnly = e.quantity == ExpectQuantity::Volume || e.quantity == ExpectQuantity::Pressure;
            const bool rigidOnly = e.quantity == ExpectQuantity::AngularSpeed || e.quantity == ExpectQuantity::TiltDeg;
            if (found != bodies.end() && !softOnly) {
                track.body = static_cast<int>(found - bodies.begin());
            } else if (foundSoft != softBodies.end() && !rigidOnly) {
                track.soft = static_cast<int>(foundSoft - softBodies.begin());
            } else {
                track.problem = "not measurable: the scene has no " +
                                std::string(softOnly ? "SoftBody" : rigidOnly ? "DynamicObject" : "DynamicObject or SoftBody") +
                                " named '" + e.object + "'";
                continue;
            }
        } else if (e.quantity != ExpectQuantity::EnergyChange) {
            track.problem = "not measurable: " + quantityName(e) + " needs Object=<name>";
            continue;
        }
        if (e.quantity == ExpectQuantity::NotThroughPlane) {
            const auto& planes = world.planes();
            const auto found = std::find_if(planes.begin(), planes.end(),
                                            [&](const CollisionPlane& p) { return sameName(p.name, e.plane); });
            if (found == planes.end()) {
                track.problem = "not measurable: the scene has no CollisionPlane named '" + e.plane + "'";
                continue;
            }
            track.plane = static_cast<int>(found - planes.begin());
        }
        if (e.quantity == ExpectQuantity::Asleep && !world.settings().sleeping) {
            track.problem = "not measurable: the scene's World has Sleep=false, so no body ever sleeps";
            continue;
        }
        if (e.quantity == ExpectQuantity::EnergyChange) {
            track.startEnergy = energyOfTrack(world, track);
            if (std::abs(track.startEnergy) < kMinStartEnergy) {
                track.problem = "not measurable: the starting energy is 0 J, so it has no relative change "
                                "(move the body, or the potential's zero at the origin, away from it)";
            }
        }
    }
}

/// The energy an EnergyChange watches: of its body, its soft body, or the whole World, J.
Real ExpectationMonitor::energyOfTrack(const World& world, const Track& track) const {
    const Vec3& g = world.settings().gravity;
    if (track.soft >= 0) return energyOf(world.softBodies()[track.soft], g).total();
    return (track.body >= 0 ? energyOf(world.dynamics()[track.body], g) : energyOf(world)).total();
}

Real ExpectationMonitor::measure(const World& world, const Expectation& e, const Track& track) const {
    if (e.quantity == ExpectQuantity::EnergyChange) {
        return (energyOfTrack(world, track) - track.startEnergy) / std::abs(track.startEnergy);
    }
    if (track.soft >= 0) {
        return measureSoft(world.softBodies()[track.soft], e, track.plane >= 0 ? &world.planes()[track.plane] : nullptr);
    }
    const DynamicObject& body = world.dynamics()[track.body];
    if (const std::optional<Real> centre = measureCentre(body.position, body.velocity, e)) return *centre;
    switch (e.quantity) {
        case ExpectQuantity::AngularSpeed: return glm::length(body.angularVelocity);
        case ExpectQuantity::TiltDeg: {
            const Vec3 bodyUp = body.orientation * Vec3(0, 1, 0);
            return std::acos(std::clamp(glm::dot(bodyUp, up_), Real(-1), Real(1))) * kDegreesPerRadian;
        }
        case ExpectQuantity::AtRest:
            return glm::length(body.velocity) + glm::length(body.angularVelocity) * farthestPointDistance(body);
        case ExpectQuantity::NotThroughPlane:
            return world.planes()[track.plane].signedDistance(body.position);
        case ExpectQuantity::Asleep: return body.asleep ? Real(1) : Real(0);
        default: return 0;
    }
}

void ExpectationMonitor::sample(const Expectation& e, Track& track, Real value, Real time) const {
    const Verdict verdict = judge(e, value);
    // The first failing sample replaces a passing one; among samples of the
    // same verdict, the worse one wins.
    const bool replace = !track.sampled || (!verdict.passed && !track.failed) ||
                         (verdict.passed != track.failed && verdict.badness > track.worstBadness);
    if (replace) {
        track.worstValue = value;
        track.worstTime = time;
        track.worstBadness = verdict.badness;
    }
    track.sampled = true;
    track.failed = track.failed || !verdict.passed;
}

void ExpectationMonitor::observe(const World& world) {
    const Real t = world.time();
    for (std::size_t i = 0; i < expectations_.size(); ++i) {
        const Expectation& e = expectations_[i];
        Track& track = tracks_[i];
        if (!track.problem.empty()) continue;
        switch (e.when) {
            case ExpectWhen::Instant:
                if (!track.sampled && t >= e.time - slack_) sample(e, track, measure(world, e, track), t);
                break;
            case ExpectWhen::Throughout:
                if (t >= e.from - slack_ && (e.until < 0 || t <= e.until + slack_)) {
                    sample(e, track, measure(world, e, track), t);
                }
                break;
            case ExpectWhen::Apex: {
                if (track.apexesSeen >= e.apex) break;
                const bool soft = track.soft >= 0;
                const GameObject& body = soft ? static_cast<const GameObject&>(world.softBodies()[track.soft])
                                              : world.dynamics()[track.body];
                const Vec3& velocity = soft ? world.softBodies()[track.soft].velocity : world.dynamics()[track.body].velocity;
                const Real height = glm::dot(body.position, up_);
                const Real upward = glm::dot(velocity, up_);
                const Real value = measure(world, e, track);
                if (!track.havePrevious) {
                    track.lowestSinceApex = height;
                } else {
                    track.lowestSinceApex = std::min(track.lowestSinceApex, height);
                    const Real top = std::max(track.previousHeight, height);
                    const bool turned = track.previousUp > 0 && upward <= 0;
                    if (turned && top - track.lowestSinceApex >= kMinApexRise) {
                        if (++track.apexesSeen == e.apex) {
                            const bool previousHigher = track.previousHeight > height;
                            sample(e, track, previousHigher ? track.previousValue : value,
                                   previousHigher ? track.previousTime : t);
                        }
                        track.lowestSinceApex = height;
                    }
                }
                track.havePrevious = true;
                track.previousUp = upward;
                track.previousHeight = height;
                track.previousValue = value;
                track.previousTime = t;
                break;
            }
        }
    }
}

std::vector<ExpectationResult> ExpectationMonitor::results(const World& world) const {
    const Real end = world.time();
    std::vector<ExpectationResult> results(expectations_.size());
    for (std::size_t i = 0; i < expectations_.size(); ++i) {
        const Expectation& e = expectations_[i];
        const Track& track = tracks_[i];
        ExpectationResult& r = results[i];
        if (!track.problem.empty()) {
            r.reason = track.problem;
            continue;
        }
        r.measured = track.sampled;
        r.value = track.worstValue;
        r.time = track.worstTime;
        r.passed = track.sampled && !track.failed;
        const std::string ended = "the run ended at t = " + number(end) + " s";
        if (!track.sampled) {
            if (e.when == ExpectWhen::Apex) {
                r.reason = "not reached: only " + std::to_string(track.apexesSeen) + " apex(es) before " + ended;
            } else if (e.when == ExpectWhen::Instant) {
                r.reason = "not reached: " + ended + ", before t = " + number(e.time) + " s";
            } else {
                r.reason = "not reached: " + ended + ", before the window starts";
            }
        } else if (e.when == ExpectWhen::Throughout && e.until >= 0 && end < e.until - slack_ && r.passed) {
            // It held as far as the run went, but the window is not over: that is not a pass.
            r.passed = false;
            r.reason = "not reached: " + ended + ", before t = " + number(e.until) + " s";
        }
    }
    return results;
}

}  // namespace stepwise
