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

}  // namespace

void writeTrajectoryHeader(std::FILE* out, bool withSpace) {
    std::fprintf(out, "%s\n", withSpace ? kSpacesTrajectoryCsvHeader : kTrajectoryCsvHeader);
}

void writeTrajectoryRows(std::FILE* out, const World& world) {
    const double time = static_cast<double>(world.time());
    for (const DynamicObject& body : world.dynamics()) writeRow(out, time, body, body.velocity, body.angularVelocity);
    for (const KinematicsObject& body : world.kinematics()) writeRow(out, time, body, body.velocity, body.angularVelocity);
}

void writeTrajectoryRows(std::FILE* out, const World& world, const std::string& space) {
    const double time = static_cast<double>(world.time());
    for (const DynamicObject& body : world.dynamics()) writeRow(out, time, body, body.velocity, body.angularVelocity, &space);
    for (const KinematicsObject& b : world.kinematics()) writeRow(out, time, b, b.velocity, b.angularVelocity, &space);
}

}  // namespace stepwise
