/// @file game_object.cpp
/// @brief Names of the object model's enumerations.
#include "objects/game_object.hpp"

namespace stepwise {

const char* toString(Shape shape) {
    switch (shape) {
        case Shape::Sphere: return "Sphere";
        case Shape::Box: return "Box";
        case Shape::Capsule: return "Capsule";
        case Shape::Cylinder: return "Cylinder";
        case Shape::Hull: return "Hull";
        case Shape::Compound: return "Compound";
        case Shape::Mesh: return "Mesh";
    }
    return "?";
}

}  // namespace stepwise
