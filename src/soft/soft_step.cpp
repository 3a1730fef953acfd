/// @file soft_step.cpp
/// @brief The soft step, read top to bottom: forces, volume, pressure, move, collide.
///
/// A pressure soft body (Matyka & Ollila 2003; docs/soft-bodies.md) is a
/// closed surface of point masses. In each substep of length h_s:
///
///     1. springs    F_i  = Σ Hooke + damper along each spring          spring_forces.cpp
///     2. volume     V    = (1/6) Σ_faces a·(b × c)                     enclosed_volume.cpp
///     3. pressure   P    = nRT / V,  F_i += Σ_faces round i (P·A·n)/3   pressure_forces.cpp
///     4. integrate  v, x by the scene's integrator, a_i = F_i/m_i + g  integrate_nodes.cpp
///     5. collide    each node a small sphere against the rigid objects node_collisions.cpp
///     6. soft–soft  each node against the other soft bodies' faces     soft_contacts.cpp
///
/// then the centre of mass and its velocity, for output. After every
/// stage the nodes it moved are checked: the first non-finite number stops
/// the run naming the body, the stage and the step, as World::checkFinite()
/// does for rigid bodies. One call is one soft substep: the World calls it
/// at the start of each of its rigid substeps (h_s = h/Substeps under the
/// sequential impulse; stage 5a of World::stepWithSequentialImpulses()),
/// and once a step, for h, under Impulse. Springs on light nodes are stiff,
/// and the explicit stability limit h·ω < 2 (soft_stability.hpp) is met by
/// the short substep.
///
/// An asleep body (src/dynamics/islands.hpp) is not stepped at all: its nodes
/// stay where they are, as an asleep rigid body is not integrated. An awake
/// one starts the step with empty lists of the bodies it touched; the
/// collisions fill them, and the sleep stage reads them as the island's edges.
#include "soft/soft_step.hpp"

#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "soft/soft_stages.hpp"

namespace stepwise {

namespace {

/// Stops the run naming @p body, the soft stage @p after and the step, when a node's state is not finite.
void requireFiniteNodes(const SoftBody& body, const char* after, const StageAtStep& where) {
    Real probe = 0;  // zero exactly when every number is finite (zeroIfFinite(), core/types.hpp)
    for (std::size_t i = 0; i < body.nodeCount(); ++i) {
        probe += zeroIfFinite(body.nodePositions[i]) + zeroIfFinite(body.nodeVelocities[i]);
    }
    if (probe == 0) return;
    for (std::size_t i = 0; i < body.nodeCount(); ++i) {
        const char* quantity = !isFinite(body.nodePositions[i])    ? "position"
                               : !isFinite(body.nodeVelocities[i]) ? "velocity"
                                                                    : nullptr;
        if (quantity == nullptr) continue;
        throw SimulationError(body.name, stageName(where.stage), where.step, where.time,
                              std::string("non-finite ") + quantity + " of node " + std::to_string(i) + " after the " +
                                  after + " (a stiffness past the stability limit? docs/soft-bodies.md)");
    }
}

/// A gas needs a volume to push: a surface turned inside out (V ≤ 0) has none, and P = nRT/V would
/// pull it further in. Stop there, naming the body.
void requirePositiveVolume(const SoftBody& body, const StageAtStep& where) {
    if (body.nRT == 0 || (body.volume > 0 && std::isfinite(body.pressure))) return;
    throw SimulationError(body.name, stageName(where.stage), where.step, where.time,
                          "the surface turned inside out in the pressure forces: enclosed volume " +
                              std::to_string(double(body.volume)) +
                              " m^3, so P = nRT/V has no pressure to give (docs/soft-bodies.md, stability)");
}

}  // namespace

void measureCentreOfMass(SoftBody& body) {
    Vec3 momentum(0), moment(0);
    Real mass = 0;
    for (std::size_t i = 0; i < body.nodeCount(); ++i) {
        const Real m = Real(1) / body.nodeInverseMasses[i];
        mass += m;
        moment += m * body.nodePositions[i];
        momentum += m * body.nodeVelocities[i];
    }
    if (mass == 0) return;
    body.position = moment / mass;
    body.velocity = momentum / mass;
}

void computeNodeForces(SoftBody& body) {
    clearNodeForces(body);
    addSpringForces(body);
    addPressureForces(body);
}

void measureSoftBody(SoftBody& body) {
    body.volume = enclosedVolume(body.nodePositions, body.faces);
    body.pressure = body.nRT == 0 ? Real(0) : body.nRT / body.volume;
    measureCentreOfMass(body);
}

void stepSoftBodies(std::span<SoftBody> bodies, const BodySet& rigid, const SoftStepSettings& settings) {
    const Real hs = settings.timeStep;
    const StageAtStep& where = settings.where;
    const ContactMaterials byProduct{};
    const ContactMaterials& materials = rigid.materials != nullptr ? *rigid.materials : byProduct;
    for (SoftBody& body : bodies) {
        if (!settings.startsStep) break;  // a later substep of the World's step adds to the step's lists
        body.touchedDynamics.clear();  // keeps the capacity: no allocation once warm
        body.touchedSoftBodies.clear();
        body.carried = false;
    }
    for (SoftBody& body : bodies) {
        if (body.asleep) continue;  // not moved while asleep, as a sleeping rigid body is not integrated
        // 1–3. Springs, then the volume and the gas's push (spring_forces.cpp, enclosed_volume.cpp,
        //      pressure_forces.cpp)
        clearNodeForces(body);
        addSpringForces(body);
        addPressureForces(body);
        requirePositiveVolume(body, where);

        // 4. Move the nodes (integrate_nodes.cpp; Verlet works 1–3 out again at the new positions)
        integrateNodes(body, settings.integrator, hs, settings.gravity);
        requireFiniteNodes(body, "integration of the nodes", where);

        // 5. Out of the rigid objects, with a bounce and friction (node_collisions.cpp)
        collideNodes(body, rigid, settings.gravity, hs);
        requireFiniteNodes(body, "node collisions", where);
    }
    // 6. Soft bodies against each other, once all have moved (soft_contacts.cpp)
    if (bodies.size() > 1) {
        collideSoftBodies(bodies, materials, settings.gravity, hs);
        for (const SoftBody& body : bodies) requireFiniteNodes(body, "soft-soft contacts", where);
    }
    for (SoftBody& body : bodies) {
        if (!body.asleep) measureCentreOfMass(body);
    }
}

}  // namespace stepwise
