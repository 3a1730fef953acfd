/// @file reference_problems.cpp
/// @brief Each reference problem: what its scene must hold, its exact solution, and its error measures.
#include "reference_problems.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "core/errors.hpp"
#include "exact_solutions.hpp"
#include "world/world.hpp"

namespace stepwise::bench {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = 3.14159265358979323846;

/// The spring is judged after this many periods, the orbits after this many revolutions (issue #7).
constexpr double kPeriodsMeasured = 10;
/// The bounce is judged on this many apexes: by the fifth the ball is 0.1 m
/// high and the contact starts to count as resting.
constexpr int kApexesMeasured = 4;
/// Runge–Kutta step of the free box's reference, s: 1/10 000 of the finest
/// step swept; RK4's error ∝ dt⁴ puts its flip times within 10⁻⁹ s (checked
/// against dt·2 when the reference is built).
constexpr double kReferenceStep = 1e-5;
/// The pendulum runs this much longer than 11 exact periods, so a run whose
/// period comes out a little long still shows its 11 crossings.
constexpr double kPendulumRunMargin = 1.2;
/// Two positions or velocities closer than this (relative) count as equal when checking a scene's shape.
constexpr double kShapeTolerance = 1e-9;

DVec3 d(const Vec3& v) { return DVec3(v); }

void require(bool condition, const std::string& scene, const std::string& what) {
    if (!condition) throw std::runtime_error(scene + ": " + what);
}

/// Steps from t = 0 to the whole number of steps nearest @p duration.
std::uint64_t stepsFor(double duration, double h) { return static_cast<std::uint64_t>(std::llround(duration / h)); }

/// True when the run did not reach its planned end: its end-of-run errors are then NaN.
bool cutShort(const Measurement& m, std::uint64_t planned) { return m.steps < planned; }

/// A judge's observe() and finish() share what it has seen of one run: made anew for each run.
template <class Seen>
std::shared_ptr<Seen> freshRecord(Seen initial = {}) { return std::make_shared<Seen>(std::move(initial)); }

double wrapAngle(double a) { return std::remainder(a, 2 * kPi); }  // into [−π, π]

// ------------------------------------------------------------------ projectile

JudgeMaker prepareProjectile(const Scene& scene) {
    const std::string& file = scene.sourcePath;
    require(scene.dynamics.size() == 1 && scene.planes.empty() && scene.kinematics.empty() &&
                scene.springs.empty() && scene.attractors.empty(),
            file, "the projectile problem needs exactly one DynamicObject and nothing else (no floor to hit)");
    const DynamicObject& body = scene.dynamics[0];
    const PointState start{d(body.position), d(body.velocity)};
    const DVec3 g = d(scene.settings.gravity + body.constantAcceleration);
    const double duration = double(scene.settings.duration);
    return [=](double h) {
        const std::uint64_t steps = stepsFor(duration, h);
        const auto finish = [=](const BodyState& b, Measurement& m) {
            const PointState exact = projectileAt(start, g, double(m.steps) * h);
            const bool whole = !cutShort(m, steps);
            m.metrics = {{"position_error", "m", whole ? glm::length(d(b.position) - exact.position) : kNaN},
                         {"velocity_error", "m/s", whole ? glm::length(d(b.velocity) - exact.velocity) : kNaN}};
        };
        return Judge{steps, [](const BodyState&, double) {}, finish};
    };
}

// ------------------------------------------------------------------ spring

/// A body on a spring to a fixed point, moving along the spring's line: u¨ = −(k/m)·u with
/// u = l − L₀ the stretch. The exact solution is the cosine of oscillatorAt().
JudgeMaker prepareSpring(const Scene& scene) {
    const std::string& file = scene.sourcePath;
    require(scene.dynamics.size() == 1 && scene.springs.size() == 1 && scene.attractors.empty() &&
                scene.planes.empty() && scene.kinematics.empty(),
            file, "the spring problem needs one DynamicObject, one Spring and nothing else");
    const Spring& spring = scene.springs[0];
    const DynamicObject& body = scene.dynamics[0];
    require(spring.bodyB == kFixedInWorld && glm::length(spring.anchorA) == 0, file,
            "the spring must hold the body's centre (AnchorA=(0, 0, 0)) to a fixed point (no BodyB)");
    require(spring.damping == 0 && glm::length(scene.settings.gravity + body.constantAcceleration) == 0, file,
            "the spring problem has an exact cosine only without damping and without gravity");
    const DVec3 anchor = d(spring.anchorB);
    const DVec3 offset = d(body.position) - anchor;
    const DVec3 axis = glm::normalize(offset);
    require(glm::length(glm::cross(axis, d(body.velocity))) <= kShapeTolerance * (1 + glm::length(d(body.velocity))),
            file, "the body must start moving along the spring (or at rest), so it stays on the line");
    const double omega = std::sqrt(double(spring.stiffness) / double(body.mass));
    const double u0 = glm::length(offset) - double(spring.restLength);
    const double rate0 = glm::dot(axis, d(body.velocity));
    const double stiffness = double(spring.stiffness), mass = double(body.mass);
    const auto energy = [=](double u, double rate) { return 0.5 * mass * rate * rate + 0.5 * stiffness * u * u; };
    const double e0 = energy(u0, rate0);
    const double restLength = double(spring.restLength);
    const double duration = kPeriodsMeasured * 2 * kPi / omega;

    const auto stretch = [=](const BodyState& b) {
        const DVec3 r = d(b.position) - anchor;
        return std::pair{glm::length(r) - restLength, glm::dot(glm::normalize(r), d(b.velocity))};
    };

    return [=](double h) {
        const std::uint64_t steps = stepsFor(duration, h);
        const auto worstEnergy = freshRecord<double>();
        const auto observe = [=](const BodyState& b, double) {
            const auto [u, rate] = stretch(b);
            *worstEnergy = std::max(*worstEnergy, std::abs(energy(u, rate) - e0) / e0);
        };
        const auto finish = [=](const BodyState& b, Measurement& m) {
            if (cutShort(m, steps)) {
                m.metrics = {{"phase_error", "rad", kNaN}, {"amplitude_error", "1", kNaN}, {"energy_error_max", "1", kNaN}};
                return;
            }
            const auto [u, rate] = stretch(b);
            const auto [uExact, rateExact] = oscillatorAt(u0, rate0, omega, double(m.steps) * h);
            // u = A·cos θ, u̇ = −A·ω·sin θ: the phase θ and the amplitude A of the swing.
            const double phase = std::atan2(-rate / omega, u), phaseExact = std::atan2(-rateExact / omega, uExact);
            const double amplitude = std::hypot(u, rate / omega), amplitudeExact = std::hypot(uExact, rateExact / omega);
            m.metrics = {{"phase_error", "rad", std::abs(wrapAngle(phase - phaseExact))},
                         {"amplitude_error", "1", amplitude / amplitudeExact - 1},
                         {"energy_error_max", "1", *worstEnergy}};
        };
        return Judge{steps, observe, finish};
    };
}

// ------------------------------------------------------------------ Kepler orbits

/// One body about one Attractor, no gravity: Kepler's problem, solved exactly by KeplerOrbit.
JudgeMaker prepareKepler(const Scene& scene) {
    const std::string& file = scene.sourcePath;
    require(scene.dynamics.size() == 1 && scene.attractors.size() == 1 && scene.springs.empty() &&
                scene.planes.empty() && scene.kinematics.empty(),
            file, "an orbit problem needs one DynamicObject, one Attractor and nothing else");
    const DynamicObject& body = scene.dynamics[0];
    require(glm::length(scene.settings.gravity + body.constantAcceleration) == 0, file,
            "an orbit problem has no uniform gravity: set World, Gravity=(0, 0, 0)");
    const Attractor& centre = scene.attractors[0];
    const double mu = double(centre.mu);
    const DVec3 origin = d(centre.position);
    const PointState start{d(body.position) - origin, d(body.velocity)};
    const KeplerOrbit orbit(start, mu);  // throws if the orbit is not bound
    const double e0 = orbit.specificEnergy();
    const double duration = kPeriodsMeasured * orbit.period();
    const auto energy = [=](const BodyState& b) {
        return 0.5 * glm::dot(d(b.velocity), d(b.velocity)) - mu / glm::length(d(b.position) - origin);
    };

    return [=](double h) {
        const std::uint64_t steps = stepsFor(duration, h);
        const auto worstEnergy = freshRecord<double>();
        const auto observe = [=](const BodyState& b, double) {
            *worstEnergy = std::max(*worstEnergy, std::abs(energy(b) - e0) / std::abs(e0));
        };
        const auto finish = [=](const BodyState& b, Measurement& m) {
            if (cutShort(m, steps)) {
                m.metrics = {{"position_error", "m", kNaN}, {"energy_drift", "1", kNaN}, {"energy_error_max", "1", kNaN}};
                return;
            }
            const PointState exact = orbit.at(double(m.steps) * h);
            m.metrics = {{"position_error", "m", glm::length(d(b.position) - origin - exact.position)},
                         {"energy_drift", "1", (energy(b) - e0) / std::abs(e0)},
                         {"energy_error_max", "1", *worstEnergy}};
        };
        return Judge{steps, observe, finish};
    };
}

// ------------------------------------------------------------------ torque-free box

/// A box spun near its intermediate axis with no force and no torque: the
/// Dzhanibekov flip. Its flip times come from Euler's equations by RK4
/// (exact_solutions.hpp); |L| and the kinetic energy are conserved exactly.
JudgeMaker prepareFreeBox(const Scene& scene) {
    const std::string& file = scene.sourcePath;
    require(scene.dynamics.size() == 1 && scene.springs.empty() && scene.attractors.empty() && scene.planes.empty() &&
                scene.kinematics.empty(),
            file, "the free-box problem needs one DynamicObject and nothing else");
    require(glm::length(scene.settings.gravity + scene.dynamics[0].constantAcceleration) == 0, file,
            "the free-box problem has no gravity (it would not turn the box, but it would carry it away)");
    // The World fills in the inertia; build one to read it.
    const World initial(scene);
    const DynamicObject& body = initial.dynamics()[0];
    const DVec3 moments = d(body.inertiaBody);
    // The intermediate axis: neither the largest nor the smallest moment.
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int i, int j) { return moments[i] < moments[j]; });
    const int axis = order[1];
    const DVec3 omegaBody = glm::conjugate(glm::dquat(body.orientation)) * d(body.angularVelocity);
    const double duration = double(scene.settings.duration);
    const std::vector<double> reference = flipTimes(moments, omegaBody, axis, duration, kReferenceStep);
    const std::vector<double> coarser = flipTimes(moments, omegaBody, axis, duration, 2 * kReferenceStep);
    require(!reference.empty(), file, "the box never flips within Duration: spin it near its intermediate axis");
    require(coarser.size() == reference.size(), file, "the flip reference does not converge");
    const double l0 = glm::length(d(body.angularMomentum));
    const double e0 = 0.5 * glm::dot(d(body.angularVelocity), d(body.angularMomentum));

    // Which side of zero the body-frame L has along the intermediate axis: a flip is a change of sign.
    const auto side = [axis](const Quat& orientation, const Vec3& angularMomentum) {
        return (glm::conjugate(glm::dquat(orientation)) * d(angularMomentum))[axis];
    };
    const double startSide = side(body.orientation, body.angularMomentum);

    return [=](double h) {
        const std::uint64_t steps = stepsFor(duration, h);
        struct Seen {
            std::vector<double> flips;
            double previous = 0, worstMomentum = 0, worstEnergy = 0;
        };
        const auto seen = freshRecord<Seen>({{}, startSide, 0, 0});
        const auto observe = [=](const BodyState& b, double t) {
            const double now = side(b.orientation, b.angularMomentum);
            if ((now < 0) != (seen->previous < 0)) seen->flips.push_back(t - h + h * seen->previous / (seen->previous - now));
            seen->previous = now;
            seen->worstMomentum = std::max(seen->worstMomentum, std::abs(glm::length(d(b.angularMomentum)) - l0) / l0);
            const double e = 0.5 * glm::dot(d(b.angularVelocity), d(b.angularMomentum));
            seen->worstEnergy = std::max(seen->worstEnergy, std::abs(e - e0) / e0);
        };
        const auto finish = [=](const BodyState&, Measurement& m) {
            const std::vector<double>& flips = seen->flips;
            double worstFlip = 0;
            for (std::size_t i = 0; i < reference.size(); ++i) {
                worstFlip = i < flips.size() ? std::max(worstFlip, std::abs(flips[i] - reference[i])) : kNaN;
            }
            if (flips.size() != reference.size()) {
                m.note = std::to_string(flips.size()) + " flips instead of " + std::to_string(reference.size());
            }
            const bool whole = !cutShort(m, steps);
            m.metrics = {{"flip_time_error", "s", whole ? worstFlip : kNaN},
                         {"energy_error_max", "1", whole ? seen->worstEnergy : kNaN},
                         {"momentum_error_max", "1", whole ? seen->worstMomentum : kNaN}};
        };
        return Judge{steps, observe, finish};
    };
}

