/// @file run_watch.cpp
/// @brief RunWatch: a body behind a plane, an unequal pair in contact.
#include "world/run_watch.hpp"

#include <algorithm>
#include <cstdio>

#include "core/limits.hpp"

namespace stepwise {

namespace {

/// "step 12 (t = 0.2 s): " for the step just taken.
std::string when(const World& world) {
    char text[96];
    std::snprintf(text, sizeof text, "step %llu (t = %.6g s): ", static_cast<unsigned long long>(world.stepCount()),
                  double(world.time()));
    return text;
}

}  // namespace

RunWatch::RunWatch(const World& world) : throughPlane_(world.dynamics().size(), 0) {}

std::vector<std::string> RunWatch::observe(const World& world) {
    std::vector<std::string> warnings;
    const std::vector<DynamicObject>& bodies = world.dynamics();

    // A body whose centre is behind a plane is more than half way through the solid side:
    // no contact the solver keeps can have put it there.
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (throughPlane_[i] != 0) continue;
        for (const CollisionPlane& plane : world.planes()) {
            const Real depth = -plane.signedDistance(bodies[i].position);
            if (depth <= 0) continue;
            throughPlane_[i] = 1;
            char text[512];
            std::snprintf(text, sizeof text,
                          "DynamicObject '%s' has gone through CollisionPlane '%s': its centre is %.3g m behind "
                          "it. A body more than %.6g times heavier pressing on it, or a speed the step cannot "
                          "follow, does this; what follows for it is not physics",
                          bodies[i].name.c_str(), plane.name.c_str(), double(depth), double(kMaxMassRatio));
            warnings.push_back(when(world) + text);
            break;
        }
    }

    // Two dynamic bodies in contact whose masses differ beyond what the solver holds.
    for (const Contact& contact : world.contacts()) {
        if (contact.b.kind != BodyKind::Dynamic) continue;
        const DynamicObject& a = bodies[contact.a];
        const DynamicObject& b = bodies[contact.b.index];
        const Real ratio = std::max(a.mass, b.mass) / std::min(a.mass, b.mass);
        if (ratio <= kMaxMassRatio) continue;
        const std::uint64_t key = std::uint64_t(std::min<std::uint32_t>(contact.a, contact.b.index)) * bodies.size() +
                                  std::max<std::uint32_t>(contact.a, contact.b.index);
        if (!unequalPairs_.insert(key).second) continue;
        const DynamicObject& light = a.mass < b.mass ? a : b;
        const DynamicObject& heavy = a.mass < b.mass ? b : a;
        char text[512];
        std::snprintf(text, sizeof text,
                      "DynamicObject '%s' (%.6g kg) touches '%s' (%.6g kg), %.3g times heavier; the solver holds "
                      "two bodies apart only up to a mass ratio of %.6g",
                      light.name.c_str(), double(light.mass), heavy.name.c_str(), double(heavy.mass), double(ratio),
                      double(kMaxMassRatio));
        warnings.push_back(when(world) + text);
    }
    count_ += warnings.size();
    return warnings;
}

}  // namespace stepwise
