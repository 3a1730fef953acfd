/// @file contact_body.hpp
/// @brief The other body of a contact, whatever its kind, as the impulse formulas see it.
#pragma once

#include "collision/contact.hpp"
#include "objects/body_set.hpp"

namespace stepwise {

/// @brief Body B of a contact: a dynamic body, a kinematic body (infinite
/// mass, prescribed velocity) or a plane (infinite mass, at rest).
///
/// Folding the three kinds into one view lets the impulse stage prepare a
/// contact once: what B's surface does at the point, how it accelerates, and
/// its material. A kinematic body or plane has no `dynamic`, which the
/// impulse formulas read as m⁻¹ = 0 and I⁻¹ = 0.
struct ContactBody {
    DynamicObject* dynamic = nullptr;  ///< The body when it is dynamic, else nullptr.
    Vec3 velocity{0, 0, 0};            ///< Velocity of B's material at the contact point, m/s (for a dynamic B only its centre's: the resolver reads the body itself).
    Vec3 acceleration{0, 0, 0};        ///< Acceleration of B, m/s² (zero unless dynamic).
    Real elasticity = 1;               ///< Restitution factor of B's material.
    Real friction = 1;                 ///< Friction factor of B's material.
    std::uint32_t material = kNoMaterial; ///< B's material index, for a MaterialPair (objects/materials.hpp).
};

/// @brief Looks up body @p ref and describes it at world point @p point.
inline ContactBody contactBody(const BodySet& bodies, const BodyRef& ref, const Vec3& point) {
    ContactBody view;
    switch (ref.kind) {
        case BodyKind::Dynamic: {
            DynamicObject& body = bodies.dynamics[ref.index];
            view.dynamic = &body;
            view.velocity = body.velocity;
            view.acceleration = body.acceleration;
            view.elasticity = body.elasticity;
            view.friction = body.friction;
            view.material = body.material;
            break;
        }
        case BodyKind::Kinematic: {
            const KinematicsObject& body = bodies.kinematics[ref.index];
            // A turning kinematic body's surface moves at v + ω × r.
            view.velocity = body.velocity + glm::cross(body.angularVelocity, point - body.position);
            view.elasticity = body.elasticity;
            view.friction = body.friction;
            view.material = body.material;
            break;
        }
        case BodyKind::Plane: {
            const CollisionPlane& plane = bodies.planes[ref.index];
            view.elasticity = plane.elasticity;
            view.friction = plane.friction;
            view.material = plane.material;
            break;
        }
    }
    return view;
}

}  // namespace stepwise
