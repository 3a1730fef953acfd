/// @file simulation.cpp
/// @brief The viewer's World: loading and reloading, fixed steps, the S key's recorded steps, picking forces.
#include "viewer/simulation.hpp"

#include "dynamics/islands.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "config/scene_loader.hpp"
#include "core/errors.hpp"
#include "io/trajectory_csv.hpp"
#include "world/object_name.hpp"

namespace stepwise::viewer {

namespace {

std::unique_ptr<World> loadWorld(const std::string& path) {
    Scene scene = loadSceneFile(path);
    for (const std::string& warning : scene.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
    return std::make_unique<World>(std::move(scene));
}

}  // namespace

std::string bodyName(const World& world, const BodyRef& ref) { return objectName(world, ref); }

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
    walkthrough_.clear();
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
    if (steps > 0) shownStage_.reset();
    std::uint64_t taken = 0;
    try {
        for (; taken < steps; ++taken) takeStep();
    } catch (const SimulationError&) {
        // takeStep() paused the clock and keeps the message for the screen.
    }
    return taken;
}

void Simulation::stepOnce() {
    if (shownStage_) {  // the World is at the end of the walk-through's step already
        shownStage_.reset();
        return;
    }
    try {
        takeStep();
    } catch (const SimulationError&) {
    }
}

void Simulation::stepTo(double seconds) {
    const auto target = static_cast<std::uint64_t>(std::llround(seconds / double(world_->settings().timeStep)));
    while (world_->stepCount() < target) takeStep();  // a SimulationError reaches the caller
}

bool Simulation::recordStep() {
    shownStage_.reset();
    world_->setObserver(&walkthrough_);
    try {
        takeStep();
    } catch (const SimulationError&) {
        world_->setObserver(nullptr);
        walkthrough_.clear();  // a half-recorded step: start afresh next time
        return false;
    }
    world_->setObserver(nullptr);  // only the walk-through's steps are watched
    return walkthrough_.size() > 0;
}

void Simulation::stepStage(bool skipMiddleSubsteps) {
    clock_.setPaused(true);
    if (shownStage_) {
        for (std::size_t k = *shownStage_ + 1; k < walkthrough_.size(); ++k) {
            if (skipMiddleSubsteps && !walkthrough_.isSummaryStop(k)) continue;
            shownStage_ = k;
            walkthrough_.show(k);
            return;
        }
    }
    if (!recordStep()) return;
    shownStage_ = 0;
    walkthrough_.show(0);
}

bool Simulation::showStageRun(std::size_t k) {
    clock_.setPaused(true);
    if (!recordStep()) return false;
    const bool exists = k < walkthrough_.size();
    shownStage_ = exists ? k : walkthrough_.size() - 1;
    walkthrough_.show(*shownStage_);
    return exists;
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
