/// @file soft_contacts.cpp
/// @brief Soft step, stage 6: soft bodies against each other, each node against the other body's triangles.
///
/// A node of body A collides with a triangle (a, b, c) of another body B
/// as a sphere of radius r_A against the triangle thickened by B's node
/// radius r_B: with q the triangle's closest point to the node x
/// (closestPointOnTriangle(), Ericson §5.1.5) and weights w_a, w_b, w_c
/// (q = w_a·a + w_b·b + w_c·c), they touch when |x − q| < r_A + r_B, along
/// n = (x − q)/|x − q| (the face's outward normal when x has crossed it).
/// The contact point of B moves with v_q = Σ w_k·v_k, and a push j·n on it
/// shares out to the three corners as w_k·j·n, so its inverse mass along n is
/// \f[ K = \frac1{m_x} + \sum_k \frac{w_k^2}{m_k} \f]
/// (the same as for a point of a rigid bar held at its ends). Then, as for a
/// node on a rigid object (node_collisions.cpp): the overlap d is removed,
/// the node moved by d·(1/m_x)/K and the corners by −d·(w_k/m_k)/K (a split
/// that keeps the centre of mass where it was); an approach v_n < 0 becomes
/// a separation e·|v_n|, less what pays for the work of that push against the
/// forces on the node and the corners (separationPayingFor(), soft_stages.hpp),
/// by the impulse j = (|v_n| + v_sep) / K; friction, clamped to μ·j,
/// stops the sliding by the same rule along the tangent. Every impulse acts
/// on the node and, opposite, on the corners: the total momentum is kept.
///
/// Each pair of bodies is met both ways (A's nodes on B's faces, B's nodes on
/// A's), so neither body's mesh needs to be finer than the other's. Nothing
/// stops a node that has gone further in than r_A + r_B: it is not found
/// again (a thin-shell contact), and a body does not collide with itself.
/// The cost is nodes × faces per pair whose boxes overlap. Two bodies that
/// touch note each other in SoftBody::touchedSoftBodies, which makes them one
/// island (src/dynamics/islands.hpp); a pair with a sleeper in it is not met
/// (the World has woken every sleeper an awake body could reach this step).
#include <algorithm>
#include <cmath>

#include "collision/aabb.hpp"
#include "collision/closest_points.hpp"
#include "soft/soft_stages.hpp"

