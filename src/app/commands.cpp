/// @file commands.cpp
/// @brief `stepwise run` and `stepwise check`: load, simulate, report.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <new>
#include <optional>
#include <string>

#include "app/cli.hpp"
#include "app/interrupt.hpp"
#include "config/scene_changes.hpp"
#include "config/scene_loader.hpp"
#include "core/errors.hpp"
#include "io/output_file.hpp"
#include "io/trajectory_csv.hpp"
#include "world/measurements.hpp"
#include "world/run_watch.hpp"
#include "world/spaces.hpp"
#include "world/world.hpp"

namespace stepwise::cli {

namespace {

/// Objects listed one per line in a summary; beyond this the table would scroll away.
constexpr std::size_t kMaxListedObjects = 20;
/// Warnings a run prints as they happen (RunWatch); past these, only their number at the end.
constexpr std::size_t kMaxRunWarnings = 10;
/// Runs shorter than this many steps finish before a progress line is worth drawing.
constexpr std::uint64_t kProgressMinSteps = 2000;
/// Seconds between progress redraws.
constexpr double kProgressInterval = 0.1;

using Clock = std::chrono::steady_clock;

std::string vec(const Vec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.4f, %.4f, %.4f)", double(v.x), double(v.y), double(v.z));
    return text;
}


void printSceneHeader(const std::string& path, const Scene& scene) {
    const WorldSettings& s = scene.settings;
    std::printf("Scene %s\n", path.c_str());
    std::printf("  integrator %s, time step %.6g s (%.4g steps/s), gravity %s m/s^2\n", toString(s.integrator),
                double(s.timeStep), 1.0 / double(s.timeStep), vec(s.gravity).c_str());
    if (s.solver == SolverKind::SequentialImpulse) {
        std::printf("  solver SequentialImpulse: %d substeps x (%d solve + %d relax passes), contacts %.3g Hz, "
                    "warm starting %s, sleep %s\n",
                    s.substeps, s.velocityIterations, s.relaxIterations, double(contactHertzInUse(s)),
                    s.warmStarting ? "on" : "off", s.sleeping ? "on" : "off");
    } else {
        std::printf("  solver Impulse: %d passes, warm starting %s\n", s.impulseIterations, s.warmStarting ? "on" : "off");
    }
    std::printf("  %zu dynamic, %zu kinematic, %zu plane(s)", scene.dynamics.size(), scene.kinematics.size(),
                scene.planes.size());
    if (!scene.joints.empty()) std::printf(", %zu joint(s) at %.3g Hz", scene.joints.size(), double(jointHertzInUse(s)));
    if (!scene.softBodies.empty()) std::printf(", %zu soft bod%s", scene.softBodies.size(), scene.softBodies.size() == 1 ? "y" : "ies");
    std::printf("\n");
    // Said only when the scene departs from the products, so the classic scenes print as before.
    const bool rules = s.frictionCombine != CombineRule::Product || s.elasticityCombine != CombineRule::Product;
    if (rules || !scene.materials.empty()) {
        std::printf("  %zu material(s), %zu pair(s); contacts combine friction by %s, elasticity by %s\n",
                    scene.materials.size(), scene.materialPairs.size(), toString(s.frictionCombine),
                    toString(s.elasticityCombine));
    }
}

class Progress {
public:
    Progress(std::uint64_t totalSteps) : enabled_(isatty(STDERR_FILENO) && totalSteps >= kProgressMinSteps),
                                         total_(totalSteps) {}
    void update(std::uint64_t step, double time) {
        if (!enabled_) return;
        const auto now = Clock::now();
        if (std::chrono::duration<double>(now - last_).count() < kProgressInterval) return;
        last_ = now;
        const int percent = static_cast<int>(100.0 * double(step) / double(total_));
        std::fprintf(stderr, "\r  simulating: t = %.3f s, step %llu of %llu (%d%%)  ", time,
                     static_cast<unsigned long long>(step), static_cast<unsigned long long>(total_), percent);
    }
    ~Progress() {
        if (enabled_) std::fprintf(stderr, "\r%70s\r", "");
    }

private:
    bool enabled_;
    std::uint64_t total_;
    Clock::time_point last_{};
};

/// The numbers that size a body's shape, as `stepwise check` prints them.
template <class Body>
std::string shapeSize(const Body& b) {
    char text[128];
    switch (b.shape) {
        case Shape::Sphere: std::snprintf(text, sizeof text, "radius %.6g m", double(b.radius)); break;
        case Shape::Box: return "size " + vec(b.scale) + " m";
        case Shape::Capsule:
        case Shape::Cylinder:
            std::snprintf(text, sizeof text, "radius %.6g m, height %.6g m", double(b.radius), double(b.height));
            break;
        case Shape::Hull:
            std::snprintf(text, sizeof text, "%zu vertices, %zu faces", b.hull ? b.hull->vertices.size() : std::size_t(0),
                          b.hull ? b.hull->faces.size() : std::size_t(0));
            break;
        case Shape::Compound:
            std::snprintf(text, sizeof text, "%zu parts", b.compound ? b.compound->parts.size() : std::size_t(0));
            break;
        case Shape::Mesh: return "a triangle mesh";  // only a kinematic body has one (the overload below)
    }
    return text;
}

std::string shapeSize(const KinematicsObject& b) {
    if (b.shape != Shape::Mesh) return shapeSize<KinematicsObject>(b);
    char text[64];
    std::snprintf(text, sizeof text, "%zu triangles", b.mesh ? b.mesh->triangles.size() : std::size_t(0));
    return text;
}

std::string quat(const Quat& q) {
    char text[112];
    std::snprintf(text, sizeof text, "(%.4f, %.4f, %.4f, %.4f)", double(q.w), double(q.x), double(q.y), double(q.z));
    return text;
}

/// Final position and velocity of each object, then its orientation and angular velocity.
void printFinalState(const World& world) {
    std::printf("\nFinal state at t = %.6g s\n", double(world.time()));
    const std::size_t total = world.dynamics().size() + world.kinematics().size();
    if (total == 0) {  // a scene of soft bodies alone: printSoftBodies() gives their state
        std::printf("  no rigid object%s\n", world.softBodies().empty() ? "" : "; the soft bodies follow");
        return;
    }
    auto forEachListed = [&](auto&& row) {
        std::size_t listed = 0;
        for (const DynamicObject& b : world.dynamics()) {
            if (listed++ >= kMaxListedObjects) return;
            row(b, b.shape, b.velocity, b.angularVelocity, "");
        }
        for (const KinematicsObject& b : world.kinematics()) {
            if (listed++ >= kMaxListedObjects) return;
            row(b, b.shape, b.velocity, b.angularVelocity, "  (kinematic)");
        }
    };
    std::printf("  %-20s %-8s %-32s %s\n", "name", "shape", "position (m)", "velocity (m/s)");
    forEachListed([](const GameObject& b, Shape shape, const Vec3& v, const Vec3&, const char* note) {
        std::printf("  %-20s %-8s %-32s %s%s\n", b.name.c_str(), toString(shape), vec(b.position).c_str(),
                    vec(v).c_str(), note);
    });
    std::printf("  %-20s %-40s %s\n", "name", "orientation (w, x, y, z)", "angular velocity (rad/s)");
    forEachListed([](const GameObject& b, Shape, const Vec3&, const Vec3& w, const char* note) {
        std::printf("  %-20s %-40s %s%s\n", b.name.c_str(), quat(b.orientation).c_str(), vec(w).c_str(), note);
    });
    if (total > kMaxListedObjects) std::printf("  ... and %zu more\n", total - kMaxListedObjects);
}

void printEnergyLine(const char* label, const Energy& e) {
    std::printf("  %-5s %-12.6g (translational %.6g, rotational %.6g, potential %.6g)\n", label, double(e.total()),
                double(e.translational), double(e.rotational), double(e.potential));
}

/// The conserved quantities at the start and end of a run. With no gravity and
/// no contacts all three are conserved; how well they are shows the integrator.
void printConservation(const Energy& before, const Energy& after, const Vec3& p0, const Vec3& p1, const Vec3& l0,
                       const Vec3& l1) {
    const double e0 = double(before.total());
    const double e1 = double(after.total());
    std::printf("\nEnergy (kinetic = translational + rotational, plus potential), J\n");
    printEnergyLine("start", before);
    printEnergyLine("end", after);
    std::printf("  change %+.6g", e1 - e0);
    if (std::abs(e0) > 0) std::printf(" (%+.3f %%)", 100.0 * (e1 - e0) / std::abs(e0));
    std::printf("\nLinear momentum, kg*m/s\n  start %s, end %s\n", vec(p0).c_str(), vec(p1).c_str());
    std::printf("Angular momentum about the origin, kg*m^2/s\n  start %s, end %s\n", vec(l0).c_str(),
                vec(l1).c_str());
}

/// "bob - world": the two bodies of a joint.
std::string jointBodies(const World& world, const Joint& joint) {
    const std::string& a = world.dynamics()[joint.bodyA].name;
    return a + " - " + (joint.bodyB == kWorldAnchor ? std::string("world") : world.dynamics()[joint.bodyB].name);
}

/// How far a joint is from its constraint, in the units a reader checks it in: mm, degrees, rad/s.
std::string jointErrorText(const World& world, const Joint& joint) {
    constexpr double kMillimetres = 1000.0;
    constexpr double kDegrees = 180.0 / 3.14159265358979323846;
    const JointError e = measureJoint(joint, world.dynamics());
    char text[96];
    switch (joint.kind) {
        case JointKind::Distance:
        case JointKind::Rope:
        case JointKind::Ball: std::snprintf(text, sizeof text, "%.3f mm", kMillimetres * double(e.distance)); break;
        case JointKind::Hinge:
            std::snprintf(text, sizeof text, "%.3f mm, %.3f deg", kMillimetres * double(e.distance),
                          kDegrees * double(e.angle));
            break;
        case JointKind::AngularMotor:
            std::snprintf(text, sizeof text, "%.4g of %.4g rad/s", double(e.speed), double(joint.motorSpeed));
            break;
    }
    return text;
}

/// Each joint: kind, bodies, its error at the end, and whether (and when) it broke.
void printJoints(const World& world) {
    if (world.joints().empty()) return;
    std::printf("\nJoints (error: how far each is from its constraint at the end)\n");
    std::printf("  %-16s %-14s %-28s %-24s %s\n", "name", "kind", "bodies", "error", "state");
    std::size_t listed = 0;
    for (const Joint& joint : world.joints()) {
        if (listed++ >= kMaxListedObjects) {
            std::printf("  ... and %zu more\n", world.joints().size() - kMaxListedObjects);
            break;
        }
        const std::string error = joint.broken ? "-" : jointErrorText(world, joint);
        std::printf("  %-16s %-14s %-28s %-24s ", joint.name.c_str(), toString(joint.kind),
                    jointBodies(world, joint).c_str(), error.c_str());
        if (joint.broken) {
            std::printf("broken at t = %.6g s (step %llu: %.4g N > MaxForce %.4g N)\n", double(joint.brokenAtTime),
                        static_cast<unsigned long long>(joint.brokenAtStep), double(joint.brokenForce),
                        double(joint.maxForce));
        } else {
            std::printf("intact\n");
        }
    }
}

/// Each region, what it does and whom it held in the last step; then what Kill regions removed.
void printRegions(const World& world) {
    if (world.regions().empty()) return;
    std::printf("\nRegions (the bodies each held in the last step)\n");
    const std::vector<Region>& regions = world.regions();
    for (std::size_t r = 0; r < regions.size(); ++r) {
        const Region& region = regions[r];
        std::printf("  %-16s %-12s ", region.name.c_str(), toString(region.effect));
        if (region.effect == RegionEffect::Kill) {
            std::size_t taken = 0;
            for (const RemovedBody& gone : world.removedBodies()) taken += gone.region == region.name ? 1 : 0;
            std::printf("removed %zu bod%s in all\n", taken, taken == 1 ? "y" : "ies");
            continue;
        }
        const std::span<const std::uint32_t> inside = world.regionMembers().of(r);
        std::string names;
        for (std::size_t k = 0; k < inside.size() && k < kMaxListedObjects; ++k) {
            names += (k == 0 ? "" : ", ") + world.dynamics()[inside[k]].name;
        }
        if (inside.size() > kMaxListedObjects) names += ", ... " + std::to_string(inside.size() - kMaxListedObjects) + " more";
        std::printf("%zu inside%s%s\n", inside.size(), inside.empty() ? "" : ": ", names.c_str());
    }
    for (const RemovedBody& gone : world.removedBodies()) {
        std::printf("  removed: %s by %s at t = %.6g s, at %s m\n", gone.name.c_str(), gone.region.c_str(),
                    double(gone.time), vec(gone.position).c_str());
    }
}

/// Which broadphase ran, and, when the scene left the choice to Auto, why; or why none ran.
void printBroadphase(const World& world) {
    // Auto chooses when the broadphase first runs, so a run in which it never ran has no choice to show.
    if (world.stageRecords()[static_cast<std::size_t>(Stage::Broadphase)].runs == 0) {
        const PlanDecision& planned = world.plan().stage(Stage::Broadphase);
        if (world.stepCount() == 0) {
            std::printf("Broadphase none ran (no step ran)\n");
        } else if (!planned.runs) {
            std::printf("Broadphase none ran (%s)\n", planned.reason);  // e.g. a single body: no pair to find
        } else {
            std::printf("Broadphase none ran (every step was idle: no body awake, no kinematic body moving)\n");
        }
        return;
    }
    if (world.settings().broadphase != BroadphaseKind::Auto) {
        std::printf("Broadphase %s (set by the scene)\n", toString(world.settings().broadphase));
        return;
    }
    const BroadphaseChoice& choice = world.broadphase().autoChoice();
    std::printf("Broadphase %s (Auto: %s)\n", toString(choice.kind), choice.reason.c_str());
}

/// Each soft body at the end: its centre of mass, volume and pressure (src/objects/soft_body.hpp).
void printSoftBodies(const World& world) {
    if (world.softBodies().empty()) return;
    std::printf("\nSoft bodies (centre of mass, its velocity, the volume and the pressure P = nRT/V at the end)\n");
    std::printf("  %-16s %6s %-28s %-28s %12s %12s\n", "name", "nodes", "centre (m)", "velocity (m/s)", "volume (m^3)",
                "pressure (Pa)");
    for (const SoftBody& body : world.softBodies()) {
        std::printf("  %-16s %6zu %-28s %-28s %12.6g %12.6g\n", body.name.c_str(), body.nodeCount(), vec(body.position).c_str(),
                    vec(body.velocity).c_str(), double(body.volume), double(body.pressure));
    }
}

void printStageTimes(const World& world, double wallSeconds) {
    std::printf("\nTime per stage (a substep stage runs several times a step; skipped stages show 0 runs)\n");
    std::printf("  %-20s %8s %12s %12s\n", "stage", "runs", "us/step", "total ms");
    const double steps = world.stepCount() ? double(world.stepCount()) : 1.0;
    for (std::size_t i = 0; i < kStageCount; ++i) {
        const StageRecord& r = world.stageRecords()[i];
        const double mean = 1e6 * r.totalSeconds / steps;
        std::printf("  %-20s %8llu %12.3f %12.3f\n", stageName(static_cast<Stage>(i)),
                    static_cast<unsigned long long>(r.runs), mean, 1e3 * r.totalSeconds);
    }
    std::printf("  wall time %.3f ms for %llu steps\n", 1e3 * wallSeconds,
                static_cast<unsigned long long>(world.stepCount()));
}

}  // namespace

