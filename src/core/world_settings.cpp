/// @file world_settings.cpp
/// @brief The scene-file spellings of the World record's choices.
#include "core/world_settings.hpp"

namespace stepwise {

const char* toString(IntegratorKind kind) {
    switch (kind) {
        case IntegratorKind::ExplicitEuler: return "Euler";
        case IntegratorKind::SymplecticEuler: return "SymplecticEuler";
        case IntegratorKind::Verlet: return "Verlet";
    }
    return "?";
}

const char* toString(SolverKind kind) {
    switch (kind) {
        case SolverKind::Impulse: return "Impulse";
        case SolverKind::SequentialImpulse: return "SequentialImpulse";
    }
    return "?";
}

const char* toString(NarrowphaseKind kind) {
    switch (kind) {
        case NarrowphaseKind::Auto: return "Auto";
        case NarrowphaseKind::GjkEpa: return "GjkEpa";
        case NarrowphaseKind::Mpr: return "Mpr";
    }
    return "?";
}

const char* toString(CombineRule rule) {
    switch (rule) {
        case CombineRule::Product: return "Product";
        case CombineRule::Min: return "Min";
        case CombineRule::Max: return "Max";
        case CombineRule::Average: return "Average";
        case CombineRule::GeometricMean: return "GeometricMean";
    }
    return "?";
}

const char* toString(ContactOrder order) {
    switch (order) {
        case ContactOrder::Colours: return "Colours";
        case ContactOrder::Found: return "Found";
    }
    return "?";
}

const char* toString(BroadphaseKind kind) {
    switch (kind) {
        case BroadphaseKind::Auto: return "Auto";
        case BroadphaseKind::BruteForce: return "BruteForce";
        case BroadphaseKind::SweepAndPrune: return "SweepAndPrune";
        case BroadphaseKind::AabbTree: return "AabbTree";
        case BroadphaseKind::Grid: return "Grid";
        case BroadphaseKind::Octree: return "Octree";
    }
    return "?";
}

}  // namespace stepwise
