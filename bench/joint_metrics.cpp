/// @file joint_metrics.cpp
/// @brief The joint meter and the mechanical energy (joint_metrics.hpp).
#include "joint_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace stepwise::bench {

namespace {

/// A hinge axis shorter than this is not normalised (the scene loader refuses it anyway).
constexpr Real kShortestAxis = Real(1e-9);

}  // namespace

JointMeter::JointMeter(const Scene& scene) {
    const auto indexOf = [&](const std::string& name, const std::string& joint) {
        const auto found = std::find_if(scene.dynamics.begin(), scene.dynamics.end(),
                                        [&](const DynamicObject& b) { return b.name == name; });
        if (found == scene.dynamics.end()) {
            throw std::invalid_argument(joint + ": the joint meter finds no DynamicObject named '" + name + "'");
        }
        return static_cast<std::size_t>(found - scene.dynamics.begin());
    };
    for (const JointDef& def : scene.joints) {
        if (def.kind == JointKind::AngularMotor) continue;  // holds no point
        Held held{};
        held.kind = def.kind;
        held.a = indexOf(def.bodyA, def.name);
        held.b = def.bodyB.empty() ? kWorld : indexOf(def.bodyB, def.name);
        // Ball and Hinge share one point; Distance and Rope have one at each end.
        const bool onePoint = def.kind == JointKind::Ball || def.kind == JointKind::Hinge;
        const Vec3 pointB = onePoint ? def.anchorA : def.anchorB;
        const Vec3 axis = glm::length(def.axis) > kShortestAxis ? glm::normalize(def.axis) : Vec3(0, 0, 1);
        const DynamicObject& a = scene.dynamics[held.a];
        held.anchorA = glm::conjugate(a.orientation) * (def.anchorA - a.position);
        held.axisA = glm::conjugate(a.orientation) * axis;
        if (held.b == kWorld) {
            held.anchorB = pointB;
            held.axisB = axis;
        } else {
            const DynamicObject& b = scene.dynamics[held.b];
            held.anchorB = glm::conjugate(b.orientation) * (pointB - b.position);
            held.axisB = glm::conjugate(b.orientation) * axis;
        }
        held.length = def.length ? *def.length : glm::length(def.anchorB - def.anchorA);
        joints_.push_back(held);
    }
}

void JointMeter::observe(std::span<const BodyState> bodies) {
    Real gap = 0, sum = 0;
    for (const Held& j : joints_) {
        const BodyState& a = bodies[j.a];
        const Vec3 pA = a.position + a.orientation * j.anchorA;
        const Vec3 kA = a.orientation * j.axisA;
        Vec3 pB = j.anchorB, kB = j.axisB;
        if (j.b != kWorld) {
            const BodyState& b = bodies[j.b];
            pB = b.position + b.orientation * j.anchorB;
            kB = b.orientation * j.axisB;
        }
        const Real apart = glm::length(pA - pB);
        Real error = apart;
        if (j.kind == JointKind::Distance) error = std::abs(apart - j.length);
        if (j.kind == JointKind::Rope) error = std::max(Real(0), apart - j.length);
        // A body at NaN has blown up: its gap is counted as infinite (std::max would skip a NaN).
        if (std::isnan(error)) error = std::numeric_limits<Real>::infinity();
        gap = std::max(gap, error);
        sum += error;
        if (j.kind == JointKind::Hinge) {
            // The angle between unit vectors from atan2(|k_A × k_B|, k_A·k_B): exact near 0, where acos is not.
            Real angle = std::atan2(glm::length(glm::cross(kA, kB)), glm::dot(kA, kB));
            if (std::isnan(angle)) angle = std::numeric_limits<Real>::infinity();
            worstAngle_ = std::max(worstAngle_, angle);
        }
    }
    lastGap_ = gap;
    worstGap_ = std::max(worstGap_, gap);
    worstSum_ = std::max(worstSum_, sum);
}

double mechanicalEnergy(std::span<const BodyState> bodies, const Scene& scene) {
    const glm::dvec3 g(scene.settings.gravity);
    double energy = 0;
    for (std::size_t n = 0; n < bodies.size() && n < scene.dynamics.size(); ++n) {
        const double m = double(scene.dynamics[n].mass);
        const glm::dvec3 v(bodies[n].velocity), w(bodies[n].angularVelocity), l(bodies[n].angularMomentum);
        energy += 0.5 * m * glm::dot(v, v) + 0.5 * glm::dot(w, l) - m * glm::dot(g, glm::dvec3(bodies[n].position));
    }
    return energy;
}

}  // namespace stepwise::bench
