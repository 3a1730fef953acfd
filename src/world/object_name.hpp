/// @file object_name.hpp
/// @brief The scene name of the object a BodyRef points to, for anything that reports on a World
/// (the trace, the viewer's panel and walk-through).
#pragma once

#include <string>

#include "world/world.hpp"

namespace stepwise {

/// @brief Name of the object @p ref of @p world: a dynamic or kinematic body, or a plane.
inline const std::string& objectName(const World& world, const BodyRef& ref) {
    switch (ref.kind) {
        case BodyKind::Dynamic: return world.dynamics()[ref.index].name;
        case BodyKind::Kinematic: return world.kinematics()[ref.index].name;
        case BodyKind::Plane: break;
    }
    return world.planes()[ref.index].name;
}

}  // namespace stepwise
