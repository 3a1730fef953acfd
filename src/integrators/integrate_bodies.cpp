/// @file integrate_bodies.cpp
/// @brief The integrate stage: the scene's integrator, picked by name.
#include "integrators/integrators.hpp"

namespace stepwise {

void integrateBodies(IntegratorKind integrator, std::span<DynamicObject> bodies, Real h,
                     const AccelerationFunction& forces) {
    switch (integrator) {
        case IntegratorKind::ExplicitEuler: integrateExplicitEuler(bodies, h); return;
        case IntegratorKind::SymplecticEuler: integrateSymplecticEuler(bodies, h); return;
        case IntegratorKind::Verlet: integrateVerlet(bodies, h, forces); return;
    }
}

}  // namespace stepwise
