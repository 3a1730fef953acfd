/// @file stages.cpp
/// @brief The stages' printed names.
#include "core/stages.hpp"

namespace stepwise {

const char* stageName(Stage stage) {
    switch (stage) {
        case Stage::ApplyForces: return "apply-forces";
        case Stage::Integrate: return "integrate";
        case Stage::MoveKinematics: return "move-kinematics";
        case Stage::Broadphase: return "broadphase";
        case Stage::Narrowphase: return "narrowphase";
        case Stage::ResolveImpulses: return "resolve-impulses";
        case Stage::CorrectPositions: return "correct-positions";
        case Stage::PrepareConstraints: return "prepare-constraints";
        case Stage::SolveConstraints: return "solve-constraints";
        case Stage::RelaxConstraints: return "relax-constraints";
        case Stage::Restitution: return "restitution";
        case Stage::Sleep: return "sleep";
        case Stage::Continuous: return "continuous";
        case Stage::SoftBodies: return "soft-bodies";
        case Stage::Count: break;
    }
    return "?";
}

}  // namespace stepwise
