/// @file contact_solver.cpp
/// @brief The solver bodies' records: the poses the separations are measured from, the velocities copied in and out.
#include "dynamics/contact_solver.hpp"

#include <vector>

namespace stepwise {

void recordPoses(const BodySet& bodies, SolverWorkspace& workspace) {
    const std::size_t dynamicCount = bodies.dynamics.size();
    workspace.poses.resize(dynamicCount + bodies.kinematics.size() + 1);
    for (std::size_t i = 0; i < dynamicCount; ++i) {
        workspace.poses[i] = {bodies.dynamics[i].position, bodies.dynamics[i].orientation};
    }
    recordKinematicPoses(bodies, workspace);
    workspace.poses.back() = Pose{};  // the planes' fixed pose at the origin
}

void recordKinematicPoses(const BodySet& bodies, SolverWorkspace& workspace) {
    const std::size_t dynamicCount = bodies.dynamics.size();
    for (std::size_t i = 0; i < bodies.kinematics.size(); ++i) {
        workspace.poses[dynamicCount + i] = {bodies.kinematics[i].position, bodies.kinematics[i].orientation};
    }
}

void recordPoses(const BodySet& bodies, SolverWorkspace& workspace, std::span<const std::uint32_t> dynamicBodies) {
    workspace.poses.resize(bodies.dynamics.size() + bodies.kinematics.size() + 1);
    for (const std::uint32_t i : dynamicBodies) workspace.poses[i] = {bodies.dynamics[i].position, bodies.dynamics[i].orientation};
    recordKinematicPoses(bodies, workspace);
    workspace.poses.back() = Pose{};  // the planes' fixed pose at the origin
}

namespace {

/// copyVelocitiesIn() of record @p i.
inline void copyVelocityIn(SolverWorkspace& workspace, std::size_t i) {
    const DynamicObject& body = workspace.dynamics[workspace.recordBody[i]];
    workspace.bodies[i].velocity = body.velocity;
    workspace.bodies[i].angularVelocity = body.angularVelocity;
}

}  // namespace

void copyVelocitiesIn(SolverWorkspace& workspace) {
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) copyVelocityIn(workspace, i);
}

void copyVelocitiesIn(SolverWorkspace& workspace, std::span<const std::uint32_t> records) {
    for (const std::uint32_t i : records) copyVelocityIn(workspace, i);
}

void copyVelocitiesOut(SolverWorkspace& workspace) {
    for (std::size_t i = 1; i < workspace.bodies.size(); ++i) copyVelocitiesOut(workspace, i);
}

void copyVelocitiesOut(SolverWorkspace& workspace, std::span<const std::uint32_t> records) {
    for (const std::uint32_t i : records) copyVelocitiesOut(workspace, std::size_t{i});
}

namespace {

template <class T>
std::size_t bytesOf(const std::vector<T>& array) {
    return array.size() * sizeof(T);
}

}  // namespace

SolverFootprint solverFootprint(const SolverWorkspace& w) {
    SolverFootprint f;
    f.passBytes = bytesOf(w.bodies) + bytesOf(w.contacts) + bytesOf(w.rows) + bytesOf(w.turningAnchors) + bytesOf(w.poses) +
                  bytesOf(w.roundContacts) + bytesOf(w.otherContacts);
    f.substepBytes = f.passBytes + bytesOf(w.substepStart) + bytesOf(w.turnSums);
    f.allBytes = f.passBytes + bytesOf(w.starts) + bytesOf(w.bouncing) + bytesOf(w.inertias) + bytesOf(w.recordBody) +
                 bytesOf(w.ballInertia) + bytesOf(w.bodyRecord) + bytesOf(w.previousImpulses) +
                 bytesOf(w.currentImpulses) + bytesOf(w.substepStart) + bytesOf(w.turnSums);
    return f;
}

}  // namespace stepwise
