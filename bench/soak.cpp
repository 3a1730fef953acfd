/// @file soak.cpp
/// @brief `stepwise-bench soak`: random valid scenes of every shape, joint and force, a million steps in all.
///
/// The stress suite (stress.cpp) pushes the engine where it is known to be
/// weak, one case at a time. A soak run does the opposite: many ordinary
/// scenes, each a random mix of what a user may write, for long enough that a
/// rare combination shows itself. Each scene is written as scene-file text and
/// loaded like a user's file, so the loader is soaked too. The criteria:
/// - no step ends in a non-finite state (a SimulationError);
/// - no body's centre leaves the closed box of planes the scene is built in
///   (a body outside went through a wall);
/// - an isolated elastic gas (no gravity, e = 1, μ = 0, spheres only) never
///   gains more than 1 % of its kinetic energy: nothing in a step may create
///   energy. (That it loses energy is the stress suite's elastic-gas case.)
/// A failing scene's text is written to a file, so that `stepwise run` can replay it.
#include "soak.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <stdexcept>

#include "config/scene_loader.hpp"
#include "core/errors.hpp"
#include "world/world.hpp"

namespace stepwise::bench {

const char* const kSoakUsage =
    "usage: stepwise-bench soak [--quick] [--steps N] [--steps-per-scene N] [--seed S] [--keep DIR]\n"
    "\n"
    "  Random valid scenes (spheres, boxes, kinematic bodies, springs, attractors, every joint, both\n"
    "  solvers and every integrator), each run --steps-per-scene steps (default 2000) until --steps\n"
    "  (default 1000000) have run; one scene in eight an isolated elastic gas. Fails on a non-finite\n"
    "  state, a body outside the scene's box, or a gas that gains more than 1 % of its energy; a\n"
    "  failing scene is written to DIR (default .) as soak-SEED.scene. --quick: 30 scenes of 300 steps.\n";

namespace {

constexpr double kHalfBox = 6;             ///< The closed box: planes at ±6 m (floor at 0, ceiling at 12), m.
constexpr double kEnergyGrowthLimit = 0.01; ///< An isolated elastic gas may not gain more than this fraction.
constexpr int kElasticEvery = 8;           ///< One scene in this many is an isolated elastic gas.
constexpr double kKinematicMargin = 2.5;   ///< A kinematic body starts this far from the walls, m.
constexpr double kKinematicClearance = 1.5;  ///< and keeps this far from them, m: more than a body's size.

/// A seeded source of the scene's random choices.
struct Dice {
    std::mt19937_64 random;
    double uniform(double lo, double hi) { return lo + (hi - lo) * double(random() >> 11) * 0x1.0p-53; }
    int whole(int lo, int hi) { return lo + int(random() % std::uint64_t(hi - lo + 1)); }
    bool chance(double p) { return uniform(0, 1) < p; }
    std::string vec(double lo, double hi) {
        char text[96];
        std::snprintf(text, sizeof text, "(%.4f, %.4f, %.4f)", uniform(lo, hi), uniform(lo, hi), uniform(lo, hi));
        return text;
    }
    std::string num(double lo, double hi) {
        char text[32];
        std::snprintf(text, sizeof text, "%.4f", uniform(lo, hi));
        return text;
    }
};

/// A point inside the box, away from its walls by @p margin.
std::string inside(Dice& d, double margin) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.4f, %.4f, %.4f)", d.uniform(-kHalfBox + margin, kHalfBox - margin),
                  d.uniform(margin, 2 * kHalfBox - margin), d.uniform(-kHalfBox + margin, kHalfBox - margin));
    return text;
}

std::string closedBox() {
    std::string text;
    const char* walls[][2] = {{"floor", "(0, 0, 0), Normal=(0, 1, 0)"},   {"ceiling", "(0, 12, 0), Normal=(0, -1, 0)"},
                              {"west", "(-6, 0, 0), Normal=(1, 0, 0)"},   {"east", "(6, 0, 0), Normal=(-1, 0, 0)"},
                              {"south", "(0, 0, -6), Normal=(0, 0, 1)"},  {"north", "(0, 0, 6), Normal=(0, 0, -1)"}};
    for (const auto& wall : walls) text += std::string("CollisionPlane, Name=") + wall[0] + ", Position=" + wall[1] + "\n";
    return text;
}

std::string elasticGas(Dice& d) {
    std::string text = "World, Gravity=(0, 0, 0), Sleep=false, TimeStep=1/" + std::to_string(d.chance(0.5) ? 60 : 120) + "\n";
    text += closedBox();
    const int count = d.whole(8, 40);
    for (int i = 0; i < count; ++i) {
        text += "DynamicObject, Name=g" + std::to_string(i) + ", Shape=Sphere, Radius=" + d.num(0.2, 0.5) +
                ", Mass=" + d.num(0.5, 3) + ", Position=" + inside(d, 0.6) + ", Velocity=" + d.vec(-4, 4) +
                ", Elasticity=1, Friction=0\n";
    }
    return text;
}