std::unique_ptr<Scene> loadOrReport(const std::string& path) {
    try {
        auto scene = std::make_unique<Scene>(loadSceneFile(path));
        for (const std::string& warning : scene->warnings) std::fprintf(stderr, "%s\n", warning.c_str());
        return scene;
    } catch (const ConfigError& error) {
        for (const ConfigDiagnostic& d : error.diagnostics()) std::fprintf(stderr, "%s\n", d.message().c_str());
        std::fprintf(stderr, "stepwise: %zu error(s) in %s; nothing was loaded.\n", error.diagnostics().size(),
                     path.c_str());
        return nullptr;
    }
}

std::string outOfMemoryMessage(const World& world) {
    // What grows without bound is the contacts: n bodies that all overlap (dropped on one spot)
    // make a candidate pair and a contact for every pair, n(n - 1)/2 of them, each with its
    // manifold and solver record.
    const double n = double(world.dynamics().size());
    char text[320];
    std::snprintf(text, sizeof text,
                  "out of memory in step %llu (t = %.6g s) of a scene of %.0f dynamic bodies, with %zu contacts "
                  "found. Bodies that overlap all at once make a contact for every pair, n(n-1)/2 = %.3g "
                  "here: spread them out",
                  static_cast<unsigned long long>(world.stepCount() + 1), double(world.time()), n,
                  world.contacts().size(), n * (n - 1) / 2);
    return text;
}