namespace stepwise {

namespace {

Aabb boundsOf(const SoftBody& body) {
    Aabb box{body.nodePositions[0], body.nodePositions[0]};
    for (const Vec3& x : body.nodePositions) box = {glm::min(box.min, x), glm::max(box.max, x)};
    box.min -= Vec3(body.nodeRadius);
    box.max += Vec3(body.nodeRadius);
    return box;
}

/// The nodes of @p a against the faces of @p b; true when some node touched.
bool collideNodesWithFaces(SoftBody& a, SoftBody& b, const ContactMaterials& materials, const Vec3& gravity, Real h) {
    bool touched = false;
    const Real reach = a.nodeRadius + b.nodeRadius;
    Aabb faceBounds = boundsOf(b);
    faceBounds.min -= Vec3(a.nodeRadius);
    faceBounds.max += Vec3(a.nodeRadius);
    const ContactCoefficients mixed = materials.mix(a.material, a.friction, a.elasticity, b.material, b.friction, b.elasticity);
    for (std::size_t i = 0; i < a.nodeCount(); ++i) {
        const Vec3 x0 = a.nodePositions[i];
        if (!faceBounds.overlaps({x0, x0})) continue;
        for (const SoftFace& f : b.faces) {
            const std::uint32_t corner[3] = {f.a, f.b, f.c};
            const Vec3& pa = b.nodePositions[f.a];
            const Vec3& pb = b.nodePositions[f.b];
            const Vec3& pc = b.nodePositions[f.c];
            const Vec3 centroid = (pa + pb + pc) / Real(3);
            const Real spread = std::max({glm::length(pa - centroid), glm::length(pb - centroid), glm::length(pc - centroid)});
            const Vec3& x = a.nodePositions[i];
            if (glm::length(x - centroid) > spread + reach) continue;  // too far from every point of the face
            const TriangleClosestPoint closest = closestPointOnTriangle(x, pa, pb, pc);
            const Vec3 apart = x - closest.point;
            const Real distance = glm::length(apart);
            if (distance >= reach) continue;
            const Vec3 across = glm::cross(pb - pa, pc - pa);
            const Real area2 = glm::length(across);
            if (area2 == 0) continue;
            touched = true;
            const Vec3 faceNormal = across / area2;  // out of b
            const bool crossed = glm::dot(apart, faceNormal) < 0 || distance == 0;
            const Vec3 n = crossed ? faceNormal : apart / distance;
            const Real depth = crossed ? reach + distance : reach - distance;

            const Real nodeInverse = a.nodeInverseMasses[i];
            Real inverseMass = nodeInverse;  // K along any direction: the corners' share is the same for all
            for (int k = 0; k < 3; ++k) {
                inverseMass += closest.weights[k] * closest.weights[k] * b.nodeInverseMasses[corner[k]];
            }
            // The overlap removed, split so that the centre of mass stays where it is; the work that
            // takes against the forces pressing the node and the corners together, J (separationPayingFor())
            const Vec3 nodeMove = depth * nodeInverse / inverseMass * n;
            Real work = -glm::dot(a.nodeForces[i] + gravity / nodeInverse, nodeMove);
            a.nodePositions[i] += nodeMove;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t c = corner[k];
                const Vec3 cornerMove = -depth * closest.weights[k] * b.nodeInverseMasses[c] / inverseMass * n;
                work -= glm::dot(b.nodeForces[c] + gravity / b.nodeInverseMasses[c], cornerMove);
                b.nodePositions[c] += cornerMove;
            }
            const auto relativeVelocity = [&] {
                Vec3 v = a.nodeVelocities[i];
                for (int k = 0; k < 3; ++k) v -= closest.weights[k] * b.nodeVelocities[corner[k]];
                return v;
            };
            const auto push = [&](const Vec3& impulse) {
                a.nodeVelocities[i] += impulse * nodeInverse;
                for (int k = 0; k < 3; ++k) {
                    b.nodeVelocities[corner[k]] -= closest.weights[k] * b.nodeInverseMasses[corner[k]] * impulse;
                }
            };
            const Real approach = -glm::dot(relativeVelocity(), n);
            if (approach <= 0) continue;
            const Real e = approach < kSoftRestingSteps * std::abs(glm::dot(gravity, n)) * h ? Real(0) : mixed.elasticity;
            const Real separation = separationPayingFor(e * approach, inverseMass, std::max(Real(0), work));
            const Real normalImpulse = (approach + separation) / inverseMass;
            push(normalImpulse * n);
            const Vec3 relative = relativeVelocity();
            const Vec3 sliding = relative - glm::dot(relative, n) * n;
            const Real slidingSpeed = glm::length(sliding);
            if (slidingSpeed == 0 || mixed.friction == 0) continue;
            const Real frictionImpulse = std::min(slidingSpeed / inverseMass, mixed.friction * normalImpulse);
            push(-frictionImpulse / slidingSpeed * sliding);
        }
    }
    return touched;
}

}  // namespace

void collideSoftBodies(std::span<SoftBody> bodies, const ContactMaterials& materials, const Vec3& gravity, Real h) {
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        for (std::size_t j = i + 1; j < bodies.size(); ++j) {
            SoftBody& a = bodies[i];
            SoftBody& b = bodies[j];
            if (a.asleep || b.asleep) continue;  // a sleeper an awake body may reach was woken first (World::stepSoftBodies())
            if (a.nodeCount() == 0 || b.nodeCount() == 0 || !boundsOf(a).overlaps(boundsOf(b))) continue;
            const bool aOnB = collideNodesWithFaces(a, b, materials, gravity, h);
            const bool bOnA = collideNodesWithFaces(b, a, materials, gravity, h);
            if (aOnB || bOnA) {  // one island (src/dynamics/islands.hpp)
                noteTouched(a.touchedSoftBodies, static_cast<std::uint32_t>(j));
                noteTouched(b.touchedSoftBodies, static_cast<std::uint32_t>(i));
            }
        }
    }
}

}  // namespace stepwise