std::string mixedScene(Dice& d, std::uint64_t steps) {
    static const char* kIntegrators[] = {"Euler", "SymplecticEuler", "Verlet"};
    const bool impulse = d.chance(0.25);
    const int rate = d.chance(0.7) ? 60 : 120;
    // The scene says how long it runs, so the loader's warnings (a spring the integrator will blow
    // up over that many steps) are about the run the soak makes.
    std::string text = std::string("World, Solver=") + (impulse ? "Impulse" : "SequentialImpulse") +
                       ", Integrator=" + kIntegrators[d.whole(0, 2)] + ", TimeStep=1/" + std::to_string(rate) +
                       ", Duration=" + std::to_string(steps) + "/" + std::to_string(rate) +
                       ", Sleep=" + (d.chance(0.5) ? "true" : "false");
    if (!impulse) text += ", Substeps=" + std::to_string(d.whole(1, 16)) + ", FastPath=" + (d.chance(0.5) ? "true" : "false");
    text += "\n" + closedBox();
    const int bodies = d.whole(3, 30);
    for (int i = 0; i < bodies; ++i) {
        const bool sphere = d.chance(0.5);
        text += "DynamicObject, Name=b" + std::to_string(i) + ", Shape=" + (sphere ? "Sphere, Radius=" + d.num(0.15, 0.6)
                                                                                     : "Box, Scale=" + d.vec(0.3, 1.2)) +
                ", Mass=" + d.num(0.2, 5) + ", Position=" + inside(d, 1.0) + ", Velocity=" + d.vec(-3, 3) +
                ", Elasticity=" + d.num(0, 0.9) + ", Friction=" + d.num(0, 1) + "\n";
    }
    for (int i = 0, n = d.whole(0, 2); i < n; ++i) {
        // A kinematic body is never stopped: one that drifted out of the box would push whatever it
        // met through the walls. It keeps at least kKinematicClearance from them over the run.
        const double drift = (kKinematicMargin - kKinematicClearance) * rate / double(steps);
        text += "KinematicsObject, Name=k" + std::to_string(i) + ", Shape=" + (d.chance(0.5) ? "Box, Scale=(1, 0.3, 1)" : "Sphere, Radius=0.4") +
                ", Position=" + inside(d, kKinematicMargin) + ", Velocity=" + d.vec(-drift, drift) +
                ", AngularVelocity=" + d.vec(-1, 1) + "\n";
    }
    const auto body = [&] { return "b" + std::to_string(d.whole(0, bodies - 1)); };
    if (impulse) return text;  // joints and the forces below need the sequential impulse (joints) or are enough with one kind
    for (int i = 0, n = d.whole(0, 3); i < n; ++i) {
        text += "Spring, Name=s" + std::to_string(i) + ", BodyA=" + body() + ", AnchorB=" + inside(d, 1.0) +
                ", Stiffness=" + d.num(1, 200) + ", Damping=" + d.num(0, 5) + ", RestLength=" + d.num(0.5, 3) + "\n";
    }
    if (d.chance(0.2)) text += "Attractor, Name=sun, Position=" + inside(d, 2.0) + ", Mu=" + d.num(1, 30) + "\n";
    static const char* kJoints[] = {"DistanceJoint", "Rope", "BallJoint", "HingeJoint", "AngularMotor"};
    for (int i = 0, n = d.whole(0, 4); i < n && bodies >= 2; ++i) {
        const std::string kind = kJoints[d.whole(0, 4)];
        const std::string a = body();
        std::string b = body();
        text += kind + ", Name=j" + std::to_string(i) + ", BodyA=" + a;
        if (b != a && d.chance(0.6)) text += ", BodyB=" + b;
        if (kind == "DistanceJoint" || kind == "Rope") {
            text += ", AnchorA=" + inside(d, 1.0) + ", AnchorB=" + inside(d, 1.0);
        } else if (kind == "BallJoint") {
            text += ", Anchor=" + inside(d, 1.0);
        } else if (kind == "HingeJoint") {
            text += ", Anchor=" + inside(d, 1.0) + ", Axis=" + d.vec(0.2, 1);
            if (d.chance(0.5)) text += ", LowerAngle=" + d.num(-90, -10) + ", UpperAngle=" + d.num(10, 90);
            if (d.chance(0.5)) text += ", MotorSpeed=" + d.num(-3, 3) + ", MaxMotorTorque=" + d.num(0, 20);
        } else {
            text += ", Axis=" + d.vec(0.2, 1) + ", MotorSpeed=" + d.num(-3, 3) + ", MaxMotorTorque=" + d.num(0, 20);
        }
        if (kind != "AngularMotor" && d.chance(0.2)) text += ", MaxForce=" + d.num(50, 500);
        text += "\n";
    }
    return text;
}

Real kineticEnergy(const World& world) {
    Real energy = 0;
    for (const DynamicObject& b : world.dynamics()) {
        energy += Real(0.5) * b.mass * glm::dot(b.velocity, b.velocity) + Real(0.5) * glm::dot(b.angularVelocity, b.angularMomentum);
    }
    return energy;
}

