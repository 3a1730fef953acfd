/// @file soft_body.hpp
/// @brief A pressure soft body: point masses on a closed surface, springs along its edges, gas inside.
///
/// The fourth kind of object, beside DynamicObject (objects/game_object.hpp).
/// Where a rigid body is six numbers of pose and six of motion, a soft body
/// is a closed triangle mesh whose every vertex (a *node*) is a point mass
/// with its own position and velocity. Springs along the mesh edges keep
/// the surface together; the gas inside keeps it inflated, by the ideal-gas
/// law P·V = nRT (Matyka & Ollila, "Pressure model of soft body
/// simulation", 2003). The stages that move it are in src/soft/, the maths
/// in docs/soft-bodies.md.
///
/// Like the other objects it is plain data with no virtual functions, and
/// the World keeps its soft bodies in one contiguous vector. The node state
/// is a structure of arrays (positions, velocities, forces, inverse masses:
/// one vector each, indexed by node), because every stage of the soft step
/// is a loop over one or two of them.
#pragma once

#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "objects/game_object.hpp"

namespace stepwise {

/// @brief A spring between two nodes of a soft body: Hooke's law plus a damper along the line.
struct SoftSpring {
    std::uint32_t a = 0;   ///< First node.
    std::uint32_t b = 0;   ///< Second node.
    Real restLength = 0;   ///< L₀, m: the length at which it pulls on nothing (the starting length).
    Real stiffness = 0;    ///< k, N/m.
    Real damping = 0;      ///< c, N·s/m, against the rate at which the nodes separate.
};

/// @brief One triangle of a soft body's surface: three node indices, counter-clockwise seen from outside.
///
/// With that winding (b − a) × (c − a) points out of the body and has
/// twice the triangle's area as its length: the pressure pushes along it,
/// and the divergence theorem adds up the volume from it.
struct SoftFace {
    std::uint32_t a = 0;  ///< First corner.
    std::uint32_t b = 0;  ///< Second corner.
    std::uint32_t c = 0;  ///< Third corner.
};

/// @brief A closed surface of point masses and springs, inflated by an ideal gas.
///
/// GameObject::position is the centre of mass of the nodes (kept current
/// by the soft step), `velocity` its velocity; the orientation stays the
/// identity (a soft body has no single rotation). `nRT` is the gas's
/// n·R·T in joules (equivalently P·V, N/m² × m³ = J): the pressure is
/// P = nRT / V with V the volume the surface encloses now, so a ball
/// squeezed to half its volume pushes back with twice the pressure.
class SoftBody : public GameObject {
public:
    // Node state, one entry per node (structure of arrays: each stage loops over one or two of them).
    std::vector<Vec3> nodePositions;      ///< x_i, m, world frame.
    std::vector<Vec3> nodeVelocities;     ///< v_i, m/s.
    std::vector<Vec3> nodeForces;         ///< F_i, N: springs and gas this substep (gravity is added as g, not m·g).
    std::vector<Real> nodeInverseMasses;  ///< 1/m_i, 1/kg (the mass is spread evenly: every node has m/N).

    std::vector<SoftSpring> springs;  ///< The edge springs first, then the bending springs (edgeSprings says where).
    std::vector<SoftFace> faces;      ///< The closed surface, wound outward.
    std::uint32_t edgeSprings = 0;    ///< How many of `springs` run along mesh edges; the rest are bending springs.

    Shape shape = Shape::Sphere;  ///< What the mesh was made from: Sphere (an icosphere) or Box (a subdivided cube).
    int resolution = 0;           ///< Icosphere subdivisions, or cells along each edge of the cube.
    Real mass = 1;                ///< Total mass, kg (the nodes' masses add up to it).
    Real nRT = 0;                 ///< n·R·T of the gas inside, J (= P·V); 0: no gas, the springs alone.
    Real nodeRadius = 0;          ///< Radius of the small sphere each node collides as, m (soft_mesh.hpp).
    Real elasticity = Real(0.5);  ///< Coefficient of restitution of a node's contacts, 0–1.
    Real friction = Real(0.5);    ///< Coulomb friction coefficient of a node's contacts, ≥ 0.
    std::uint32_t material = kNoMaterial;  ///< Its material's index, or kNoMaterial (as DynamicObject::material).

    // Measured by the soft step, for output and for a debugger.
    Vec3 velocity{0, 0, 0};  ///< Velocity of the centre of mass, m/s.
    Real volume = 0;         ///< V, m³: the volume the surface encloses (divergence theorem).
    Real pressure = 0;       ///< P = nRT / V, Pa.

    // Islands and sleep (src/dynamics/islands.hpp): the body is one unit of an island, as a DynamicObject is.
    bool asleep = false;            ///< Sleeping: its nodes are not moved, until something wakes its island.
    Real stillTime = 0;             ///< How long every node has been slower than the World's SleepLinearSpeed, s.
    std::uint32_t sleepIsland = 0;  ///< Island it fell asleep with (the bodies of one island wake together).
    /// Indices into the World's dynamic bodies of those its nodes touched in this step, each once
    /// (node_collisions.cpp): they are in its island. Cleared each step; the capacity stays.
    std::vector<std::uint32_t> touchedDynamics;
    /// Indices into the World's soft bodies of those it touched in this step, each once (soft_contacts.cpp).
    std::vector<std::uint32_t> touchedSoftBodies;
    bool carried = false;  ///< A node touched a moving kinematic body in this step: not still, as a carried rigid body.

    /// @brief Number of nodes.
    std::size_t nodeCount() const { return nodePositions.size(); }
};

}  // namespace stepwise
