/// @file node_collisions.cpp
/// @brief Soft step, stage 5: each node is a small sphere that the rigid objects push out and bounce.
///
/// A node collides as a sphere of radius `nodeRadius` (a fifth of the mean
/// edge, soft_mesh.hpp), tested with the narrowphase's own sphere tests
/// (src/collision/: sphere–plane, sphere–sphere, sphere–box, GJK for
/// capsules, cylinders and hulls; a compound part by part; a triangle mesh
/// by its deepest triangle, node_mesh_contacts.cpp). A node that
/// overlaps an object by the depth d along the object's outward normal n:
///
/// 1. **moves out** by d along n: a position projection, as in
///    position-based dynamics, so no node stays inside a wall. It moves
///    against the force F that pressed it in (springs, gas, weight), which
///    takes the work W = max(0, −F·n)·d that no force paid;
/// 2. if it approaches the object at the contact point, v_n = (v − v_B)·n < 0,
///    gets the **normal impulse** that turns the approach into a separation
///    at v_sep = √((e·|v_n|)² − 2·K·W), or 0: the bounce pays the push out's
///    work back from the approach's kinetic energy ½·v_n²/K (separationPayingFor(),
///    soft_stages.hpp), so that e = 1 gains nothing. e = 0 for an approach
///    slower than gravity builds in two substeps: a resting node, which would
///    otherwise hop for ever. K is the inverse mass of the node and, for a
///    dynamic body, of the body at that point:
///    \f[ j_n = \frac{|v_n| + v_{sep}}{K},\qquad K = \tfrac1{m_i} + \tfrac1{m_B} + (r\times n)\cdot I_B^{-1}(r\times n) ; \f]
/// 3. then the **friction impulse** on what is left sliding (measured after
///    the normal impulse, which can change it when B turns), clamped to
///    Coulomb's cone |j_t| ≤ μ·j_n.
///
/// e and μ mix the soft body's and the object's values by the World's rules
/// (ContactMaterials::mix(), objects/materials.hpp). A dynamic body takes
/// the opposite impulse at the same point (applyImpulseAt()), so the node
/// and the body together keep their momentum and angular momentum; a plane
/// or a kinematic body does not move. The position projection moves the
/// node only: a node is light beside most bodies, and a projection changes
/// no velocity, so momentum is not touched.
///
/// Each node is met alone, in node order: a node pressed between two
/// objects is pushed out of the later one last. A dynamic body that a node
/// touches is noted in SoftBody::touchedDynamics (a moving kinematic one sets
/// SoftBody::carried): the World wakes its island if it slept, and the sleep
/// stage puts it in the soft body's island (src/dynamics/islands.hpp).
#include <algorithm>
#include <cmath>

#include "collision/aabb.hpp"
#include "collision/narrowphase.hpp"
#include "objects/inertia.hpp"
#include "soft/soft_stages.hpp"

namespace stepwise {

namespace {

/// The side a node touches: a dynamic body (which takes the opposite impulse), or something that does not give.
struct Obstacle {
    DynamicObject* dynamic = nullptr;   ///< The body, or nullptr for a plane or a kinematic body.
    std::uint32_t index = 0;            ///< The dynamic body's index in BodySet::dynamics, for the island.
    bool moving = false;                ///< A kinematic body with a velocity or an angular velocity.
    Vec3 velocity{0, 0, 0};             ///< A kinematic body's prescribed v, m/s.
    Vec3 angularVelocity{0, 0, 0};      ///< Its ω, rad/s.
    Vec3 centre{0, 0, 0};               ///< Its centre, m.
    Real friction = 1;                  ///< Its friction factor.
    Real elasticity = 1;                ///< Its restitution factor.
    std::uint32_t material = kNoMaterial;  ///< Its material, for a MaterialPair.

