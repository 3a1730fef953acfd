/// @file game_object.cpp
/// @brief Names of the object model's enumerations.
#include "objects/game_object.hpp"

namespace stepwise {

const char* toString(Shape shape) {
    switch (shape) {
        case Shape::Sphere: return "Sphere";
        case Shape::Box: return "Box";
    }
    return "?";
}

}  // namespace stepwise
