/// @file broadphase_table.cpp
/// @brief The broadphase tracker's ranked table and its list of differences.
#include "io/broadphase_table.hpp"

namespace stepwise {

namespace {

const char* kindOfBody(BodyKind kind) {
    switch (kind) {
        case BodyKind::Dynamic: return "dynamic";
        case BodyKind::Kinematic: return "kinematic";
        case BodyKind::Plane: break;
    }
    return "plane";
}

}  // namespace

void writeBroadphaseTable(std::FILE* out, const BroadphaseTracker& tracker, const BodySet& bodies) {
    std::fprintf(out, "Broadphases on %zu dynamic, %zu kinematic bodies and %zu plane(s): %llu steps, %llu checked "
                      "against brute force\n",
                 bodies.dynamics.size(), bodies.kinematics.size(), bodies.planes.size(),
                 static_cast<unsigned long long>(tracker.steps()),
                 static_cast<unsigned long long>(tracker.checkedSteps()));
    std::fprintf(out, "  %-4s %-14s %11s %14s %12s %12s %10s %10s %s\n", "rank", "broadphase", "ms/step",
                 "pairs tested", "node tests", "candidates", "contacts", "efficiency", "differences");
    std::fprintf(out, "  %-4s %-14s %11s %14s %12s %12s %10s %10s %s\n", "", "", "", "per step", "per step",
                 "per step", "per step", "", "(errors)");
    int rank = 0;
    for (const TrackedBroadphase& t : tracker.ranked()) {
        const double steps = t.steps ? double(t.steps) : 1.0;
        std::fprintf(out, "  %-4d %-14s %11.4f %14.0f %12.0f %12.1f %10.1f %10.4f %llu (%llu)\n", ++rank,
                     toString(t.kind), 1e3 * t.secondsPerStep(), double(t.pairTests) / steps,
                     double(t.structureTests) / steps, double(t.candidatePairs) / steps,
                     double(t.contactPairs) / steps, t.efficiency(),
                     static_cast<unsigned long long>(t.missedContacts + t.otherDifferences),
                     static_cast<unsigned long long>(t.missedContacts));
    }
    std::fprintf(out, "  efficiency = touching pairs / pairs tested. Every broadphase returns brute force's pairs,\n"
                      "  so touching pairs / candidates is the same for all: the tightness of the boxes.\n");
    if (tracker.checkedSteps() < tracker.steps()) {
        std::fprintf(out, "  Brute force ran on the checked steps only; its per-step figures are over those.\n");
    }
    for (const BroadphaseDifference& d : tracker.differences()) {
        const std::string& a = bodies.dynamics[d.pair.a].name;
        const std::string& b = bodyName(bodies, d.pair.b);
        if (d.orderOnly) {
            std::fprintf(out, "  step %llu: %s returned its pairs out of order, first at (%s, %s)\n",
                         static_cast<unsigned long long>(d.step), toString(d.kind), a.c_str(), b.c_str());
        } else if (d.missing) {
            std::fprintf(out, "  step %llu: %s%s missed (%s, %s %s)%s\n", static_cast<unsigned long long>(d.step),
                         d.touching ? "ERROR: " : "", toString(d.kind), a.c_str(), kindOfBody(d.pair.b.kind),
                         b.c_str(), d.touching ? ", which the narrowphase finds touching" : " (not touching)");
        } else {
            std::fprintf(out, "  step %llu: %s returned (%s, %s %s), which brute force does not\n",
                         static_cast<unsigned long long>(d.step), toString(d.kind), a.c_str(),
                         kindOfBody(d.pair.b.kind), b.c_str());
        }
    }
}

}  // namespace stepwise