/// Prints @p warnings of a run to stderr as they come, up to kMaxRunWarnings in all.
void reportWarnings(const RunWatch& watch, const std::vector<std::string>& warnings) {
    std::size_t index = watch.count() - warnings.size();
    for (const std::string& warning : warnings) {
        if (index < kMaxRunWarnings) std::fprintf(stderr, "stepwise: warning: %s\n", warning.c_str());
        ++index;
    }
}

/// Opens an output file (--csv, --csv-nodes) when one is asked for; false (and the reason on stderr)
/// when it cannot be.
static bool openOutput(const std::optional<std::string>& path, std::optional<OutputFile>& file) {
    if (!path) return true;
    file.emplace(*path);
    if (file->ok()) return true;
    std::fprintf(stderr, "stepwise: error: %s\n", file->error().c_str());
    return false;
}


/// `stepwise run` of a scene with spaces (src/world/spaces.hpp): every space on one clock, one CSV
/// with a space column, and a summary of each space in turn.
int runSpaces(const RunOptions& options, Scene scene) {
    if (options.threads) {
        scene.settings.threads = *options.threads;
        for (SpaceDef& space : scene.spaces) space.settings.threads = *options.threads;
    }
    const double duration = options.duration.value_or(double(scene.settings.duration));
    Spaces spaces(std::move(scene));
    const Real tick = spaces.finestTick();
    std::printf("\nSpaces (%zu, on one clock ticking every %.6g s)\n", spaces.all().size(), double(tick));
    for (const Space& space : spaces.all()) {
        const WorldSettings& s = space.world.settings();
        std::printf("  %-12s %s, %s, h %.6g s, TimeScale %.6g%s: %zu dynamic, %zu kinematic, %zu plane(s)",
                    space.name.c_str(), toString(s.integrator), toString(s.solver), double(s.timeStep),
                    double(space.timeScale), space.paused ? ", paused" : "", space.world.dynamics().size(),
                    space.world.kinematics().size(), space.world.planes().size());
        const std::size_t soft = space.world.softBodies().size();
        if (soft != 0) std::printf(", %zu soft bod%s", soft, soft == 1 ? "y" : "ies");
        std::printf("\n");
    }
    const bool anySoft = std::any_of(spaces.all().begin(), spaces.all().end(),
                                     [](const Space& space) { return !space.world.softBodies().empty(); });
    if (options.explain) {
        for (const Space& space : spaces.all()) {
            std::printf("\nSpace %s: %s", space.name.c_str(), describeStepPlan(space.world.plan()).c_str());
        }
        if (options.steps == std::uint64_t(0)) return kExitOk;
    }
    std::vector<ExpectationMonitor> monitors;
    std::vector<std::vector<Expectation>> expectations;
    for (const Space& space : spaces.all()) expectations.push_back(space.expectations);
    for (std::size_t k = 0; k < spaces.all().size(); ++k) {
        monitors.emplace_back(spaces.all()[k].world, expectations[k]);
        monitors.back().observe(spaces.all()[k].world);
    }
    // --steps counts ticks of the shared clock; otherwise the clock runs for the Duration
    const std::uint64_t ticks = options.steps.value_or(static_cast<std::uint64_t>(std::llround(duration / double(tick))));

    std::optional<OutputFile> csvFile;
    if (!openOutput(options.csvPath, csvFile)) return kExitUsageError;
    std::FILE* csv = csvFile ? csvFile->file() : nullptr;
    if (csv) {
        writeTrajectoryHeader(csv, true, anySoft);
        for (const Space& space : spaces.all()) writeTrajectoryRows(csv, space.world, space.name);
    }
    std::optional<OutputFile> nodesFile;
    if (!openOutput(options.nodesCsvPath, nodesFile)) return kExitUsageError;
    if (nodesFile) {
        writeNodeHeader(nodesFile->file(), true);
        for (const Space& space : spaces.all()) writeNodeRows(nodesFile->file(), space.world, space.name);
    }
    std::vector<Energy> energyBefore;
    for (const Space& space : spaces.all()) energyBefore.push_back(energyOf(space.world));
    int exitCode = kExitOk;
    {
        const InterruptGuard interrupts;
        const Deadline deadline(options.maxSeconds);
        const auto afterStep = [&](std::size_t k) {
            const Space& space = spaces.all()[k];
            monitors[k].observe(space.world);
            if (csv && space.world.stepCount() % options.every == 0) writeTrajectoryRows(csv, space.world, space.name);
            if (nodesFile && space.world.stepCount() % options.every == 0) {
                writeNodeRows(nodesFile->file(), space.world, space.name);
            }
        };
        try {
            for (std::uint64_t i = 0; i < ticks; ++i) {
                spaces.advance(tick, afterStep);
                if (csvFile && csvFile->failed()) break;
                if (InterruptGuard::signalReceived() != 0) break;
                if (i + 1 < ticks && deadline.passed()) {
                    std::fprintf(stderr, "stepwise: stopped after --max-seconds %g of wall-clock time: %.6g of %.6g s\n",
                                 deadline.seconds(), double(spaces.clock()), duration);
                    exitCode = kExitSimulationError;
                    break;
                }
            }
        } catch (const SimulationError& error) {
            std::fprintf(stderr, "stepwise: simulation failed: %s\n", error.what());
            exitCode = kExitSimulationError;
        }
        if (const int signal = InterruptGuard::signalReceived(); signal != 0) {
            std::fprintf(stderr, "stepwise: stopped by signal %d at %.6g of %.6g s on the clock\n", signal,
                         double(spaces.clock()), duration);
            exitCode = exitCodeForSignal(signal);
        }
    }
    std::string csvError;
    if (csvFile) csvError = csvFile->close();
    if (nodesFile) {
        const std::string nodesError = nodesFile->close();
        if (csvError.empty()) csvError = nodesError;
    }
    std::printf("Ran the clock for %.6g s\n", double(spaces.clock()));
    for (std::size_t k = 0; k < spaces.all().size(); ++k) {
        const Space& space = spaces.all()[k];
        std::printf("\n=== Space %s: simulated %.6g s in %llu steps\n", space.name.c_str(), double(space.world.time()),
                    static_cast<unsigned long long>(space.world.stepCount()));
        printFinalState(space.world);
        printJoints(space.world);
        printRegions(space.world);
        printSoftBodies(space.world);
        const Energy after = energyOf(space.world);
        std::printf("\nEnergy (kinetic = translational + rotational, plus potential), J\n");
        printEnergyLine("start", energyBefore[k]);
        printEnergyLine("end  ", after);
        if (!expectations[k].empty() && !printExpectationTable(expectations[k], monitors[k].results(space.world)) &&
            exitCode == kExitOk) {
            exitCode = kExitExpectationFailed;
        }
    }
    if (csvFile && csvError.empty()) std::printf("\nTrajectory written to %s\n", options.csvPath->c_str());
    if (nodesFile && csvError.empty()) std::printf("Soft bodies' nodes written to %s\n", options.nodesCsvPath->c_str());
    if (!csvError.empty()) {
        std::fprintf(stderr, "stepwise: error: %s; the trajectory is incomplete\n", csvError.c_str());
        if (exitCode == kExitOk || exitCode == kExitExpectationFailed) exitCode = kExitSimulationError;
    }
    return exitCode;
}