/// What went wrong in one scene, or "" when nothing did; @p warned gets the loader's first warning.
std::string soakOne(const std::string& text, bool elastic, std::uint64_t steps, std::uint64_t& stepsRun,
                    std::string& warned) {
    Scene scene = parseScene(text, "soak");
    warned = scene.warnings.empty() ? "" : scene.warnings.front();
    World world(std::move(scene));
    const Real start = kineticEnergy(world);
    Real most = start;
    stepsRun = 0;
    try {
        for (; stepsRun < steps; ++stepsRun) {
            world.step();
            for (const DynamicObject& b : world.dynamics()) {
                for (const CollisionPlane& p : world.planes()) {
                    if (p.signedDistance(b.position) < 0) {
                        char what[160];
                        std::snprintf(what, sizeof what, "body '%s' left the box through '%s' at step %llu", b.name.c_str(),
                                      p.name.c_str(), static_cast<unsigned long long>(world.stepCount()));
                        return what;
                    }
                }
            }
            if (elastic) most = std::max(most, kineticEnergy(world));
        }
    } catch (const SimulationError& error) {
        return error.what();
    }
    if (elastic && most > start * (1 + kEnergyGrowthLimit)) {
        char what[160];
        std::snprintf(what, sizeof what, "the elastic gas gained %.2f %% of its kinetic energy", 100 * double(most / start - 1));
        return what;
    }
    return "";
}

}  // namespace

std::string soakSceneText(std::uint64_t seed, bool elastic, std::uint64_t steps) {
    Dice d{std::mt19937_64(seed)};
    return (elastic ? elasticGas(d) : mixedScene(d, steps));
}

int soakCommand(const std::vector<std::string>& args) {
    SoakOptions o;
    auto count = [&](const std::string& option, const std::string& text) {
        std::size_t used = 0;
        unsigned long long value = 0;
        try {
            value = std::stoull(text, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != text.size() || text.empty() || text[0] == '-' || value == 0) {
            throw std::invalid_argument(option + " expects a whole number > 0, found '" + text + "'");
        }
        return std::uint64_t(value);
    };
    try {
        for (std::size_t i = 0; i < args.size(); ++i) {
            const std::string& arg = args[i];
            if (arg == "--quick") {
                o.quick = true;
                continue;
            }
            if (i + 1 >= args.size()) throw std::invalid_argument("unknown option or missing value: '" + arg + "'");
            const std::string& value = args[++i];
            if (arg == "--steps") o.totalSteps = count(arg, value);
            else if (arg == "--steps-per-scene") o.stepsPerScene = count(arg, value);
            else if (arg == "--seed") o.seed = count(arg, value);
            else if (arg == "--keep") o.failureDir = value;
            else throw std::invalid_argument("unknown option '" + arg + "' for soak");
        }
    } catch (const std::invalid_argument& error) {
        std::fprintf(stderr, "stepwise-bench: error: %s\n\n%s", error.what(), kSoakUsage);
        return 2;
    }
    if (o.quick) {
        o.stepsPerScene = 300;
        o.totalSteps = 30 * o.stepsPerScene;
    }
    const auto start = std::chrono::steady_clock::now();
    std::uint64_t done = 0;
    std::uint64_t scenes = 0, gases = 0, failures = 0, foretold = 0;
    for (std::uint64_t k = 0; done < o.totalSteps; ++k) {
        const std::uint64_t seed = o.seed + k;
        const bool elastic = seed % kElasticEvery == 0;
        const std::string text = soakSceneText(seed, elastic, o.stepsPerScene);
        std::uint64_t ran = 0;
        std::string failure, warned;
        try {
            failure = soakOne(text, elastic, std::min(o.stepsPerScene, o.totalSteps - done), ran, warned);
        } catch (const std::exception& error) {  // the loader or the World refused a scene this program wrote
            failure = std::string("the scene was refused: ") + error.what();
        }
        done += std::max<std::uint64_t>(ran, 1);
        ++scenes;
        gases += elastic;
        if (!failure.empty() && !warned.empty()) {
            // The loader said so before the run (a spring this integrator blows up, masses the solver
            // cannot hold apart): the scene did what its warning foretold, not what no one expected.
            ++foretold;
            std::printf("WARNED  seed %llu: %s, as the loader foretold: %s\n", static_cast<unsigned long long>(seed),
                        failure.c_str(), warned.c_str());
        } else if (!failure.empty()) {
            ++failures;
            const std::string path = o.failureDir + "/soak-" + std::to_string(seed) + ".scene";
            std::ofstream(path) << text;
            std::printf("FAIL  seed %llu (%s): %s; the scene is in %s\n", static_cast<unsigned long long>(seed),
                        elastic ? "elastic gas" : "mixed", failure.c_str(), path.c_str());
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("soak: %llu scenes (%llu elastic gases), %llu steps, %.1f s: %llu failed, %llu more as their "
                "warnings foretold\n",
                static_cast<unsigned long long>(scenes), static_cast<unsigned long long>(gases),
                static_cast<unsigned long long>(done), seconds, static_cast<unsigned long long>(failures),
                static_cast<unsigned long long>(foretold));
    return failures == 0 ? 0 : 1;
}

}  // namespace stepwise::bench
