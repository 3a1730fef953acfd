/// @file soft_stages.hpp
/// @brief The stages of a soft body's step, one file each; soft_step.cpp calls them in order.
///
/// | stage | file | reads | writes |
/// |---|---|---|---|
/// | spring forces | `spring_forces.cpp` | node positions, velocities, springs | node forces |
/// | enclosed volume | `enclosed_volume.cpp` | node positions, faces | V |
/// | pressure forces | `pressure_forces.cpp` | node positions, faces, nRT, V | P, node forces |
/// | integrate | `integrate_nodes.cpp` | forces, gravity, h | node positions, velocities |
/// | collide | `node_collisions.cpp` | nodes, the rigid objects, materials | node positions, velocities; a dynamic body's v and L |
/// | … with a mesh | `node_mesh_contacts.cpp` | a node, a triangle mesh and its hierarchy | the node's deepest contact |
/// | soft contacts | `soft_contacts.cpp` | every soft body's nodes and faces | node positions, velocities |
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "collision/narrowphase.hpp"
#include "core/types.hpp"
#include "core/world_settings.hpp"
#include "objects/body_set.hpp"
#include "objects/soft_body.hpp"

namespace stepwise {

/// @brief A node approaching slower than gravity builds along the normal in this many substeps is
/// resting, not striking: it gets no bounce (as kRestingContactSteps for rigid contacts), or it
/// would hop for ever.
inline constexpr Real kSoftRestingSteps = Real(2);

/// @brief The speed a contact separates at after a bounce that pays for its push out, m/s.
///
/// A node moved out of an object by the position projection moves against
/// the force F that pressed it in (springs, gas, weight): that takes the work
/// W = max(0, −F·n)·d, J, which no force paid, and the gas's and the springs'
/// energy rise by it. The bounce pays it back from the kinetic energy of the
/// approach, ½·v_n²/K for a pair of inverse mass K along n:
/// \f[ v_{sep} = \sqrt{\max\left(0,\ (e\,|v_n|)^2 - 2KW\right)} \f]
/// so that a contact with e = 1 gives back no more energy than it took
/// (docs/soft-bodies.md, "The push out is paid for").
/// @param bounce       e·|v_n|, the separation speed of a bounce with nothing to pay, m/s
/// @param inverseMass  K, 1/kg
/// @param work         W ≥ 0, J
inline Real separationPayingFor(Real bounce, Real inverseMass, Real work) {
    const Real paid = bounce * bounce - 2 * inverseMass * work;
    return paid > 0 ? std::sqrt(paid) : Real(0);
}

/// @brief Adds @p index to @p touched unless it is there: the bodies a soft body touched this step,
/// each once (a linear search: a soft body touches few bodies in a step).
inline void noteTouched(std::vector<std::uint32_t>& touched, std::uint32_t index) {
    for (const std::uint32_t seen : touched) {
        if (seen == index) return;
    }
    touched.push_back(index);
}

/// @brief Sets every node's force to zero: the start of a force evaluation.
void clearNodeForces(SoftBody& body);

/// @brief Adds each spring's Hooke and damper force to its two nodes (spring_forces.cpp):
/// \f$ F_a = (k(l - L_0) + c\,\dot l)\,\hat d,\ F_b = -F_a \f$.
void addSpringForces(SoftBody& body);

/// @brief The volume the closed surface @p faces over @p positions encloses, m³, by the
/// divergence theorem: \f$ V = \tfrac16 \sum_f a_f\cdot(b_f \times c_f) \f$ (enclosed_volume.cpp).
/// Positive for an outward winding.
Real enclosedVolume(std::span<const Vec3> positions, std::span<const SoftFace> faces);

/// @brief Measures the volume, sets P = nRT / V, and adds the gas's push P·A·n on every face,
/// a third to each of its corners (pressure_forces.cpp). Writes body.volume and body.pressure.
void addPressureForces(SoftBody& body);

/// @brief Clears the forces, then adds the springs' and the gas's: every force on the nodes but gravity.
void computeNodeForces(SoftBody& body);

/// @brief Advances every node by @p h with @p integrator, the scene's `Integrator` (integrate_nodes.cpp):
/// the point-mass forms of src/integrators/ with a = F·(1/m) + g. Velocity Verlet works the
/// forces out again at the new positions (computeNodeForces()).
void integrateNodes(SoftBody& body, IntegratorKind integrator, Real h, const Vec3& gravity);

/// @brief Pushes every node out of the planes, kinematic and dynamic bodies of @p rigid, and turns its
/// approach into a bounce with restitution and Coulomb friction (node_collisions.cpp). A dynamic
/// body gets the opposite impulse at the same point, and is noted in body.touchedDynamics; a
/// moving kinematic body sets body.carried.
/// @param rigid   the World's rigid objects; the dynamic ones' velocity and angular momentum change
/// @param gravity the World's, m/s²: a node approaching slower than gravity builds in two steps is resting
/// @param h       the step the nodes were just moved by, s
void collideNodes(SoftBody& body, const BodySet& rigid, const Vec3& gravity, Real h);

/// @brief Node @p node (a sphere) against the triangle mesh @p mesh: the deepest overlap of all its
/// triangles near the node, found through the mesh's hierarchy by the rigid bodies' sphere–mesh test
/// (meshContacts(), within no gap), as a one-point manifold whose normal runs from the node into the
/// mesh (node_mesh_contacts.cpp). A PairTest, so collideNodes() treats a mesh as any other shape.
/// @return true when the node overlaps (or just touches) a triangle from its front
bool collideNodeMesh(const Geometry& node, const Geometry& mesh, ContactManifold& out);

/// @brief Every node of each soft body against the triangles of every other one it may touch, with the
/// same projection, bounce and friction as collideNodes(), the impulses shared by the triangle's
/// corners (soft_contacts.cpp). A body does not collide with itself, nor with an asleep one (the
/// World wakes a sleeper that an awake body may reach, first); each notes the other in touchedSoftBodies.
void collideSoftBodies(std::span<SoftBody> bodies, const ContactMaterials& materials, const Vec3& gravity, Real h);

/// @brief Sets body.position and body.velocity to the nodes' centre of mass and its velocity.
void measureCentreOfMass(SoftBody& body);

}  // namespace stepwise