// ------------------------------------------------------------------ bouncing ball

/// A ball dropped on a plane: with restitution e (ball's times plane's) each
/// bounce keeps e² of the energy, so apex n is at e^(2n)·h₀ above the floor.
JudgeMaker prepareBounce(const Scene& scene) {
    const std::string& file = scene.sourcePath;
    require(scene.dynamics.size() == 1 && scene.planes.size() == 1 && scene.springs.empty() &&
                scene.attractors.empty() && scene.kinematics.empty() && scene.dynamics[0].shape == Shape::Sphere,
            file, "the bounce problem needs one sphere above one CollisionPlane and nothing else");
    const DynamicObject& ball = scene.dynamics[0];
    const CollisionPlane& floor = scene.planes[0];
    const DVec3 normal = glm::normalize(d(floor.normal));
    const DVec3 g = d(scene.settings.gravity + ball.constantAcceleration);
    const double gravity = -glm::dot(g, normal);
    require(gravity > 0 && glm::length(glm::cross(g, normal)) <= kShapeTolerance * glm::length(g), file,
            "gravity must point straight into the floor");
    require(glm::length(d(ball.velocity)) == 0, file, "the ball must start at rest");
    const double radius = double(ball.radius);
    const double dropHeight = glm::dot(d(ball.position) - d(floor.position), normal) - radius;
    const double restitution = double(ball.elasticity) * double(floor.elasticity);
    const double duration = double(scene.settings.duration);
    const DVec3 floorPoint = d(floor.position);

    return [=](double h) {
        const std::uint64_t steps = stepsFor(duration, h);
        struct Seen {
            std::vector<double> apexes;
            double previousRate = 0;
        };
        const auto seen = freshRecord<Seen>();
        const auto observe = [=](const BodyState& b, double) {
            if (static_cast<int>(seen->apexes.size()) >= kApexesMeasured) return;
            const double rate = glm::dot(d(b.velocity), normal);
            if (seen->previousRate > 0 && rate <= 0) {
                // Past the top: the ballistic apex of this state, height + v²/(2g), is where it turned.
                const double height = glm::dot(d(b.position) - floorPoint, normal) - radius;
                seen->apexes.push_back(height + rate * rate / (2 * gravity));
            }
            seen->previousRate = rate;
        };
        const auto finish = [=](const BodyState&, Measurement& m) {
            const std::vector<double>& apexes = seen->apexes;
            double worst = 0;
            double first = kNaN;
            double expected = dropHeight;
            for (int n = 0; n < kApexesMeasured; ++n) {
                expected *= restitution * restitution;
                const double error = n < static_cast<int>(apexes.size()) ? std::abs(apexes[n] / expected - 1) : kNaN;
                worst = std::max(worst, error);  // NaN propagates: a missing apex is no measurement
                if (n == 0) first = error;
                if (std::isnan(error)) worst = kNaN;
            }
            if (static_cast<int>(apexes.size()) < kApexesMeasured) {
                m.note = std::to_string(apexes.size()) + " apexes instead of " + std::to_string(kApexesMeasured);
            }
            m.metrics = {{"apex_error_max", "1", worst}, {"first_apex_error", "1", first}};
        };
        return Judge{steps, observe, finish};
    };
}

