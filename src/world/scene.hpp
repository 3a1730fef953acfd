/// @file scene.hpp
/// @brief A scene as loaded from a file: settings plus the objects of each kind.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "forces/attractor.hpp"
#include "forces/region.hpp"
#include "forces/spring.hpp"
#include "dynamics/joints/joint_def.hpp"
#include "objects/game_object.hpp"
#include "objects/materials.hpp"
#include "objects/soft_body.hpp"
#include "world/expectations.hpp"
#include "core/world_settings.hpp"

namespace stepwise {

/// @brief One `MayChange` record: a field an assignment lets students edit.
///
/// The World never reads these. `stepwise grade --expect STARTER` does: it
/// compares every record of a submission with the starter's, field by
/// field, and fails any change that no MayChange record of the starter
/// names (docs/config-format.md, section "MayChange").
struct MayChange {
    int line = 0;        ///< Line of the record in its file.
    std::string object;  ///< The object's name, spelled as its own record spells it; "" = the World record.
    std::string field;   ///< The field's canonical name, or one component of it: "Elasticity", "ScaleY".
};

/// @brief One `Space` record: a simulation of its own beside the others (src/world/spaces.hpp).
struct SpaceDef {
    std::string name;        ///< Unique among the spaces; objects name it with `Space=`.
    WorldSettings settings;  ///< The World record's settings, with the Space record's own fields over them.
    Real timeScale = 1;      ///< Simulated seconds of this space per second of the shared clock.
    bool paused = false;     ///< Starts paused: it does not step until resumed.
    int line = 0;            ///< Line of the record in its file.
};

/// @brief Index of the default space in the `...Space` lists of a Scene: objects that name no space.
inline constexpr std::uint32_t kDefaultSpace = 0;

/// @brief Everything a scene file describes, before it becomes a World.
///
/// The scene loader fills a Scene completely or throws: there is never a
/// half-loaded Scene. Objects keep the order of the file within each kind.
struct Scene {
    std::string sourcePath;                  ///< File it came from ("" when built in code).
    WorldSettings settings;                  ///< From the `World` record, or defaults.
    std::vector<DynamicObject> dynamics;     ///< Simulated bodies.
    std::vector<KinematicsObject> kinematics;///< Prescribed-motion bodies.
    std::vector<CollisionPlane> planes;      ///< Infinite planes.
    std::vector<Spring> springs;             ///< Springs between dynamic bodies (indices into `dynamics`).
    std::vector<Attractor> attractors;       ///< Fixed points pulling by the inverse-square law.
    std::vector<Region> regions;             ///< Volumes with effects: drag, wind, buoyancy, ... (src/forces/region.hpp).
    std::vector<JointDef> joints;            ///< Joints between dynamic bodies (or to the world), in world space.
    std::vector<std::string> warnings;       ///< Things that load but may surprise (e.g. features not yet simulated).
    std::vector<Expectation> expectations;   ///< `Expect` records: what `stepwise run` checks (World ignores them).
    std::vector<MayChange> mayChange;        ///< `MayChange` records: what `stepwise grade` lets a student edit.

    /// `Space` records, in file order; empty for a scene of one simulation (every scene before spaces).
    std::vector<SpaceDef> spaces;
    // With spaces: the space of each object, kDefaultSpace or 1 + its index in `spaces`, parallel to
    // its list. Empty without spaces.
    std::vector<std::uint32_t> dynamicSpace;    ///< The space of each of `dynamics`.
    std::vector<std::uint32_t> kinematicSpace;  ///< The space of each of `kinematics`.
    std::vector<std::uint32_t> planeSpace;      ///< The space of each of `planes`.
    std::vector<std::uint32_t> attractorSpace;  ///< The space of each of `attractors`.
    std::vector<std::uint32_t> regionSpace;     ///< The space of each of `regions`.
    std::vector<Material> materials;         ///< `Material` records, in file order (objects' `material` indexes them).
    std::vector<MaterialPair> materialPairs; ///< `MaterialPair` records: pairs with their own μ or e.
    std::vector<SoftBody> softBodies;        ///< `SoftBody` records: pressure soft bodies (src/objects/soft_body.hpp).
    std::vector<std::uint32_t> softBodySpace;  ///< With spaces: the space of each of `softBodies` (as `dynamicSpace`).
};

}  // namespace stepwise
