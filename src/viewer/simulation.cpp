/// @file simulation.cpp
/// @brief The viewer's World or Spaces: loading and reloading, fixed steps, the S key's recorded steps, picking forces.
#include "viewer/simulation.hpp"

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

/// Sweeps each space's box over the scene's Duration (SpaceLayout): a copy of the scene runs
/// ahead, every space running whatever its Paused field says (it may be resumed), for at
/// most kLayoutLookaheadBodySteps of work. A simulation error ends the sweep early:
/// the live run meets it too, and reports it then.
void sweepAhead(Scene scene, SpaceLayout& layout) {
    const Real duration = scene.settings.duration;
    Spaces ahead(std::move(scene));
    for (Space& space : ahead.all()) space.paused = false;
    const Real tick = ahead.finestTick();
    std::uint64_t bodies = 1;  // every space's dynamic bodies and soft bodies' nodes: what a tick costs, at most
    for (const Space& space : ahead.all()) {
        bodies += space.world.dynamics().size();
        for (const SoftBody& soft : space.world.softBodies()) bodies += soft.nodeCount();
    }
    const auto ticks = std::min(static_cast<std::uint64_t>(std::llround(duration / tick)),
                                kLayoutLookaheadBodySteps / bodies);
    const auto grow = [&](std::size_t k) { layout.grow(k, ahead.all()[k].world); };
    try {
        for (std::uint64_t i = 0; i < ticks; ++i) ahead.advance(tick, grow);
    } catch (const SimulationError&) {
    }
}

}  // namespace

std::string bodyName(const World& world, const BodyRef& ref) { return objectName(world, ref); }