// ------------------------------------------------------------------ pendulum

/// A bob on a DistanceJoint to a fixed point, released from rest: a simple
/// pendulum (the rod holds the bob's centre, so nothing turns it). Its exact
/// period at amplitude θ₀ is 4·√(L/g)·K(sin(θ₀/2)) (pendulumPeriod()).
/// With @p bobTurnsWithRod, the judges of an engine whose rod pins the bob at
/// the pivot instead (preparePendulumTurningBob(), in the header).
JudgeMaker preparePendulum(const Scene& scene, bool bobTurnsWithRod) {
    const std::string& file = scene.sourcePath;
    require(scene.dynamics.size() == 1 && scene.joints.size() == 1 && scene.springs.empty() &&
                scene.attractors.empty() && scene.planes.empty() && scene.kinematics.empty(),
            file, "the pendulum problem needs one DynamicObject, one DistanceJoint and nothing else");
    require(scene.settings.solver == SolverKind::SequentialImpulse, file,
            "joints need Solver=SequentialImpulse");
    const DynamicObject& body = scene.dynamics[0];
    const JointDef& rod = scene.joints[0];
    require(rod.kind == JointKind::Distance && rod.bodyB.empty(), file,
            "the joint must be a DistanceJoint from the bob to a fixed point (no BodyB)");
    const DVec3 pivot = d(rod.anchorB);
    const DVec3 start = d(body.position);
    require(glm::length(d(rod.anchorA) - start) <= kShapeTolerance * (1 + glm::length(start)), file,
            "AnchorA must be the bob's centre, so the rod cannot turn it (a simple pendulum)");
    require(glm::length(d(body.velocity)) == 0 && glm::length(d(body.angularVelocity)) == 0, file,
            "the bob must start at rest");
    const double length = rod.length ? double(*rod.length) : glm::length(start - pivot);
    require(std::abs(glm::length(start - pivot) - length) <= kShapeTolerance * length, file,
            "the rod must start at its Length");
    const DVec3 g = d(scene.settings.gravity + body.constantAcceleration);
    const double gravity = glm::length(g);
    require(gravity > 0, file, "the pendulum needs gravity");
    const DVec3 down = g / gravity;
    const DVec3 arm = start - pivot;
    // θ₀ from the hanging direction; the swing stays in the plane of `down` and the arm.
    const double theta0 = std::acos(std::clamp(glm::dot(arm, down) / length, -1.0, 1.0));
    const DVec3 sideways = arm - glm::dot(arm, down) * down;
    require(theta0 > 0 && theta0 < kPi && glm::length(sideways) > 0, file,
            "release the bob away from the vertical (0 < theta0 < 180 degrees)");
    const DVec3 across = glm::normalize(sideways);
    const double mass = double(body.mass);
    // A bob that turns with its rod swings like a simple pendulum of length L + I/(m·L),
    // I its moment about the swing's axis (the header says why).
    double equivalentLength = length;
    if (bobTurnsWithRod) {
        const World built(scene);  // fills in the bob's principal moments
        const DynamicObject& bob = built.dynamics()[0];
        const DVec3 swingAxis = glm::conjugate(glm::dquat(bob.orientation)) * glm::normalize(glm::cross(down, across));
        const double moment = glm::dot(d(bob.inertiaBody), swingAxis * swingAxis);
        equivalentLength += moment / (mass * length);
    }
    const double period = pendulumPeriod(equivalentLength, gravity, theta0);
    // Energy above the lowest point, m·g·L·(1 − cos θ₀) at the start; ½·ω·L_bob is the bob's
    // turning (zero when the rod holds its centre).
    const auto energy = [=](const BodyState& b) {
        return 0.5 * mass * glm::dot(d(b.velocity), d(b.velocity)) +
               0.5 * glm::dot(d(b.angularVelocity), d(b.angularMomentum)) -
               mass * gravity * glm::dot(d(b.position) - pivot - length * down, down);
    };
    const double e0 = mass * gravity * length * (1 - std::cos(theta0));
    // The first upward crossing of the vertical comes ¾ of a period after the release; then one per period.
    const double duration = (kPeriodsMeasured + 1) * period * kPendulumRunMargin;

    return [=](double h) {
        const std::uint64_t steps = stepsFor(duration, h);
        struct Seen {
            std::vector<double> crossings;
            double previous = 0, worstLength = 0, worstEnergy = 0;
        };
        const auto seen = freshRecord<Seen>({{}, glm::dot(start - pivot, across), 0, 0});
        const auto observe = [=](const BodyState& b, double t) {
            const double now = glm::dot(d(b.position) - pivot, across);
            if (seen->previous < 0 && now >= 0 && seen->crossings.size() < std::size_t(kPeriodsMeasured) + 1) {
                // Linear interpolation inside the step for the moment the bob passes under the pivot.
                seen->crossings.push_back(t - h * now / (now - seen->previous));
            }
            seen->previous = now;
            seen->worstLength = std::max(seen->worstLength, std::abs(glm::length(d(b.position) - pivot) - length));
            seen->worstEnergy = std::max(seen->worstEnergy, std::abs(energy(b) - e0) / e0);
        };
        const auto finish = [=](const BodyState&, Measurement& m) {
            const std::vector<double>& crossings = seen->crossings;
            const bool whole = !cutShort(m, steps) && crossings.size() == std::size_t(kPeriodsMeasured) + 1;
            if (!cutShort(m, steps) && !whole) {
                m.note = std::to_string(crossings.size()) + " crossings of the vertical instead of " +
                         std::to_string(int(kPeriodsMeasured) + 1);
            }
            const double measured = whole ? (crossings.back() - crossings.front()) / kPeriodsMeasured : kNaN;
            m.metrics = {{"period_error", "1", whole ? std::abs(measured / period - 1) : kNaN},
                         {"length_error_max", "m", !cutShort(m, steps) ? seen->worstLength : kNaN},
                         {"energy_error_max", "1", !cutShort(m, steps) ? seen->worstEnergy : kNaN}};
        };
        return Judge{steps, observe, finish};
    };
}

