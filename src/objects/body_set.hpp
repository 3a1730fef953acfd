/// @file body_set.hpp
/// @brief The World's arrays of objects, handed to each stage as one argument.
#pragma once

#include <span>

#include "objects/game_object.hpp"
#include "objects/materials.hpp"
#include "objects/soft_body.hpp"

namespace stepwise {

/// @brief Views of the World's contiguous object arrays.
///
/// Stages receive this instead of the World so that each stage declares,
/// by its signature, that it only works on bodies: it cannot reach the
/// settings or the clock, and nothing outside the physics.
struct BodySet {
    std::span<DynamicObject> dynamics;             ///< Simulated bodies (stages may change them).
    std::span<const KinematicsObject> kinematics;  ///< Prescribed-motion bodies (read-only here).
    std::span<const CollisionPlane> planes;        ///< Infinite planes (read-only).
    /// How contacts mix their sides' friction and elasticity; nullptr: by product, as ContactMaterials() does.
    const ContactMaterials* materials = nullptr;
    /// Pressure soft bodies: each is one unit of an island (src/dynamics/islands.hpp). The soft step
    /// gets them apart from this set (src/soft/soft_step.hpp), and the rigid stages do not read them.
    std::span<SoftBody> softBodies{};
};

}  // namespace stepwise