int runCommand(const RunOptions& options) {
    std::unique_ptr<Scene> scene = loadOrReport(options.scenePath);
    if (!scene) return kExitUsageError;
    printSceneHeader(options.scenePath, *scene);
    if (!scene->spaces.empty()) return runSpaces(options, std::move(*scene));
    const std::vector<Expectation> expectations = scene->expectations;

    if (options.threads) scene->settings.threads = *options.threads;
    // --explain with SubstepsPerIsland=true: a copy of the scene takes the first step, to show each island's count
    std::optional<World> firstStep;
    if (options.explain && scene->settings.substepsPerIsland) {
        firstStep.emplace(Scene(*scene));
        firstStep->step();
    }
    World world(std::move(*scene));
    world.timeStages(true);  // for the stage table at the end (printStageTimes())
    if (options.explain) {
        std::printf("\n%s", describeStepPlan(world.plan()).c_str());
        if (firstStep && world.plan().islandSubsteps.runs) {
            constexpr std::size_t kIslandLines = 12;  // a rain has thousands of islands: the counts, then a few
            std::printf("%s", describeIslandSubsteps(firstStep->islandSubsteps(), firstStep->dynamics(),
                                                     world.settings().substeps, kIslandLines)
                                  .c_str());
        }
        if (options.steps == std::uint64_t(0)) return kExitOk;  // --steps 0: the plan is all that was asked
        std::printf("\n");
    }
    // Observes between steps only: the trajectory is the same with or without Expect records.
    ExpectationMonitor monitor(world, expectations);
    monitor.observe(world);
    const double h = double(world.settings().timeStep);
    const double duration = options.duration.value_or(double(world.settings().duration));
    // Round to the nearest whole step: 10 s at 1/60 s is 600 steps, not 599.99.
    const std::uint64_t steps = options.steps.value_or(static_cast<std::uint64_t>(std::llround(duration / h)));

    std::optional<OutputFile> csvFile;
    if (!openOutput(options.csvPath, csvFile)) return kExitUsageError;
    std::FILE* csv = csvFile ? csvFile->file() : nullptr;
    if (csv) {
        writeTrajectoryHeader(csv, false, !world.softBodies().empty());
        writeTrajectoryRows(csv, world);
    }
    std::optional<OutputFile> nodesFile;
    if (!openOutput(options.nodesCsvPath, nodesFile)) return kExitUsageError;
    if (nodesFile) {
        writeNodeHeader(nodesFile->file());
        writeNodeRows(nodesFile->file(), world);
    }

    const Energy energyBefore = energyOf(world);
    const Vec3 momentumBefore = linearMomentumOf(world);
    const Vec3 angularMomentumBefore = angularMomentumOf(world);
    const auto start = Clock::now();
    int exitCode = kExitOk;
    RunWatch watch(world);
    {
        // Ctrl-C, kill or the time budget: stop between two steps, with every CSV row whole, and
        // report what ran (interrupt.hpp).
        const InterruptGuard interrupts;
        const Deadline deadline(options.maxSeconds);
        bool outOfTime = false;
        Progress progress(steps);
        try {
            for (std::uint64_t i = 0; i < steps; ++i) {
                world.step();
                monitor.observe(world);
                reportWarnings(watch, watch.observe(world));
                if (csv && world.stepCount() % options.every == 0) writeTrajectoryRows(csv, world);
                if (nodesFile && world.stepCount() % options.every == 0) writeNodeRows(nodesFile->file(), world);
                progress.update(world.stepCount(), double(world.time()));
                if (csvFile && csvFile->failed()) break;  // a full disk: no use going on
                if (InterruptGuard::signalReceived() != 0) break;
                if (i + 1 < steps && deadline.passed()) {
                    outOfTime = true;
                    break;
                }
            }
        } catch (const SimulationError& error) {
            std::fprintf(stderr, "stepwise: simulation failed: %s\n", error.what());
            exitCode = kExitSimulationError;
        } catch (const std::bad_alloc&) {
            std::fprintf(stderr, "stepwise: error: %s\n", outOfMemoryMessage(world).c_str());
            exitCode = kExitSimulationError;
        }
        if (outOfTime) {
            std::fprintf(stderr, "stepwise: stopped after --max-seconds %g of wall-clock time: %llu of %llu steps\n",
                         deadline.seconds(), static_cast<unsigned long long>(world.stepCount()),
                         static_cast<unsigned long long>(steps));
            exitCode = kExitSimulationError;
        }
        if (const int signal = InterruptGuard::signalReceived(); signal != 0) {
            std::fprintf(stderr, "stepwise: stopped by signal %d after %llu of %llu steps\n", signal,
                         static_cast<unsigned long long>(world.stepCount()), static_cast<unsigned long long>(steps));
            exitCode = exitCodeForSignal(signal);
        }
    }
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    std::string csvError;
    if (csvFile) csvError = csvFile->close();
    if (nodesFile) {
        const std::string nodesError = nodesFile->close();
        if (csvError.empty()) csvError = nodesError;
    }

    std::printf("Simulated %.6g s in %llu steps\n", double(world.time()),
                static_cast<unsigned long long>(world.stepCount()));
    if (watch.count() > kMaxRunWarnings) {
        std::fprintf(stderr, "stepwise: %zu warnings in all; the first %zu are above\n", watch.count(), kMaxRunWarnings);
    }
    printBroadphase(world);
    printFinalState(world);
    printJoints(world);
    printRegions(world);
    printSoftBodies(world);
    printConservation(energyBefore, energyOf(world), momentumBefore, linearMomentumOf(world), angularMomentumBefore,
                      angularMomentumOf(world));
    printStageTimes(world, wall);
    if (csvFile && csvError.empty()) std::printf("\nTrajectory written to %s\n", options.csvPath->c_str());
    if (nodesFile && csvError.empty()) std::printf("Soft bodies' nodes written to %s\n", options.nodesCsvPath->c_str());
    if (!csvError.empty()) {
        std::fprintf(stderr, "stepwise: error: %s; the trajectory is incomplete\n", csvError.c_str());
        if (exitCode == kExitOk || exitCode == kExitExpectationFailed) exitCode = kExitSimulationError;
    }
    if (!expectations.empty() && !printExpectationTable(expectations, monitor.results(world)) && exitCode == kExitOk) {
        exitCode = kExitExpectationFailed;
    }
    return exitCode;
}

