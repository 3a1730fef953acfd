/// @file types.cpp
/// @brief Finite-number checks shared by the stages that validate state.
#include "core/types.hpp"

#include <cmath>

namespace stepwise {

bool isFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool isFinite(const Quat& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

}  // namespace stepwise
