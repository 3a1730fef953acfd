/// @file packed_records.cpp
/// @brief Into the packed records at a step's start, and back to the objects at its end (packed_substeps.hpp).
#include "fast/packed_substeps.hpp"

#include <cstring>

#include "objects/inertia.hpp"

namespace stepwise {

bool packRecords(SolverWorkspace& solver, FastWorkspace& fast) {
    if (!solver.otherContacts.empty()) return false;  // rows of a box, a moving kinematic body or a belt: the substeps on the objects
    const std::size_t count = solver.bodies.size();
    fast.centres.resize(count);
    fast.orientations.resize(count);
    fast.freeFlight.resize(count);
    fast.startMomentum.resize(count);
    solver.substepStart.resize(count);
    fast.centres[0] = SolverCentre{};  // the static record: a plane's "centre" is the origin
    bool shared = true;
    for (std::size_t i = 1; i < count; ++i) {
        const DynamicObject& body = solver.dynamics[solver.recordBody[i]];
        // A ball turns by ω = L/I about any axis (rotateTorqueFree()); a sleeper never has a contact
        // (dropSleepingPairs()) and is never moved, which the kick would not know.
        if (solver.ballInertia[i] == Real(0) || !equalMoments(body.inverseInertiaBody) || body.asleep) return false;
        fast.centres[i].position = body.position;
        fast.orientations[i] = body.orientation;
        fast.freeFlight[i] = {body.acceleration, body.torque};
        // Compared as bits, not numbers: −0 and +0 are equal numbers, but v + h·(−0) and v + h·(+0)
        // differ when v is −0, and the kick must give every ball the bits its own a and τ give it.
        shared = shared && std::memcmp(&fast.freeFlight[i], &fast.freeFlight[1], sizeof(FreeFlight)) == 0;
        fast.startMomentum[i] = body.angularMomentum;
    }
    fast.sharedFlight = shared;
    return true;
}

void unpackRecords(SolverWorkspace& solver, const FastWorkspace& fast) {
    for (std::size_t i = 1; i < solver.bodies.size(); ++i) {
        DynamicObject& body = solver.dynamics[solver.recordBody[i]];
        const SolverBody& record = solver.bodies[i];
        body.velocity = record.velocity;
        body.angularVelocity = record.angularVelocity;
        body.angularMomentum = solver.ballInertia[i] * record.angularVelocity;  // as copyVelocitiesOut()
        body.position = fast.centres[i].position;
        body.orientation = fast.orientations[i];
    }
}

}  // namespace stepwise