int checkCommand(const std::string& scenePath) {
    std::unique_ptr<Scene> scene = loadOrReport(scenePath);
    if (!scene) return kExitUsageError;
    printSceneHeader(scenePath, *scene);
    std::printf("  duration %.6g s\n", double(scene->settings.duration));
    for (const DynamicObject& b : scene->dynamics) {
        std::printf("  DynamicObject    %-16s %-8s at %s m, v %s m/s, mass %.6g kg, %s, ", b.name.c_str(),
                    toString(b.shape), vec(b.position).c_str(), vec(b.velocity).c_str(), double(b.mass),
                    shapeSize(b).c_str());
        std::printf("elasticity %.3g, friction %.3g\n", double(b.elasticity), double(b.friction));
    }
    for (const KinematicsObject& b : scene->kinematics) {
        std::printf("  KinematicsObject %-16s %-8s at %s m, v %s m/s, %s\n", b.name.c_str(), toString(b.shape),
                    vec(b.position).c_str(), vec(b.velocity).c_str(), shapeSize(b).c_str());
    }
    for (const CollisionPlane& p : scene->planes) {
        std::printf("  CollisionPlane   %-16s through %s m, normal %s\n", p.name.c_str(), vec(p.position).c_str(),
                    vec(p.normal).c_str());
    }
    for (const SoftBody& b : scene->softBodies) {
        std::printf("  SoftBody         %-16s %-8s at %s m, v %s m/s, mass %.6g kg, %zu nodes, %zu springs, %zu "
                    "triangles, nRT %.6g J, elasticity %.3g, friction %.3g\n",
                    b.name.c_str(), toString(b.shape), vec(b.position).c_str(), vec(b.velocity).c_str(), double(b.mass),
                    b.nodeCount(), b.springs.size(), b.faces.size(), double(b.nRT), double(b.elasticity),
                    double(b.friction));
    }
    // "-" for a value the material leaves to each object's own default.
    const auto optional = [](const std::optional<Real>& value) {
        char text[32] = "-";
        if (value) std::snprintf(text, sizeof text, "%.6g", double(*value));
        return std::string(text);
    };
    for (const Material& m : scene->materials) {
        std::printf("  Material         %-16s density %s kg/m^3, friction %s, elasticity %s\n", m.name.c_str(),
                    optional(m.density).c_str(), optional(m.friction).c_str(), optional(m.elasticity).c_str());
    }
    for (const MaterialPair& pair : scene->materialPairs) {
        const std::string names = scene->materials[pair.a].name + " / " + scene->materials[pair.b].name;
        std::printf("  MaterialPair     %-16s friction %s, elasticity %s\n", names.c_str(), optional(pair.friction).c_str(),
                    optional(pair.elasticity).c_str());
    }
    for (const Expectation& e : scene->expectations) std::printf("  Expect (line %d)  %s\n", e.line, describe(e).c_str());
    for (const MayChange& m : scene->mayChange) {
        std::printf("  MayChange (line %d)  %s may differ from this file when it is graded as the starter\n", m.line,
                    describeAllowed(m).c_str());
    }
    for (const Spring& s : scene->springs) {
        const std::string other = s.bodyB == kFixedInWorld ? "the world point " + vec(s.anchorB) + " m"
                                                           : scene->dynamics[s.bodyB].name;
        std::printf("  Spring           %-16s %s to %s, k %.6g N/m, c %.6g N*s/m, rest length %.6g m\n",
                    s.name.c_str(), scene->dynamics[s.bodyA].name.c_str(), other.c_str(), double(s.stiffness),
                    double(s.damping), double(s.restLength));
    }
    for (const Attractor& a : scene->attractors) {
        std::printf("  Attractor        %-16s at %s m, mu %.6g m^3/s^2\n", a.name.c_str(), vec(a.position).c_str(),
                    double(a.mu));
    }
    for (const Region& r : scene->regions) {
        std::printf("  Region           %-16s %s at %s m\n", r.name.c_str(), toString(r.effect), vec(r.position).c_str());
    }
    for (const JointDef& j : scene->joints) {
        std::printf("  %-16s %-16s %s - %s\n", toString(j.kind), j.name.c_str(), j.bodyA.c_str(),
                    j.bodyB.empty() ? "world" : j.bodyB.c_str());
    }
    std::printf("OK: %s is a valid scene.\n", scenePath.c_str());
    return kExitOk;
}

}  // namespace stepwise::cli