    Vec3 velocityAt(const Vec3& point) const {
        if (dynamic != nullptr) return stepwise::velocityAt(*dynamic, point);
        return velocity + glm::cross(angularVelocity, point - centre);
    }
    /// 1/m + (r × d)·I⁻¹·(r × d) of a dynamic body at @p point along @p d; 0 for one that does not give.
    Real inverseMassAlong(const Vec3& point, const Vec3& d) const {
        if (dynamic == nullptr) return 0;
        const Vec3 rd = glm::cross(point - dynamic->position, d);
        return dynamic->inverseMass +
               glm::dot(rd, worldInverseInertia(dynamic->orientation, dynamic->inverseInertiaBody) * rd);
    }
};

/// Node @p i of @p body touches @p obstacle at @p point, @p depth deep along the obstacle's outward @p normal.
void respond(SoftBody& body, std::size_t i, const Vec3& normal, Real depth, const Vec3& point, const Obstacle& obstacle,
             const ContactCoefficients& mixed, const Vec3& gravity, Real h) {
    Vec3& x = body.nodePositions[i];
    Vec3& v = body.nodeVelocities[i];
    const Real inverseMass = body.nodeInverseMasses[i];
    // 1. Out of the object, against the force pressing the node in: the work that takes, J
    const Vec3 force = body.nodeForces[i] + gravity / inverseMass;  // springs, gas and weight, N
    const Real work = depth > 0 ? std::max(Real(0), -glm::dot(force, normal)) * depth : Real(0);
    if (depth > 0) x += depth * normal;

    const Real approach = -glm::dot(v - obstacle.velocityAt(point), normal);  // −v_n, > 0 when approaching
    if (approach <= 0) return;
    const Real resting = kSoftRestingSteps * std::abs(glm::dot(gravity, normal)) * h;
    const Real e = approach < resting ? Real(0) : mixed.elasticity;

    // 2. The normal impulse, to a separation e·|v_n| less the push's work (a bounce that pays for it)
    const Real inverseMassAlongNormal = inverseMass + obstacle.inverseMassAlong(point, normal);
    const Real separation = separationPayingFor(e * approach, inverseMassAlongNormal, work);
    const Real normalImpulse = (approach + separation) / inverseMassAlongNormal;
    v += normalImpulse * inverseMass * normal;
    if (obstacle.dynamic != nullptr) applyImpulseAt(*obstacle.dynamic, -normalImpulse * normal, point);

    // 3. Friction, on the sliding left after the normal impulse
    const Vec3 relative = v - obstacle.velocityAt(point);
    const Vec3 sliding = relative - glm::dot(relative, normal) * normal;
    const Real slidingSpeed = glm::length(sliding);
    if (slidingSpeed == 0 || mixed.friction == 0) return;
    const Vec3 t = sliding / slidingSpeed;
    const Real stopping = slidingSpeed / (inverseMass + obstacle.inverseMassAlong(point, t));
    const Real frictionImpulse = std::min(stopping, mixed.friction * normalImpulse);
    v -= frictionImpulse * inverseMass * t;
    if (obstacle.dynamic != nullptr) applyImpulseAt(*obstacle.dynamic, frictionImpulse * t, point);
}

/// Every node of @p body within @p bounds against @p shape (one geometry: a part of a compound counts alone).
void collideWithShape(SoftBody& body, const Aabb& nodeBounds, const Geometry& shape, Obstacle& obstacle,
                      const ContactMaterials& materials, const Vec3& gravity, Real h) {
    const PairTest test =  // a mesh: its deepest triangle's overlap only (node_mesh_contacts.cpp)
        shape.type == GeometryType::Mesh ? collideNodeMesh : pairTestFor(GeometryType::Sphere, shape.type);
    if (test == nullptr) return;
    if (shape.type != GeometryType::Plane && !geometryAabb(shape).overlaps(nodeBounds)) return;
    const ContactCoefficients mixed = materials.mix(body.material, body.friction, body.elasticity, obstacle.material,
                                                    obstacle.friction, obstacle.elasticity);
    Geometry node;
    node.type = GeometryType::Sphere;
    node.radius = body.nodeRadius;
    ContactManifold manifold;
    for (std::size_t i = 0; i < body.nodeCount(); ++i) {
        node.centre = body.nodePositions[i];
        manifold.pointCount = 0;
        if (!test(node, shape, manifold) || manifold.pointCount == 0) continue;
        // The deepest point; the manifold's normal runs from the node into the object
        const ContactPoint* deepest = &manifold.points[0];
        for (int k = 1; k < manifold.pointCount; ++k) {
            if (manifold.points[k].depth > deepest->depth) deepest = &manifold.points[k];
        }
        respond(body, i, -manifold.normal, deepest->depth, deepest->position, obstacle, mixed, gravity, h);
        if (obstacle.dynamic != nullptr) noteTouched(body.touchedDynamics, obstacle.index);
        body.carried = body.carried || obstacle.moving;
    }
}

/// Every node against @p object, part by part when it is a compound.
template <class Object>
void collideWithObject(SoftBody& body, const Aabb& nodeBounds, const Object& object, const Geometry& whole,
                       Obstacle& obstacle, const ContactMaterials& materials, const Vec3& gravity, Real h) {
    if (object.shape != Shape::Compound) {
        collideWithShape(body, nodeBounds, whole, obstacle, materials, gravity, h);
        return;
    }
    for (std::size_t p = 0; p < object.compound->parts.size(); ++p) {
        const Geometry part = geometryOfPart(whole, object.compound->parts[p], static_cast<std::uint32_t>(p));
        collideWithShape(body, nodeBounds, part, obstacle, materials, gravity, h);
    }
}

}  // namespace

void collideNodes(SoftBody& body, const BodySet& rigid, const Vec3& gravity, Real h) {
    if (body.nodeCount() == 0) return;
    const ContactMaterials byProduct;
    const ContactMaterials& materials = rigid.materials != nullptr ? *rigid.materials : byProduct;
    Aabb nodeBounds{body.nodePositions[0], body.nodePositions[0]};
    for (const Vec3& x : body.nodePositions) nodeBounds = {glm::min(nodeBounds.min, x), glm::max(nodeBounds.max, x)};
    nodeBounds.min -= Vec3(body.nodeRadius);
    nodeBounds.max += Vec3(body.nodeRadius);

    for (const CollisionPlane& plane : rigid.planes) {
        Obstacle obstacle;
        obstacle.friction = plane.friction;
        obstacle.elasticity = plane.elasticity;
        obstacle.material = plane.material;
        collideWithShape(body, nodeBounds, geometryOf(plane), obstacle, materials, gravity, h);
    }
    for (const KinematicsObject& mover : rigid.kinematics) {
        Obstacle obstacle;
        obstacle.velocity = mover.velocity;
        obstacle.angularVelocity = mover.angularVelocity;
        obstacle.centre = mover.position;
        obstacle.moving = mover.velocity != Vec3(0) || mover.angularVelocity != Vec3(0);
        obstacle.friction = mover.friction;
        obstacle.elasticity = mover.elasticity;
        obstacle.material = mover.material;
        collideWithObject(body, nodeBounds, mover, geometryOf(mover), obstacle, materials, gravity, h);
    }
    for (DynamicObject& other : rigid.dynamics) {
        Obstacle obstacle;
        obstacle.dynamic = &other;
        obstacle.index = static_cast<std::uint32_t>(&other - rigid.dynamics.data());
        obstacle.friction = other.friction;
        obstacle.elasticity = other.elasticity;
        obstacle.material = other.material;
        collideWithObject(body, nodeBounds, other, geometryOf(other), obstacle, materials, gravity, h);
    }
}

}  // namespace stepwise
