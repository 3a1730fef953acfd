/// @file game_object.cpp
/// @brief Names of the enumerations used by the object model.
#include "objects/game_object.hpp"

#include "world/world_settings.hpp"

namespace stepwise {

const char* toString(Shape shape) {
    switch (shape) {
        case Shape::Sphere: return "Sphere";
        case Shape::Box: return "Box";
    }
    return "?";
}

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

}  // namespace stepwise