Simulation::Loaded Simulation::load(const std::string& path) {
    Scene scene = loadSceneFile(path);
    for (const std::string& warning : scene.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
    Loaded loaded;
    if (scene.spaces.empty()) {
        loaded.world = std::make_unique<World>(std::move(scene));
        loaded.world->timeStages(true);  // the overlay shows each stage's time
        return loaded;
    }
    Scene copy = scene;
    loaded.spaces = std::make_unique<Spaces>(std::move(scene));
    for (Space& space : loaded.spaces->all()) space.world.timeStages(true);
    loaded.layout.reset(loaded.spaces->all().size());
    for (std::size_t k = 0; k < loaded.spaces->all().size(); ++k) loaded.layout.grow(k, loaded.spaces->all()[k].world);
    sweepAhead(std::move(copy), loaded.layout);
    return loaded;
}

void Simulation::adopt(Loaded loaded) {
    const SpaceArrangement arrangement = layout_.arrangement();
    world_ = std::move(loaded.world);
    spaces_ = std::move(loaded.spaces);
    layout_ = std::move(loaded.layout);
    layout_.arrange(arrangement);
    FixedStepClock fresh(spaces_ ? double(spaces_->finestTick()) : double(world_->settings().timeStep));
    fresh.setPaused(clock_.paused());
    fresh.setScale(clock_.scale());
    clock_ = fresh;
}

Simulation::Simulation(std::string scenePath) : path_(std::move(scenePath)), clock_(1), loads_(1) {
    adopt(load(path_));
}

bool Simulation::reload() {
    try {
        adopt(load(path_));
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
    grab_.reset();
    shownStage_.reset();
    walkthrough_.clear();
    error_.clear();
    ++loads_;
    return true;
}

void Simulation::pushHeld(World& world) {
    // The held point's force, as an impulse F·h given just before the
    // step: the velocity change a force F makes over one step.
    DynamicObject& body = world.dynamics()[grab_->body];
    if (log_) {
        log_->line("%s %s step %llu at %s force %s", grab_->pull ? "pull" : "push", body.name.c_str(),
                   static_cast<unsigned long long>(world.stepCount() + 1), EventLog::vec(grabPoint()).c_str(),
                   EventLog::vec(grabForce()).c_str());
    }
    world.wakeIsland(grab_->body);  // a sleeping body must feel the push, and its island with it
    applyGrab(body, *grab_, world.settings().gravity, world.settings().timeStep);
}

void Simulation::takeStep() {
    if (grab_) pushHeld(*world_);
    try {
        world_->step();
    } catch (const SimulationError& e) {
        clock_.setPaused(true);
        error_ = std::string("simulation failed (paused; R reloads the scene):\n") + e.what();
        std::fprintf(stderr, "stepwise view: %s\n", error_.c_str());
        throw;
    }
}

std::uint64_t Simulation::takeTick() {
    std::uint64_t steps = 0;
    // The held body's push before each step of its space; each step's poses widen its swept box.
    const auto before = [this](std::size_t k) {
        if (grab_ && k == grabSpace_) pushHeld(spaces_->all()[k].world);
    };
    const auto after = [this, &steps](std::size_t k) {
        layout_.grow(k, spaces_->all()[k].world);
        ++steps;
    };
    try {
        spaces_->advance(spaces_->finestTick(), after, before);
    } catch (const SimulationError& e) {
        clock_.setPaused(true);
        error_ = std::string("simulation failed (paused; R reloads the scene):\n") + e.what();
        std::fprintf(stderr, "stepwise view: %s\n", error_.c_str());
        throw;
    }
    return steps;
}

std::uint64_t Simulation::advanceFrame(double wallSeconds) {
    const std::uint64_t steps = clock_.advance(wallSeconds);
    if (steps > 0) shownStage_.reset();
    std::uint64_t taken = 0;
    try {
        for (; taken < steps; ++taken) {
            if (spaces_) takeTick();
            else takeStep();
        }
    } catch (const SimulationError&) {
        // takeStep() and takeTick() paused the clock and keep the message for the screen.
    }
    return taken;
}

bool Simulation::stepOnce() {
    if (shownStage_) {  // the World is at the end of the walk-through's step already
        shownStage_.reset();
        return true;
    }
    try {
        if (!spaces_) {
            takeStep();
            return true;
        }
        // A running space of step h and time scale s steps at least once in every h/s of the
        // clock: that many ticks, and one for the rounding, are the most N has to wait.
        std::uint64_t limit = 0;
        const Real tick = spaces_->finestTick();
        for (const Space& space : spaces_->all()) {
            if (space.paused) continue;
            const Real ticks = space.world.settings().timeStep / space.timeScale / tick;
            limit = std::max(limit, static_cast<std::uint64_t>(std::ceil(ticks)) + 1);
        }
        for (std::uint64_t i = 0; i < limit; ++i) {
            if (takeTick() > 0) return true;
        }
    } catch (const SimulationError&) {
        return true;  // it stepped, and failed: error() says why
    }
    return false;
}

void Simulation::stepTo(double seconds) {
    if (spaces_) {
        // As `stepwise run --duration` counts its ticks: llround(seconds / tick) in all.
        const double tick = double(spaces_->finestTick());
        const auto target = static_cast<std::uint64_t>(std::llround(seconds / tick));
        auto taken = static_cast<std::uint64_t>(std::llround(double(spaces_->clock()) / tick));
        for (; taken < target; ++taken) takeTick();  // a SimulationError reaches the caller
        return;
    }
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
    if (spaces_) return;  // kNoWalkthroughWithSpaces
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
    if (spaces_) return false;  // kNoWalkthroughWithSpaces
    clock_.setPaused(true);
    if (!recordStep()) return false;
    const bool exists = k < walkthrough_.size();
    shownStage_ = exists ? k : walkthrough_.size() - 1;
    walkthrough_.show(*shownStage_);
    return exists;
}

void Simulation::grab(std::uint32_t body, const Vec3& point, const Vec3& rayDirection, bool pull, std::size_t space) {
    World& world = spaces_ ? spaces_->all().at(space).world : *world_;
    grabSpace_ = spaces_ ? space : 0;
    grab_ = grabAt(world.dynamics()[body], body, point, rayDirection, pull);
}

void Simulation::aimGrab(const Vec3& rayDirection) {
    if (grab_) viewer::aimGrab(*grab_, rayDirection);
}

void Simulation::release() {
    if (grab_ && log_) {
        const DynamicObject& b = worldAt(grabSpace_).dynamics()[grab_->body];
        log_->line("release %s v %s w %s", b.name.c_str(), EventLog::vec(b.velocity).c_str(),
                   EventLog::vec(b.angularVelocity).c_str());
    }
    grab_.reset();
}

Vec3 Simulation::grabPoint() const {
    return grab_ ? viewer::grabPoint(worldAt(grabSpace_).dynamics()[grab_->body], *grab_) : Vec3(0);
}

Vec3 Simulation::grabForce() const {
    if (!grab_) return Vec3(0);
    const World& world = worldAt(grabSpace_);
    return viewer::grabForce(world.dynamics()[grab_->body], *grab_, world.settings().gravity);
}

void Simulation::dumpState(const std::string& path) const {
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (!out) throw std::runtime_error("cannot write '" + path + "'");
    if (spaces_) {
        writeTrajectoryHeader(out, true);
        for (const Space& space : spaces_->all()) writeTrajectoryRows(out, space.world, space.name);
    } else {
        writeTrajectoryHeader(out);
        writeTrajectoryRows(out, *world_);
    }
    if (std::fclose(out) != 0) throw std::runtime_error("cannot write '" + path + "'");
}

bool Simulation::toggleSpacePause(std::size_t k) {
    if (!spaces_ || k >= spaces_->all().size()) return false;
    spaces_->togglePause(k);
    return true;
}

}  // namespace stepwise::viewer
