/// @file world.cpp
/// @brief The step pipeline, read top to bottom in World::step().
#include "world/world.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "collision/narrowphase.hpp"
#include "core/errors.hpp"
#include "dynamics/inertia.hpp"
#include "forces/apply_forces.hpp"
#include "integrators/integrators.hpp"

namespace stepwise {

namespace {

void require(bool condition, const std::string& object, const std::string& what) {
    if (!condition) throw std::invalid_argument("object '" + object + "': " + what);
}

bool isFinite(Real x) { return std::isfinite(x); }

}  // namespace

World::World(Scene scene)
    : settings_(scene.settings),
      dynamics_(std::move(scene.dynamics)),
      kinematics_(std::move(scene.kinematics)),
      planes_(std::move(scene.planes)) {
    require(isFinite(settings_.timeStep) && settings_.timeStep > 0, "World", "time step must be > 0 s");
    require(stepwise::isFinite(settings_.gravity), "World", "gravity must be finite");
    require(settings_.impulseIterations >= 1, "World", "impulse iterations must be at least 1");
    for (DynamicObject& body : dynamics_) {
        require(isFinite(body.mass) && body.mass > 0, body.name, "mass must be > 0 kg");
        require(isFinite(body.radius) && body.radius > 0, body.name, "radius must be > 0 m");
        require(stepwise::isFinite(body.position) && stepwise::isFinite(body.velocity), body.name,
                "position and velocity must be finite");
        body.inverseMass = Real(1) / body.mass;
        initialiseMassProperties(body);
    }
    for (CollisionPlane& plane : planes_) {
        const Real length = glm::length(plane.normal);
        require(isFinite(length) && length > 0, plane.name, "plane normal must not be zero");
        plane.normal /= length;
    }
}

const DynamicObject* World::findDynamic(std::string_view name) const {
    for (const DynamicObject& body : dynamics_) {
        if (body.name == name) return &body;
    }
    return nullptr;
}

BodySet World::bodies() { return {dynamics_, kinematics_, planes_}; }

/// One step of the simulation, from t to t + h. Each line is one stage,
/// each stage lives in its own file; read them in this order.
void World::step() {
    const Real h = settings_.timeStep;
    const AccelerationFunction forces = uniformForces(settings_.gravity);

    // 1. Forces → accelerations (src/forces/apply_forces.cpp)
    runStage(Stage::ApplyForces, [&] { forces(dynamics_); });

    // 2. Advance dynamic bodies by h (src/integrators/*.cpp)
    runStage(Stage::Integrate, [&] {
        switch (settings_.integrator) {
            case IntegratorKind::ExplicitEuler: integrateExplicitEuler(dynamics_, h); break;
            case IntegratorKind::SymplecticEuler: integrateSymplecticEuler(dynamics_, h); break;
            case IntegratorKind::Verlet: integrateVerlet(dynamics_, h, forces); break;
        }
    });

    // 3. Advance kinematic bodies along their prescribed motion (src/integrators/kinematic_motion.cpp)
    runStage(Stage::MoveKinematics, [&] { moveKinematics(kinematics_, h); });

    // 4. Which pairs might touch? (src/collision/broadphase.cpp → broadphase_*.cpp)
    runStage(Stage::Broadphase, [&] { broadphase_.findPairs(settings_.broadphase, bodies(), pairs_); });

    // 5. Which of them do, where, and how deep? (src/collision/narrowphase.cpp → sphere_*.cpp)
    runStage(Stage::Narrowphase, [&] { findContacts(bodies(), pairs_, contacts_); });

    // 6. Impulses: bounce and friction change velocities (src/dynamics/impulse_resolver.cpp)
    runStage(Stage::ResolveImpulses, [&] {
        impulses_.resize(contacts_.size());
        resolveImpulses(bodies(), contacts_, h, settings_.impulseIterations, settings_.warmStarting, contactWorkspace_,
                        impulses_);
    });

    // 7. Push overlapping bodies apart (src/dynamics/impulse_resolver.cpp, correctPositions)
    const Real supportStep = positionShareOfVelocityChange(settings_.integrator) * h;
    runStage(Stage::CorrectPositions, [&] { correctPositions(bodies(), contacts_, h, supportStep, contactWorkspace_); });

    time_ += h;
    ++stepCount_;
}

template <class StageBody>
void World::runStage(Stage stage, StageBody&& body) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    body();
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();

    StageRecord& record = stageRecords_[static_cast<std::size_t>(stage)];
    record.ranLastStep = true;
    record.runs += 1;
    record.lastSeconds = seconds;
    record.totalSeconds += seconds;
    checkFinite(stage);
}

void World::checkFinite(Stage stage) const {
    auto fail = [&](const std::string& object, const char* quantity) {
        throw SimulationError(object, stageName(stage), stepCount_, static_cast<double>(time_),
                              std::string("non-finite ") + quantity +
                                  " (check masses, time step and forces in the scene)");
    };
    for (const DynamicObject& body : dynamics_) {
        if (!stepwise::isFinite(body.position)) fail(body.name, "position");
        if (!stepwise::isFinite(body.velocity)) fail(body.name, "velocity");
        if (!stepwise::isFinite(body.acceleration)) fail(body.name, "acceleration");
        if (!stepwise::isFinite(body.orientation)) fail(body.name, "orientation");
        if (!stepwise::isFinite(body.angularVelocity)) fail(body.name, "angular velocity");
        if (!stepwise::isFinite(body.angularMomentum)) fail(body.name, "angular momentum");
        if (!stepwise::isFinite(body.torque)) fail(body.name, "torque");
    }
    for (const KinematicsObject& body : kinematics_) {
        if (!stepwise::isFinite(body.position)) fail(body.name, "position");
        if (!stepwise::isFinite(body.orientation)) fail(body.name, "orientation");
    }
}

const char* stageName(Stage stage) {
    switch (stage) {
        case Stage::ApplyForces: return "apply-forces";
        case Stage::Integrate: return "integrate";
        case Stage::MoveKinematics: return "move-kinematics";
        case Stage::Broadphase: return "broadphase";
        case Stage::Narrowphase: return "narrowphase";
        case Stage::ResolveImpulses: return "resolve-impulses";
        case Stage::CorrectPositions: return "correct-positions";
        case Stage::Count: break;
    }
    return "?";
}

}  // namespace stepwise
