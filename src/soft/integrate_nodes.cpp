/// @file integrate_nodes.cpp
/// @brief Soft step, stage 4: the nodes move, by the scene's integrator.
///
/// A node is a point mass: no orientation, no inertia tensor. So rather than
/// dress each node up as a DynamicObject for src/integrators/, this file
/// applies the same three formulas to the node arrays, with
/// a_i = F_i / m_i + g (gravity added as an acceleration, so that every
/// node falls alike whatever its mass):
///
/// | integrator        | velocity                       | position                 |
/// |-------------------|--------------------------------|--------------------------|
/// | explicit Euler    | v + h·a(t)                     | x + h·v(t) (the old v)   |
/// | symplectic Euler  | v + h·a(t), first              | x + h·v(t + h)           |
/// | velocity Verlet   | v + ½h·a(t), then after the move + ½h·a(t + h) | x + h·v + ½h²·a(t) |
///
/// **Which keeps the angular momentum of a spinning ball.** The springs
/// and the gas give pair-wise central forces and a torque-free pressure
/// (spring_forces.cpp, pressure_forces.cpp), so Σ x_i × F_i = 0 at every
/// instant. Symplectic Euler then keeps L = Σ m_i x_i × v_i exactly (up to
/// rounding): L' = Σ m (x + h v') × v' = Σ m x × v' = L + h Σ x × F = L.
/// Velocity Verlet is a kick, a drift and a kick, each of which keeps it
/// the same way. Explicit Euler moves with the old velocity and gets
/// L' = L + h² Σ v × F: it does not. The same argument with Σ F_i = 0 keeps
/// the total momentum for all three.
#include "soft/soft_stages.hpp"

namespace stepwise {

void integrateNodes(SoftBody& body, IntegratorKind integrator, Real h, const Vec3& gravity) {
    std::vector<Vec3>& x = body.nodePositions;
    std::vector<Vec3>& v = body.nodeVelocities;
    const std::vector<Vec3>& force = body.nodeForces;
    const std::vector<Real>& inverseMass = body.nodeInverseMasses;
    const std::size_t n = x.size();
    switch (integrator) {
        case IntegratorKind::ExplicitEuler:
            for (std::size_t i = 0; i < n; ++i) {
                const Vec3 a = force[i] * inverseMass[i] + gravity;
                x[i] += h * v[i];
                v[i] += h * a;
            }
            break;
        case IntegratorKind::SymplecticEuler:
            for (std::size_t i = 0; i < n; ++i) {
                v[i] += h * (force[i] * inverseMass[i] + gravity);
                x[i] += h * v[i];
            }
            break;
        case IntegratorKind::Verlet: {
            const Real halfStep = Real(0.5) * h;
            for (std::size_t i = 0; i < n; ++i) {
                v[i] += halfStep * (force[i] * inverseMass[i] + gravity);  // half kick with a(t)
                x[i] += h * v[i];                                          // = x + h·v + ½h²·a(t)
            }
            // a(t + h) at the new positions; the dampers read the half-kicked velocities, as for rigid springs
            computeNodeForces(body);
            for (std::size_t i = 0; i < n; ++i) v[i] += halfStep * (force[i] * inverseMass[i] + gravity);
            break;
        }
    }
}

}  // namespace stepwise
