/// @file trajectory_csv.cpp
#include "io/trajectory_csv.hpp"

namespace stepwise {

namespace {

void writeRow(std::FILE* out, double time, const GameObject& object, const Vec3& velocity, const Vec3& omega,
              const std::string* space = nullptr) {
    const Vec3& p = object.position;
    const Quat& q = object.orientation;
    if (space != nullptr) std::fprintf(out, "%.17g,%s,", time, space->c_str());
    else std::fprintf(out, "%.17g,", time);
    std::fprintf(out, "%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                 object.name.c_str(), double(p.x), double(p.y), double(p.z), double(velocity.x),
                 double(velocity.y), double(velocity.z), double(q.w), double(q.x), double(q.y), double(q.z),
                 double(omega.x), double(omega.y), double(omega.z));
}

/// The rotation rate of a soft body's nodes about their centre of mass: ω = I⁻¹·L, with
/// I = Σ m·(|r|²·1 − r·rᵀ) and L = Σ m·r × (v − v_c). It is the ω of the rigid spin that has the
/// same angular momentum; for a body that spins as a rigid one it is that spin.
Vec3 softAngularVelocity(const SoftBody& body) {
    Mat3 inertia(0);
    Vec3 angularMomentum(0);
    for (std::size_t i = 0; i < body.nodeCount(); ++i) {
        const Real m = Real(1) / body.nodeInverseMasses[i];
        const Vec3 r = body.nodePositions[i] - body.position;
        inertia += m * (glm::dot(r, r) * Mat3(1) - glm::outerProduct(r, r));
        angularMomentum += m * glm::cross(r, body.nodeVelocities[i] - body.velocity);
    }
    if (glm::determinant(inertia) == 0) return Vec3(0);
    return glm::inverse(inertia) * angularMomentum;
}

void writeSoftRow(std::FILE* out, double time, const SoftBody& body, const std::string* space = nullptr) {
    const Vec3& p = body.position;
    const Vec3& v = body.velocity;
    const Vec3 w = softAngularVelocity(body);
    if (space != nullptr) std::fprintf(out, "%.17g,%s,", time, space->c_str());
    else std::fprintf(out, "%.17g,", time);
    std::fprintf(out, "%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,1,0,0,0,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                 body.name.c_str(), double(p.x), double(p.y), double(p.z), double(v.x), double(v.y), double(v.z),
                 double(w.x), double(w.y), double(w.z), double(body.volume), double(body.pressure));
}

}  // namespace

void writeTrajectoryHeader(std::FILE* out, bool withSpace, bool withSoftBodies) {
    std::fprintf(out, "%s%s\n", withSpace ? kSpacesTrajectoryCsvHeader : kTrajectoryCsvHeader,
                 withSoftBodies ? kSoftBodyCsvColumns : "");
}

void writeNodeHeader(std::FILE* out, bool withSpace) {
    std::fprintf(out, "%s\n", withSpace ? kSpacesNodeCsvHeader : kNodeCsvHeader);
}

namespace {

void writeNodes(std::FILE* out, const World& world, const std::string* space) {
    const double time = static_cast<double>(world.time());
    for (const SoftBody& body : world.softBodies()) {
        for (std::size_t i = 0; i < body.nodeCount(); ++i) {
            const Vec3& p = body.nodePositions[i];
            const Vec3& v = body.nodeVelocities[i];
            if (space != nullptr) std::fprintf(out, "%.17g,%s,", time, space->c_str());
            else std::fprintf(out, "%.17g,", time);
            std::fprintf(out, "%s,%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", body.name.c_str(), i, double(p.x),
                         double(p.y), double(p.z), double(v.x), double(v.y), double(v.z));
        }
    }
}

}  // namespace

void writeNodeRows(std::FILE* out, const World& world) { writeNodes(out, world, nullptr); }

void writeNodeRows(std::FILE* out, const World& world, const std::string& space) { writeNodes(out, world, &space); }

void writeTrajectoryRows(std::FILE* out, const World& world) {
    const double time = static_cast<double>(world.time());
    for (const DynamicObject& body : world.dynamics()) writeRow(out, time, body, body.velocity, body.angularVelocity);
    for (const KinematicsObject& body : world.kinematics()) writeRow(out, time, body, body.velocity, body.angularVelocity);
    for (const SoftBody& body : world.softBodies()) writeSoftRow(out, time, body);
}

void writeTrajectoryRows(std::FILE* out, const World& world, const std::string& space) {
    const double time = static_cast<double>(world.time());
    for (const DynamicObject& body : world.dynamics()) writeRow(out, time, body, body.velocity, body.angularVelocity, &space);
    for (const KinematicsObject& b : world.kinematics()) writeRow(out, time, b, b.velocity, b.angularVelocity, &space);
    for (const SoftBody& body : world.softBodies()) writeSoftRow(out, time, body, &space);
}

}  // namespace stepwise