// ------------------------------------------------------------------ the list

const std::vector<ReferenceProblem>& problems() {
    static const std::vector<ReferenceProblem> list = {
        {"projectile", "reference_projectile.scene", "A ball thrown under uniform gravity, position at t = 2 s",
         prepareProjectile, ""},
        {"spring", "reference_spring.scene", "A mass on a Spring (k = 100 N/m, m = 1 kg), phase after 10 periods",
         prepareSpring, ""},
        {"kepler-circular", "reference_kepler_circular.scene", "A circular orbit about an Attractor, after 10 orbits",
         prepareKepler, ""},
        {"kepler-eccentric", "reference_kepler_eccentric.scene", "An e = 0.5 orbit about an Attractor, after 10 orbits",
         prepareKepler, ""},
        {"free-box", "reference_free_box.scene", "A 1x2x3 box spun near its middle axis, Dzhanibekov flip times",
         prepareFreeBox, ""},
        {"bounce", "reference_bounce.scene", "A ball dropped 1 m with e = 0.8, apexes against e^(2n) * 1 m",
         prepareBounce, ""},
        {"pendulum", "reference_pendulum.scene",
         "A 1 m pendulum released at 60 degrees, period against 4 sqrt(L/g) K(sin(theta0/2))",
         [](const Scene& scene) { return preparePendulum(scene, false); }, ""},
    };
    return list;
}

}  // namespace

std::span<const ReferenceProblem> referenceProblems() { return problems(); }

JudgeMaker preparePendulumTurningBob(const Scene& scene) { return preparePendulum(scene, true); }

Measurement runInStepwise(const Scene& scene, const JudgeMaker& judgeAt, IntegratorKind integrator, double h) {
    StepwiseEngine engine{World(withStep(scene, integrator, h))};
    return runJudged(engine, judgeAt(h), h);
}

Scene withStep(const Scene& scene, IntegratorKind integrator, double h) {
    Scene copy = scene;
    copy.settings.integrator = integrator;
    copy.settings.timeStep = Real(h);
    return copy;
}

}  // namespace stepwise::bench
