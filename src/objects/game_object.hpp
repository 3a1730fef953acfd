/// @file game_object.hpp
/// @brief The object model students recognise: GameObject and its three kinds.
///
/// The hierarchy follows the classic games-physics assignment:
///
///     GameObject                  name, position, orientation, scale, colour
///     ├── DynamicObject           simulated: has mass, is pushed by gravity and contacts
///     ├── KinematicsObject        moves with a prescribed velocity, pushes, is never pushed
///     └── CollisionPlane          an infinite plane: a point and a unit normal
///
/// The classes hold plain data and have no virtual functions. The World keeps
/// one contiguous `std::vector` per concrete class, so each stage of the step
/// loops over an array of one type: the hierarchy is the model you read, not a
/// virtual call per body or per pair. Nothing here knows about rendering.
#pragma once

#include <cstdint>
#include <string>

#include "core/types.hpp"
#include "objects/shapes.hpp"

namespace stepwise {

/// @brief An object's `material` when it names none (every object of a scene without materials).
inline constexpr std::uint32_t kNoMaterial = 0xFFFFFFFFu;

/// @brief Display colour, each channel from 0 to 1. Used only by viewers.
struct Color {
    float r = 0.8f;  ///< Red, 0–1.
    float g = 0.8f;  ///< Green, 0–1.
    float b = 0.8f;  ///< Blue, 0–1.
};

/// @brief What every object in a scene has: a name, a pose, a size and a colour.
class GameObject {
public:
    // What a step reads at most once comes first, the pose last, so that in a
    // DynamicObject the pose runs straight on into the motion that every
    // substep reads with it (the fields' order is their order in memory).
    std::string name;            ///< Unique within a scene; used in output and errors.
    Vec3 scale{1, 1, 1};         ///< Full size, m: a box's edge lengths; a sphere's diameter when no radius is given.
    Color color;                 ///< Display colour.
    /// How far the object can move during the current step, m, by itself or knocked by a
    /// neighbour (World::widenSweepsByKnocks(); sequential-impulse step only, 0 otherwise).
    /// Its bounds grow by this much and a sphere's contacts reach this far, so a contact is found *before* the
    /// surfaces meet and the solver can stop them exactly at touching. A
    /// plane does not move: its sweep is how far a knock from another body may
    /// carry a body towards it, the largest sweep in the scene (World::measureSweeps()).
    Real sweep = 0;
    Vec3 position{0, 0, 0};      ///< Centre of the object in world space, m.
    Quat orientation{1, 0, 0, 0};///< Rotation from body to world space (unit quaternion, w first).
};

/// @brief A simulated rigid body: gravity and contacts change its motion.
///
/// The body's state is (position, orientation, velocity, angular momentum);
/// the angular velocity ω = I_world⁻¹·L is kept alongside, derived from it
/// (src/objects/inertia.hpp). Storing L rather than ω is what makes a
/// torque-free body keep its angular momentum exactly while it tumbles.
/// Its per-object `constantAcceleration` (m/s², from the scene's
/// Acceleration fields) is added to the World's gravity every step;
/// `acceleration` is the total computed for the current step by the
/// apply-forces stage, kept on the body so the integrators and a debugger
/// can see it.
class DynamicObject : public GameObject {
public:
    // The state every substep reads and writes comes first, straight after
    // the pose that ends the base class: from position to canTurn is one run
    // of 212 bytes, four cache lines of the body, which is all that a
    // pass over the bodies (integrate, the drift, the solver's copies) reads.
    // With the name, size and colour between pose and motion it would be five
    // or six lines, and at 64k bodies such a pass reads tens of megabytes. The
    // order of fields is their order in memory; it changes nothing else.
    Vec3 velocity{0, 0, 0};          ///< Linear velocity of the centre of mass, m/s.
    Vec3 angularVelocity{0, 0, 0};   ///< Angular velocity in world space, rad/s.
    Vec3 angularMomentum{0, 0, 0};   ///< L = I_world·ω about the centre of mass, world frame, kg·m²/s: the rotational state.
    Vec3 acceleration{0, 0, 0};      ///< Total acceleration this step, m/s² (written by apply-forces).
    Vec3 torque{0, 0, 0};            ///< Total torque about the centre of mass this step, world frame, N·m.
    Vec3 inverseInertiaBody{1, 1, 1};///< Reciprocals of the principal moments, 1/(kg·m²).
    Real inverseMass = Real(1);      ///< 1/mass, 1/kg; what the impulse formulas use.
    Shape shape = Shape::Sphere;     ///< Collision shape.
    bool asleep = false;             ///< Sleeping: not integrated, not solved, until something wakes its island.
    /// false when the World's step plan found that nothing in the scene can
    /// turn this body (src/world/step_plan.hpp): the integrators then skip its
    /// angular update while its L and τ are exactly zero (skipsRotation()).
    bool canTurn = true;

