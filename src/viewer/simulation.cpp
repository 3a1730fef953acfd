/// @file simulation.cpp
/// @brief The viewer's World: loading and reloading, fixed steps, the stage walk-through, picking forces.
#include "viewer/simulation.hpp"

#include "dynamics/islands.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "config/scene_loader.hpp"
#include "core/errors.hpp"
#include "io/trajectory_csv.hpp"

namespace stepwise::viewer {

namespace {

std::unique_ptr<World> loadWorld(const std::string& path) {
    Scene scene = loadSceneFile(path);
    for (const std::string& warning : scene.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
    return std::make_unique<World>(std::move(scene));
}

std::string format(const char* pattern, double a, double b = 0, double c = 0) {
    char text[160];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

}  // namespace

std::string bodyName(const World& world, const BodyRef& ref) {
    switch (ref.kind) {
        case BodyKind::Dynamic: return world.dynamics()[ref.index].name;
        case BodyKind::Kinematic: return world.kinematics()[ref.index].name;
        case BodyKind::Plane: return world.planes()[ref.index].name;
    }
    return "?";
}

Simulation::Simulation(std::string scenePath)
    : path_(std::move(scenePath)), world_(loadWorld(path_)), clock_(double(world_->settings().timeStep)),
      loads_(1) {}

bool Simulation::reload() {
    try {
        std::unique_ptr<World> fresh = loadWorld(path_);
        world_ = std::move(fresh);
    } catch (const ConfigError& e) {
        error_ = "R: " + path_ + " was not reloaded; the last good scene stays:";
        for (const ConfigDiagnostic& d : e.diagnostics()) error_ += "\n" + d.message();
        std::fprintf(stderr, "%s\n", error_.c_str());
        return false;
    } catch (const std::invalid_argument& e) {
        error_ = "R: " + path_ + " was not reloaded; the last good scene stays:\n" + e.what();
        std::fprintf(stderr, "%s\n", error_.c_str());
        return false;
    }
    FixedStepClock fresh(double(world_->settings().timeStep));
    fresh.setPaused(clock_.paused());
    fresh.setScale(clock_.scale());
    clock_ = fresh;
    grab_.reset();
    shownStage_.reset();
    before_ = {};
    error_.clear();
    ++loads_;
    return true;
}

void Simulation::takeStep() {
    if (grab_) {
        // The held point's force, as an impulse F·h given just before the
        // step: the velocity change a force F makes over one step.
        DynamicObject& body = world_->dynamics()[grab_->body];
        if (log_) {
            log_->line("%s %s step %llu at %s force %s", grab_->pull ? "pull" : "push", body.name.c_str(),
                       static_cast<unsigned long long>(world_->stepCount() + 1),
                       EventLog::vec(grabPoint()).c_str(), EventLog::vec(grabForce()).c_str());
        }
        wakeIsland(world_->dynamics(), grab_->body);  // a sleeping body must feel the push
        applyGrab(body, *grab_, world_->settings().gravity, world_->settings().timeStep);
    }
    try {
        world_->step();
    } catch (const SimulationError& e) {
        clock_.setPaused(true);
        error_ = std::string("simulation failed (paused; R reloads the scene):\n") + e.what();
        std::fprintf(stderr, "stepwise view: %s\n", error_.c_str());
        throw;
    }
}

std::uint64_t Simulation::advanceFrame(double wallSeconds) {
    const std::uint64_t steps = clock_.advance(wallSeconds);
    if (steps > 0) {
        shownStage_.reset();
        before_ = {};
    }
    std::uint64_t taken = 0;
    try {
        for (; taken < steps; ++taken) takeStep();
    } catch (const SimulationError&) {
        // takeStep() paused the clock and keeps the message for the screen.
    }
    return taken;
}

void Simulation::stepOnce() {
    shownStage_.reset();
    before_ = {};
    try {
        takeStep();
    } catch (const SimulationError&) {
    }
}

void Simulation::stepTo(double seconds) {
    const auto target = static_cast<std::uint64_t>(std::llround(seconds / double(world_->settings().timeStep)));
    while (world_->stepCount() < target) takeStep();  // a SimulationError reaches the caller
}

void Simulation::stepStage() {
    clock_.setPaused(true);
    if (shownStage_ && *shownStage_ + 1 < kStageCount) {
        ++*shownStage_;
        return;
    }
    PoseSnapshot snapshot;
    for (const DynamicObject& b : world_->dynamics()) {
        snapshot.positions.push_back(b.position);
        snapshot.orientations.push_back(b.orientation);
    }
    try {
        takeStep();
    } catch (const SimulationError&) {
        shownStage_.reset();
        return;
    }
    before_ = std::move(snapshot);
    shownStage_ = 0;
}

std::string Simulation::describeStage(Stage stage) const {
    const World& w = *world_;
    const std::size_t n = w.dynamics().size();
    std::string text = stageName(stage);
    text += ": ";
    switch (stage) {
        case Stage::ApplyForces:
            text += std::to_string(n) + " accelerations a = g + a_obj";
            if (n > 0) {
                const Vec3& a = w.dynamics()[0].acceleration;
                text += " (" + w.dynamics()[0].name + ": " +
                        format("%.3g, %.3g, %.3g m/s^2)", double(a.x), double(a.y), double(a.z));
            }
            break;
        case Stage::Integrate: {
            Real largest = 0;
            std::string who;
            for (std::size_t i = 0; i < n && i < before_.positions.size(); ++i) {
                const Real moved = glm::length(w.dynamics()[i].position - before_.positions[i]);
                if (moved >= largest) {
                    largest = moved;
                    who = w.dynamics()[i].name;
                }
            }
            text += std::to_string(n) + " bodies advanced by h = " + format("%.4g s", double(w.settings().timeStep)) +
                    " (" + toString(w.settings().integrator) + ")";
            if (!who.empty()) text += "; largest move in the whole step " + format("%.3g mm", 1e3 * double(largest)) +
                                      " (" + who + ")";
            break;
        }
        case Stage::MoveKinematics:
            text += std::to_string(w.kinematics().size()) + " kinematic bodies moved along their prescribed velocity";
            break;
        case Stage::Broadphase:
            text += std::to_string(w.candidatePairs().size()) + " candidate pairs whose bounding boxes overlap";
            break;
        case Stage::Narrowphase: {
            text += std::to_string(w.contacts().size()) + " contacts";
            const Contact* deepest = nullptr;
            for (const Contact& c : w.contacts()) {
                if (!deepest || c.depth > deepest->depth) deepest = &c;
            }
            if (deepest) {
                text += "; deepest " + format("%.3g mm", 1e3 * double(deepest->depth)) + " (" +
                        w.dynamics()[deepest->a].name + " - " + bodyName(w, deepest->b) + ")";
            }
            break;
        }
        case Stage::ResolveImpulses: {
            Real normal = 0, friction = 0, approach = 0;
            for (const ImpulseReport& r : w.impulses()) {
                normal += r.normalImpulse;
                friction += r.frictionImpulse;
                approach = std::max(approach, r.approachSpeed);
            }
            text += std::to_string(w.impulses().size()) + " impulses, normal " + format("%.3g N*s", double(normal)) +
                    ", friction " + format("%.3g N*s", double(friction)) + ", fastest approach " +
                    format("%.3g m/s", double(approach));
            break;
        }
        case Stage::CorrectPositions: {
            Real deepest = 0;
            for (const Contact& c : w.contacts()) deepest = std::max(deepest, c.depth);
            text += "overlaps of up to " + format("%.3g mm", 1e3 * double(deepest)) +
                    " removed; resting bodies moved as a support force would";
            break;
        }
        case Stage::PrepareConstraints:
            text += std::to_string(w.contacts().size()) + " contact constraints prepared (anchors, effective masses, warm start)";
            break;
        case Stage::SolveConstraints:
        case Stage::RelaxConstraints:
            text += std::to_string(w.settings().substeps) + " substeps of h/" + std::to_string(w.settings().substeps);
            break;
        case Stage::Restitution:
        case Stage::Sleep:
            text += "done";
            break;
        case Stage::Continuous:
            text += std::to_string(w.bodiesStoppedAtImpact()) + " fast bodies stopped at their time of impact";
            break;
        case Stage::Count: break;
    }
    const StageRecord& record = w.stageRecords()[static_cast<std::size_t>(stage)];
    text += format("  [%.1f us]", 1e6 * record.lastSeconds);
    return text;
}

void Simulation::grab(std::uint32_t body, const Vec3& point, const Vec3& rayDirection, bool pull) {
    grab_ = grabAt(world_->dynamics()[body], body, point, rayDirection, pull);
}

void Simulation::aimGrab(const Vec3& rayDirection) {
    if (grab_) viewer::aimGrab(*grab_, rayDirection);
}

void Simulation::release() {
    if (grab_ && log_) {
        const DynamicObject& b = world_->dynamics()[grab_->body];
        log_->line("release %s v %s w %s", b.name.c_str(), EventLog::vec(b.velocity).c_str(),
                   EventLog::vec(b.angularVelocity).c_str());
    }
    grab_.reset();
}

Vec3 Simulation::grabPoint() const {
    return grab_ ? viewer::grabPoint(world_->dynamics()[grab_->body], *grab_) : Vec3(0);
}

Vec3 Simulation::grabForce() const {
    return grab_ ? viewer::grabForce(world_->dynamics()[grab_->body], *grab_, world_->settings().gravity) : Vec3(0);
}

void Simulation::dumpState(const std::string& path) const {
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (!out) throw std::runtime_error("cannot write '" + path + "'");
    writeTrajectoryHeader(out);
    writeTrajectoryRows(out, *world_);
    if (std::fclose(out) != 0) throw std::runtime_error("cannot write '" + path + "'");
}

}  // namespace stepwise::viewer