    // Read once a step or less.
    Real radius = Real(0.5);         ///< Sphere, Capsule, Cylinder radius, m (unused by boxes).
    Real height = 0;                 ///< Capsule: length of its segment; Cylinder: full length, m (along body y).
    std::shared_ptr<const ConvexHull> hull;         ///< Shape=Hull: its polyhedron (shapes.hpp).
    std::shared_ptr<const CompoundShape> compound;  ///< Shape=Compound: its parts (shapes.hpp).
    Real mass = Real(1);             ///< Mass, kg; always > 0.
    Vec3 constantAcceleration{0, 0, 0}; ///< The scene's per-object acceleration, m/s² (added to gravity).
    Real elasticity = Real(0.5);     ///< Coefficient of restitution, 0–1.
    Real friction = Real(0.5);       ///< Coulomb friction coefficient, ≥ 0.
    bool hollow = false;             ///< Sphere only: a thin shell (I = ⅔·m·r²) instead of a solid ball (⅖·m·r²).
    /// Index of its material in the scene's list (objects/materials.hpp), or kNoMaterial. Only a
    /// MaterialPair reads it: `elasticity` and `friction` already hold the material's values.
    std::uint32_t material = kNoMaterial;
    Vec3 inertiaBody{1, 1, 1};       ///< Principal moments of inertia about the centre of mass, body axes, kg·m².
    Real stillTime = 0;              ///< How long the body has been below the sleep speeds, s.
    std::uint32_t sleepIsland = 0;   ///< Island it fell asleep with (bodies of one island wake together).

    /// @brief Sets `mass` and keeps `inverseMass` consistent with it.
    /// @param kilograms mass in kg; the scene loader has checked it is > 0.
    void setMass(Real kilograms) {
        mass = kilograms;
        inverseMass = Real(1) / kilograms;
    }

    /// @brief Half the box's edge lengths, m (the box extends ±halfExtents in body space).
    Vec3 halfExtents() const { return scale * Real(0.5); }
};

/// @brief A body whose motion is prescribed: it moves with constant velocity
/// and angular velocity, pushes dynamic bodies and is never pushed back.
///
/// In the impulse formulas it behaves as if it had infinite mass
/// (inverse mass 0) but a non-zero velocity.
class KinematicsObject : public GameObject {
public:
    Shape shape = Shape::Box;        ///< Collision shape.
    Real radius = Real(0.5);         ///< Sphere, Capsule, Cylinder radius, m (unused by boxes).
    Real height = 0;                 ///< Capsule: length of its segment; Cylinder: full length, m (along body y).
    std::shared_ptr<const ConvexHull> hull;         ///< Shape=Hull: its polyhedron (shapes.hpp).
    std::shared_ptr<const CompoundShape> compound;  ///< Shape=Compound: its parts (shapes.hpp).
    std::shared_ptr<const TriangleMesh> mesh;       ///< Shape=Mesh: its triangles (shapes.hpp).
    Vec3 velocity{0, 0, 0};          ///< Prescribed linear velocity, m/s.
    Vec3 angularVelocity{0, 0, 0};   ///< Prescribed angular velocity in world space, rad/s.
    Real elasticity = Real(1);       ///< Restitution factor, 0–1 (combined by the World's rule, Product by default).
    Real friction = Real(1);         ///< Friction factor, ≥ 0 (combined by the World's rule, Product by default).
    std::uint32_t material = kNoMaterial; ///< Its material's index, or kNoMaterial (as DynamicObject::material).

    /// @brief Half the box's edge lengths, m.
    Vec3 halfExtents() const { return scale * Real(0.5); }
    /// @brief True when the body neither moves nor turns (v = 0 and ω = 0): a wall, a floor, a level.
    /// Its position and orientation then stay exactly as they are, step after step, as a plane's do.
    bool atRest() const { return velocity == Vec3(0) && angularVelocity == Vec3(0); }
};

/// @brief An infinite, immovable plane: every point p with (p − position)·normal = 0.
///
/// The half-space behind the plane, (p − position)·normal < 0, is solid:
/// a sphere is pushed out along `normal`.
class CollisionPlane : public GameObject {
public:
    Vec3 normal{0, 1, 0};            ///< Unit normal pointing out of the solid side.
    Real elasticity = Real(1);       ///< Restitution factor, 0–1 (combined by the World's rule, Product by default).
    Real friction = Real(1);         ///< Friction factor, ≥ 0 (combined by the World's rule, Product by default).
    std::uint32_t material = kNoMaterial; ///< Its material's index, or kNoMaterial (as DynamicObject::material).

    /// @brief Signed distance of point @p p from the plane, m (positive on the normal's side).
    Real signedDistance(const Vec3& p) const { return glm::dot(p - position, normal); }
};

}  // namespace stepwise
