/// @file main.cpp
/// @brief stepwise-figures: the numbers behind the lectures' geometric figures, computed by the engine.
///
/// scripts/figures.sh draws every figure of lectures/images/ with gnuplot. Most
/// of them plot what `stepwise run --csv` or `stepwise plot --data` writes; the
/// ones that show geometry inside a stage (the separating axes, a face being
/// clipped, the impulse at a contact, the waves of the fast path) need numbers
/// the command line does not print. This program runs a lecture's scene with a
/// StepObserver, stops at the stage the lecture looks at, and prints what the
/// stage saw or produced, as whitespace-separated columns for gnuplot (blocks
/// separated by two blank lines: gnuplot's `index`). Each command checks its
/// numbers against what the engine itself reported (the narrowphase's normal and
/// depth, the impulse stage's j), and fails rather than print a figure that
/// disagrees with the engine.
///
///   stepwise-figures impulse-geometry   lecture 3: the off-centre impact of `small` and `big`
///   stepwise-figures bounce-impulses    appendix 3a: height and normal impulse of every step of the bounce
///   stepwise-figures sat-axes           lecture 5: both boxes' shadows on each of the 15 axes
///   stepwise-figures clipping           lecture 6: the incident face clipped by each side plane in turn
///   stepwise-figures waves              appendix 8a: the waves and batches of the 1000-ball rain
///   stepwise-figures colours            appendix 8a: the waves of the two contact orders, four scenes
///   stepwise-figures gjk-bounds         lecture 10: GJK's upper and lower bounds on the distance, per iteration
///   stepwise-figures mpr-depth          lecture 11: SAT, EPA and MPR's depth and normal as a box slides off a table
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "collision/box_features.hpp"
#include "collision/clip_polygon.hpp"
#include "collision/contact.hpp"
#include "collision/convex_pairs.hpp"
#include "collision/epa.hpp"
#include "collision/gjk.hpp"
#include "collision/mpr.hpp"
#include "config/scene_loader.hpp"
#include "dynamics/contact_colours.hpp"
#include "dynamics/contact_solver.hpp"
#include "fast/box_contact_lanes.hpp"
#include "fast/contact_waves.hpp"
#include "fast/fast_workspace.hpp"
#include "fast/parallel_waves.hpp"
#include "fast/round_contact_lanes.hpp"
#include "world/object_name.hpp"
#include "world/world.hpp"

using namespace stepwise;

namespace {

/// Thrown when a figure's numbers would disagree with the engine: the figure is not drawn.
struct FigureError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

World loadWorld(const std::string& name) { return World(loadSceneFile(std::string(STEPWISE_CONFIG_DIR) + "/" + name)); }

/// Index of the dynamic body called @p name.
std::size_t dynamicIndex(const World& world, const std::string& name) {
    for (std::size_t i = 0; i < world.dynamics().size(); ++i)
        if (world.dynamics()[i].name == name) return i;
    throw FigureError("no dynamic body '" + name + "'");
}

/// Calls @p onStage after every run of @p stage, until it returns true.
class StageWatcher : public StepObserver {
public:
    StageWatcher(Stage stage, std::function<bool(const StageEvent&, const World&)> onStage, Stage before = Stage::ApplyForces,
                 std::function<void(const World&)> beforeStage = {})
        : stage_(stage), before_(before), onStage_(std::move(onStage)), beforeStage_(std::move(beforeStage)) {}
    void beforeStage(const StageEvent& event, const World& world) override {
        if (!done_ && beforeStage_ && event.stage == before_) beforeStage_(world);
    }
    void afterStage(const StageEvent& event, const World& world) override {
        if (!done_ && event.stage == stage_) done_ = onStage_(event, world);
    }
    bool done() const { return done_; }

private:
    Stage stage_;
    Stage before_;
    std::function<bool(const StageEvent&, const World&)> onStage_;
    std::function<void(const World&)> beforeStage_;
    bool done_ = false;
};

/// Steps @p world with @p watcher until the watcher is done; at most @p maxSteps steps.
void stepUntil(World& world, StageWatcher& watcher, std::uint64_t maxSteps) {
    world.setObserver(&watcher);
    for (std::uint64_t i = 0; i < maxSteps && !watcher.done(); ++i) world.step();
    world.setObserver(nullptr);
    if (!watcher.done()) throw FigureError("the stage the figure looks at never came");
}

/// The first contact between dynamic bodies @p a and @p b in the last narrowphase, or nullptr.
const Contact* contactBetween(const World& world, std::size_t a, std::size_t b) {
    for (const Contact& c : world.contacts()) {
        if (c.b.kind != BodyKind::Dynamic) continue;
        if ((c.a == a && c.b.index == b) || (c.a == b && c.b.index == a)) return &c;
    }
    return nullptr;
}

// ------------------------------------------------------------------ lecture 3

/// The off-centre impact of lesson03_collisions.scene, in the plane z = 4 the two balls move in:
/// both circles where the narrowphase found them, the contact point and normal, the velocities
/// before and after the impulses, and the impulse on B split into its normal and friction parts.
int impulseGeometry() {
    World world = loadWorld("lesson03_collisions.scene");
    const std::size_t small = dynamicIndex(world, "small"), big = dynamicIndex(world, "big");
    std::vector<DynamicObject> before;
    Contact contact;
    std::vector<DynamicObject> after;
    ImpulseReport report;
    StageWatcher watcher(
        Stage::ResolveImpulses,
        [&](const StageEvent&, const World& w) {
            const Contact* c = contactBetween(w, small, big);
            if (!c) return false;
            contact = *c;
            report = w.impulses()[static_cast<std::size_t>(c - w.contacts().data())];
            after = w.dynamics();
            return true;
        },
        Stage::ResolveImpulses, [&](const World& w) { before = w.dynamics(); });
    stepUntil(world, watcher, 1000);

    const DynamicObject& a = before[contact.a];
    const std::size_t bIndex = contact.b.index;
    const DynamicObject& b = before[bIndex];
    // The impulse on B is the change of its momentum; on A the opposite (Newton's third law).
    const Vec3 impulse = b.mass * (after[bIndex].velocity - b.velocity);
    const Vec3 impulseOnA = a.mass * (after[contact.a].velocity - a.velocity);
    const Vec3 normalPart = glm::dot(impulse, contact.normal) * contact.normal;
    const Vec3 frictionPart = impulse - normalPart;
    if (glm::length(impulse + impulseOnA) > 1e-9 || std::abs(double(glm::dot(impulse, contact.normal) - report.normalImpulse)) > 1e-9 ||
        std::abs(double(glm::length(frictionPart) - report.frictionImpulse)) > 1e-9) {
        throw FigureError("the momentum changes disagree with the impulse stage's report");
    }
    std::printf("# lesson03_collisions.scene, the impact of %s (A) and %s (B), t = %.6f s\n", a.name.c_str(),
                b.name.c_str(), double(world.time()) - double(world.settings().timeStep));
    std::printf("# j = %.6f N*s along n, friction %.6f N*s, e = %.4f, approach %.6f m/s\n", double(report.normalImpulse),
                double(report.frictionImpulse), double(report.restitution), double(report.approachSpeed));
    std::printf("# circles: x y radius name\n");
    std::printf("%.9f %.9f %.9f %s\n", double(a.position.x), double(a.position.y), double(a.radius), a.name.c_str());
    std::printf("%.9f %.9f %.9f %s\n", double(b.position.x), double(b.position.y), double(b.radius), b.name.c_str());
    std::printf("\n\n# arrows: x y dx dy what (velocities in m/s, impulses in N*s, from where they act)\n");
    const auto arrow = [](const Vec3& from, const Vec3& d, const char* what) {
        std::printf("%.9f %.9f %.9f %.9f %s\n", double(from.x), double(from.y), double(d.x), double(d.y), what);
    };
    arrow(a.position, a.velocity, "v_A-before");
    arrow(b.position, b.velocity, "v_B-before");
    arrow(a.position, after[contact.a].velocity, "v_A-after");
    arrow(b.position, after[bIndex].velocity, "v_B-after");
    arrow(contact.point, normalPart, "j*n-on-B");
    arrow(contact.point, frictionPart, "friction-on-B");
    arrow(contact.point, -impulse, "-J-on-A");
    std::printf("\n\n# contact point: x y, and the unit normal n (from A to B)\n");
    std::printf("%.9f %.9f %.9f %.9f\n", double(contact.point.x), double(contact.point.y), double(contact.normal.x),
                double(contact.normal.y));
    return 0;
}

// ------------------------------------------------------------------ appendix 3a

/// lesson03_bounce.scene, every step: the time at its end, the ball's height and the normal
/// impulse of the floor contact in that step (0 when there was none).
int bounceImpulses() {
    World world = loadWorld("lesson03_bounce.scene");
    const std::size_t ball = dynamicIndex(world, "ball");
    std::printf("# lesson03_bounce.scene: t (s, end of the step)  y (m)  j (N*s)  resting (1/0)\n");
    std::printf("# m g h = %.9f N*s: the impulse that stops one step of falling\n",
                double(world.dynamics()[ball].mass * -world.settings().gravity.y * world.settings().timeStep));
    Real j = 0;
    bool resting = false;
    StageWatcher watcher(Stage::ResolveImpulses, [&](const StageEvent&, const World& w) {
        for (std::size_t i = 0; i < w.contacts().size(); ++i) {
            if (w.contacts()[i].a == ball) {
                j = w.impulses()[i].normalImpulse;
                resting = w.impulses()[i].resting;
            }
        }
        return false;
    });
    world.setObserver(&watcher);
    std::printf("%.9f %.9f %.9f %d\n", 0.0, double(world.dynamics()[ball].position.y), 0.0, 0);
    const auto steps = static_cast<std::uint64_t>(std::llround(world.settings().duration / world.settings().timeStep));
    for (std::uint64_t i = 0; i < steps; ++i) {
        j = 0;
        resting = false;
        world.step();
        std::printf("%.9f %.9f %.9f %d\n", double(world.time()), double(world.dynamics()[ball].position.y), double(j),
                    resting ? 1 : 0);
    }
    world.setObserver(nullptr);
    return 0;
}

// ------------------------------------------------------------------ lecture 5

/// One box of a pair, as the separating-axis test sees it.
OrientedBox boxOf(const World& world, const BodyRef& ref) {
    const Geometry g = ref.kind == BodyKind::Dynamic ? geometryOf(world.dynamics()[ref.index])
                                                     : geometryOf(world.kinematics()[ref.index]);
    if (g.type != GeometryType::Box) throw FigureError("not a box: " + objectName(world, ref));
    return orientedBoxOf(g);
}

/// The shadow of @p box on the unit axis @p axis: the smallest and largest projection of its 8 corners.
std::pair<double, double> shadow(const OrientedBox& box, const Vec3& axis) {
    double low = 1e300, high = -1e300;
    for (int corner = 0; corner < 8; ++corner) {
        const double p = double(glm::dot(cornerOf(box, corner), axis));
        low = std::min(low, p);
        high = std::max(high, p);
    }
    return {low, high};
}

/// The row (0–14) of the axis the narrowphase chose, from the feature id of its contact:
/// a face of A (rows 0–2), a face of B (3–5), or the cross of an edge of each (6 + 3i + j).
int chosenRow(std::uint32_t featureId) {
    switch (featureKind(featureId)) {
        case BoxContactKind::FaceOfA: return static_cast<int>(featureId & 7u) / 2;
        case BoxContactKind::FaceOfB: return 3 + static_cast<int>(featureId & 7u) / 2;
        case BoxContactKind::EdgeEdge:
            return 6 + 3 * (static_cast<int>(featureId & 15u) / 4) + static_cast<int>((featureId >> 4) & 15u) / 4;
    }
    throw FigureError("not a box-box feature id");
}

/// The 15 candidate axes of one pair on the first step it touches: both shadows on each axis,
/// measured from A's centre, and the separation. The last column is 2 on the axis the narrowphase
/// chose (its contact's feature id says which), 1 on the others along the same line. The chosen
/// axis must lie along the contact normal, and its overlap must be the contact's depth.
void printAxes(const World& world, const Contact& contact) {
    const BodyRef a{BodyKind::Dynamic, contact.a};  // A is always dynamic
    const OrientedBox boxA = boxOf(world, a), boxB = boxOf(world, contact.b);
    std::printf("# %s (A) and %s (B), step %llu: contact normal (%.6f, %.6f, %.6f), depth %.6f m\n",
                objectName(world, a).c_str(), objectName(world, contact.b).c_str(),
                static_cast<unsigned long long>(world.stepCount() + 1), double(contact.normal.x), double(contact.normal.y),
                double(contact.normal.z), double(contact.depth));
    std::printf("# row label lowA highA lowB highB separation chosen (projections in m, from A's centre)\n");
    int row = 0;
    const int chosenAxis = chosenRow(contact.featureId);
    bool matched = false;
    const auto axis = [&](const Vec3& raw, const std::string& label) {
        const double length = double(glm::length(raw));
        if (length < 1e-3) {  // parallel edges: no axis (box_box.cpp, kParallelEdgeSine)
            std::printf("%d \"%s\" nan nan nan nan nan 0\n", row++, (label + " (parallel)").c_str());
            if (row - 1 == chosenAxis) throw FigureError("the narrowphase chose an axis of two parallel edges");
            return;
        }
        const Vec3 unit = raw / Real(length);
        const double origin = double(glm::dot(boxA.centre, unit));
        auto [lowA, highA] = shadow(boxA, unit);
        auto [lowB, highB] = shadow(boxB, unit);
        const double separation = std::max(lowB - highA, lowA - highB);
        const bool alongNormal = std::abs(std::abs(double(glm::dot(unit, contact.normal))) - 1) < 1e-9;
        const bool chosen = row == chosenAxis;
        if (chosen && alongNormal && std::abs(-separation - double(contact.depth)) < 1e-9) matched = true;
        std::printf("%d \"%s\" %.9f %.9f %.9f %.9f %.9f %d\n", row, label.c_str(), lowA - origin, highA - origin,
                    lowB - origin, highB - origin, separation, chosen ? 2 : alongNormal ? 1 : 0);
        ++row;
    };
    const char* names[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) axis(boxA.axes[i], std::string("a") + names[i]);
    for (int j = 0; j < 3; ++j) axis(boxB.axes[j], std::string("b") + names[j]);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            axis(glm::cross(boxA.axes[i], boxB.axes[j]), std::string("a") + names[i] + " x b" + names[j]);
    if (!matched) throw FigureError("the axis the narrowphase chose does not have its normal and depth");
}

/// lesson05_sat.scene: crate on table (a face, step 6), wedge on ridge (two edges, step 9).
int satAxes() {
    World world = loadWorld("lesson05_sat.scene");
    int printed = 0;
    for (const char* name : {"crate", "wedge"}) {
        const std::size_t body = dynamicIndex(world, name);
        StageWatcher watcher(Stage::Narrowphase, [&](const StageEvent&, const World& w) {
            for (const Contact& c : w.contacts()) {
                if (c.a != body || c.b.kind != BodyKind::Kinematic) continue;
                if (printed++ > 0) std::printf("\n\n");
                printAxes(w, c);
                return true;
            }
            return false;
        });
        stepUntil(world, watcher, 100);
    }
    return 0;
}

// ------------------------------------------------------------------ lecture 6

/// lesson05_sat.scene's crate on the table, step 6: the incident face and what is left of it after
/// each side plane of the reference face, in the reference face's own coordinates (u, v), as
/// faceContact() in box_box.cpp builds them, clipped by the engine's clipPolygon(). Then the
/// reference face, each side plane's line, and the narrowphase's contact points.
int clipping() {
    World world = loadWorld("lesson05_sat.scene");
    const std::size_t crate = dynamicIndex(world, "crate");
    StageWatcher watcher(Stage::Narrowphase, [&](const StageEvent&, const World& w) {
        std::vector<Contact> points;
        for (const Contact& c : w.contacts())
            if (c.a == crate && c.b.kind == BodyKind::Kinematic) points.push_back(c);
        if (points.empty()) return false;
        const Contact& first = points.front();
        const BoxContactKind kind = featureKind(first.featureId);
        if (kind == BoxContactKind::EdgeEdge) throw FigureError("an edge contact: nothing is clipped");
        const int referenceFace = static_cast<int>(first.featureId & 7u);
        const int incidentFace = static_cast<int>((first.featureId >> 3) & 7u);
        const OrientedBox boxA = boxOf(w, {BodyKind::Dynamic, static_cast<std::uint32_t>(crate)}), boxB = boxOf(w, first.b);
        const OrientedBox& reference = kind == BoxContactKind::FaceOfA ? boxA : boxB;
        const OrientedBox& incident = kind == BoxContactKind::FaceOfA ? boxB : boxA;
        const int referenceAxis = referenceFace / 2, incidentAxis = incidentFace / 2;
        const Real referenceSign = referenceFace % 2 ? Real(-1) : Real(1);
        const Real incidentSign = incidentFace % 2 ? Real(-1) : Real(1);
        const Vec3 referenceNormal = reference.axes[referenceAxis] * referenceSign;
        const int u = (referenceAxis + 1) % 3, v = (referenceAxis + 2) % 3;
        const Vec3 faceCentre = reference.centre + referenceNormal * reference.halfExtents[referenceAxis];
        const auto print = [&](const Vec3& p) {
            std::printf("%.9f %.9f\n", double(glm::dot(p - faceCentre, reference.axes[u])),
                        double(glm::dot(p - faceCentre, reference.axes[v])));
        };
        std::printf("# lesson05_sat.scene, step %llu: reference face %d of %s, incident face %d of %s\n",
                    static_cast<unsigned long long>(w.stepCount() + 1), referenceFace,
                    kind == BoxContactKind::FaceOfA ? "crate" : "table", incidentFace,
                    kind == BoxContactKind::FaceOfA ? "table" : "crate");
        std::printf("# coordinates (m) along the reference box's axes %d and %d, from the reference face's centre\n", u, v);

        // The incident face's corners, in faceContact()'s order: (−,−), (+,−), (+,+), (−,+).
        const int p = (incidentAxis + 1) % 3, q = (incidentAxis + 2) % 3;
        const Vec3 incidentCentre = incident.centre + incident.axes[incidentAxis] * (incidentSign * incident.halfExtents[incidentAxis]);
        constexpr Real kSignP[4] = {-1, 1, 1, -1};
        constexpr Real kSignQ[4] = {-1, -1, 1, 1};
        ClipVertex polygon[kMaxClipVertices], clipped[kMaxClipVertices];
        int count = 4;
        for (int m = 0; m < 4; ++m) {
            polygon[m].position = incidentCentre + incident.axes[p] * (kSignP[m] * incident.halfExtents[p]) +
                                  incident.axes[q] * (kSignQ[m] * incident.halfExtents[q]);
        }
        const auto printPolygon = [&](const char* title) {
            std::printf("# %s: %d vertices\n", title, count);
            for (int i = 0; i <= count; ++i) print(polygon[i % count].position);  // closed
            std::printf("\n\n");
        };
        printPolygon("the incident face");
        const int sideAxes[4] = {u, u, v, v};
        const Real sideSigns[4] = {1, -1, 1, -1};
        const char* sideNames[4] = {"after the +u side plane", "after the -u side plane", "after the +v side plane",
                                    "after the -v side plane"};
        for (int side = 0; side < 4 && count > 0; ++side) {
            const Vec3 planeNormal = reference.axes[sideAxes[side]] * sideSigns[side];
            const Real offset = glm::dot(planeNormal, reference.centre) + reference.halfExtents[sideAxes[side]];
            count = clipPolygon(polygon, count, planeNormal, offset, static_cast<std::uint8_t>(4 + side), kTouchTolerance, clipped);
            std::copy(clipped, clipped + count, polygon);
            printPolygon(sideNames[side]);
        }
        // The reference face: its four corners, closed.
        std::printf("# the reference face\n");
        const Real eu = reference.halfExtents[u], ev = reference.halfExtents[v];
        for (const auto& [su, sv] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}}) {
            std::printf("%.9f %.9f\n", double(su * eu), double(sv * ev));
        }
        std::printf("\n\n# the narrowphase's contact points (depth in m as the third column)\n");
        int kept = 0;
        for (int i = 0; i < count; ++i) {
            if (glm::dot(polygon[i].position - faceCentre, referenceNormal) <= kSpeculativeDistance) ++kept;
        }
        for (const Contact& c : points) {
            std::printf("%.9f %.9f %.9f\n", double(glm::dot(c.point - faceCentre, reference.axes[u])),
                        double(glm::dot(c.point - faceCentre, reference.axes[v])), double(c.depth));
        }
        if (kept != static_cast<int>(points.size())) {
            throw FigureError("the clipped face keeps " + std::to_string(kept) + " points, the narrowphase reported " +
                              std::to_string(points.size()));
        }
        return true;
    });
    stepUntil(world, watcher, 100);
    return 0;
}

// ------------------------------------------------------------------ appendix 8a

/// The contacts of @p file's step @p step as its prepare stage left them: SolverWorkspace::contacts,
/// the round ones and the others listed in the order the narrowphase found them (`ContactOrder=Found`,
/// the order of the contact array), and as many (empty) body records as they name, which is all the
/// colouring and the wave scheduling read.
SolverWorkspace contactsAtStep(const std::string& file, std::uint64_t step) {
    World world = loadWorld(file);
    for (std::uint64_t i = 1; i < step; ++i) world.step();
    SolverWorkspace solver;
    StageWatcher watcher(Stage::PrepareConstraints, [&](const StageEvent&, const World& w) {
        solver.contacts = w.solverContacts();
        std::uint32_t records = 1;
        for (std::uint32_t k = 0; k < solver.contacts.size(); ++k) {
            const SolverContact& c = solver.contacts[k];
            (c.rows == kRoundContact ? solver.roundContacts : solver.otherContacts).push_back(k);
            records = std::max({records, c.bodyA + 1, c.bodyB + 1});
        }
        solver.bodies.resize(records);
        solver.colourOrder = w.settings().contactOrder == ContactOrder::Colours;
        return true;
    });
    stepUntil(world, watcher, 1);
    return solver;
}

/// @p solver's lists put in the order its scene's passes take them, as prepareContacts() puts them:
/// colour by colour by the engine's own orderByColour() (`ContactOrder=Colours`, the default), or
/// left as found.
void toPassOrder(SolverWorkspace& solver) {
    if (!solver.colourOrder) return;
    orderByColour(solver, solver.roundContacts, solver.colouring.roundColourEnds);
    orderByColour(solver, solver.otherContacts, solver.colouring.otherColourEnds);
}

/// bench_sphere_rain_1k.scene at step @p step: the round contacts of the step, in the order its passes
/// take them, put in waves and batches by the fast path's own batchRoundContacts(): per wave, its
/// contacts and batches.
int waves(std::uint64_t step) {
    SolverWorkspace solver = contactsAtStep("bench_sphere_rain_1k.scene", step);
    toPassOrder(solver);
    FastWorkspace fast;
    batchRoundContacts(solver, fast);
    std::printf("# bench_sphere_rain_1k.scene, step %llu: %zu round contacts in %u waves, %zu batches of %d lanes\n",
                static_cast<unsigned long long>(step), solver.roundContacts.size(), fast.waves, fast.roundBatches.size(),
                kLanes);
    std::printf("# wave contacts batches full-batches\n");
    std::size_t contacts = 0;
    for (std::uint32_t wave = 0; wave < fast.waves; ++wave) {
        std::size_t inWave = 0, batches = 0, full = 0;
        for (const RoundBatch& batch : fast.roundBatches) {
            if (batch.wave != wave) continue;
            ++batches;
            int lanes = 0;
            for (int lane = 0; lane < kLanes; ++lane) lanes += batch.contact[lane] != kEmptyLane ? 1 : 0;
            inWave += static_cast<std::size_t>(lanes);
            full += lanes == kLanes ? 1 : 0;
        }
        contacts += inWave;
        std::printf("%u %zu %zu %zu\n", wave, inWave, batches, full);
    }
    if (contacts != solver.roundContacts.size()) throw FigureError("the batches do not hold every round contact");
    return 0;
}

/// One pass's list of contacts put in waves: per wave, how many contacts it holds.
struct Waves {
    std::vector<std::size_t> sizes;  ///< Contacts per wave, in the order the pass runs them.
    std::size_t splitContacts = 0;   ///< Contacts in waves of at least kParallelWaveBatches batches.
    double boxContactsPerWave = 0;   ///< The list with stored rows: its contacts per wave (batchBoxContacts()'s test).
    bool boxesInLanes = false;       ///< ... at least kMinBoxContactsPerWave: the fast path solves them in lanes.
};

/// Contacts of a wave that fill at least kParallelWaveBatches batches of kLanes: a wave the threads split.
bool wideEnoughToSplit(std::size_t contacts) {
    return (contacts + kLanes - 1) / kLanes >= kParallelWaveBatches;
}

/// Fails unless no two contacts of one wave share a dynamic body (record 0, the static one, is shared freely).
void requireColouring(const SolverWorkspace& solver, const std::vector<std::uint32_t>& list,
                      const std::vector<std::uint32_t>& waveOf) {
    std::vector<std::vector<bool>> used(solver.bodies.size());
    for (std::size_t k = 0; k < list.size(); ++k) {
        const SolverContact& c = solver.contacts[list[k]];
        for (const std::uint32_t body : {c.bodyA, c.bodyB}) {
            if (body == kStaticSolverBody) continue;
            if (used[body].size() <= waveOf[k]) used[body].resize(waveOf[k] + 1, false);
            if (used[body][waveOf[k]]) throw FigureError("two contacts of one wave share a body");
            used[body][waveOf[k]] = true;
        }
    }
}

/// The waves of @p list in its order: the engine's scheduleWaves() (contact_colours.hpp), which
/// batchRoundContacts() and batchBoxContacts() call for a list as found (for one in colour order
/// they take the colours, which requireWavesAreColours() checks are these waves). Checked to share
/// no body within a wave.
std::vector<std::uint32_t> wavesOf(const SolverWorkspace& solver, const std::vector<std::uint32_t>& list,
                                   std::vector<std::size_t>& sizes) {
    ContactWaveSchedule schedule;
    scheduleWaves(solver, list, schedule);
    requireColouring(solver, list, schedule.waveOf);
    for (std::uint32_t wave = 0; wave < schedule.waves; ++wave)
        sizes.push_back(schedule.ends[wave] - (wave == 0 ? 0 : schedule.ends[wave - 1]));
    return schedule.waveOf;
}

/// Fails unless the waves of a colour-ordered list are its colours, contact by contact: the k-th
/// contact of the list in wave c exactly when it is in colour c (contact_colours.hpp; the appendix,
/// section 6, proves it). @p colours is what orderByColour() returned, @p colourSizes its contacts per colour.
void requireWavesAreColours(const std::vector<std::uint32_t>& waveOf, std::uint32_t colours,
                            const std::vector<std::size_t>& colourSizes) {
    std::size_t k = 0;
    for (std::uint32_t colour = 0; colour < colours; ++colour)
        for (std::size_t n = 0; n < colourSizes[colour]; ++n, ++k)
            if (waveOf[k] != colour) throw FigureError("a colour-ordered list's waves are not its colours");
}

/// @p solver's two lists (the round contacts, then the others: the plain pass solves them in that
/// order) put in waves in their current order, with how many contacts sit in waves the threads would
/// split. The other list's waves are solved in lanes, and split, only when they hold
/// kMinBoxContactsPerWave contacts on average (batchBoxContacts()).
Waves bothLists(const SolverWorkspace& solver) {
    Waves result;
    std::vector<std::size_t> other;
    wavesOf(solver, solver.roundContacts, result.sizes);
    wavesOf(solver, solver.otherContacts, other);
    const double boxes = double(solver.otherContacts.size());
    result.boxContactsPerWave = other.empty() ? 0.0 : boxes / double(other.size());
    result.boxesInLanes = !other.empty() && boxes >= kMinBoxContactsPerWave * double(other.size());
    for (const std::size_t size : result.sizes)
        if (wideEnoughToSplit(size)) result.splitContacts += size;
    for (const std::size_t size : other)
        if (result.boxesInLanes && wideEnoughToSplit(size)) result.splitContacts += size;
    result.sizes.insert(result.sizes.end(), other.begin(), other.end());
    return result;
}

/// Contacts per colour of a list orderByColour() has just reordered (its scratch colourOf holds each
/// contact's colour, by its place in the list before).
std::vector<std::size_t> colourSizes(const SolverWorkspace& solver, std::uint32_t colours) {
    std::vector<std::size_t> sizes(colours, 0);
    for (const std::uint32_t colour : solver.colouring.colourOf) ++sizes[colour];
    return sizes;
}

/// Four scenes at step @p step of their default run: the same contacts in the two orders a pass can
/// take them, and the fast path's waves of each. `ContactOrder=Found`: the order the narrowphase found
/// them; `ContactOrder=Colours`: orderByColour()'s, whose waves are checked to be its colours. First
/// block: one line per scene; then one block per scene: per wave, its contacts in each order.
int colours(std::uint64_t step) {
    struct SceneOfFigure {
        const char* label;
        const char* file;
    };
    const SceneOfFigure scenes[] = {{"pyramid", "lesson08_pyramid.scene"},
                                    {"tower", "lesson08_tower.scene"},
                                    {"box-pile-1k", "bench_box_pile_1k.scene"},
                                    {"rain-1k", "bench_sphere_rain_1k.scene"}};
    std::vector<Waves> found, coloured;
    std::printf("# step %llu; a wave of at least %zu batches of %d (%zu contacts) is split between threads;\n",
                static_cast<unsigned long long>(step), kParallelWaveBatches, kLanes, kParallelWaveBatches * kLanes);
    std::printf("# box contacts go in lanes when their waves hold %.0f on average\n", double(kMinBoxContactsPerWave));
    std::printf("# scene round-contacts box-contacts waves-found waves-colours split-found split-colours "
                "box-contacts-per-wave-found box-contacts-per-wave-colours boxes-in-lanes-found boxes-in-lanes-colours\n");
    for (const SceneOfFigure& scene : scenes) {
        SolverWorkspace solver = contactsAtStep(scene.file, step);
        found.push_back(bothLists(solver));
        // The same lists in colour order; the waves of each list must be its colours.
        for (std::vector<std::uint32_t>* list : {&solver.roundContacts, &solver.otherContacts}) {
            std::vector<std::uint32_t> colourEnds;
            const std::uint32_t colours = orderByColour(solver, *list, colourEnds);
            const std::vector<std::size_t> sizes = list->size() < 2 ? std::vector<std::size_t>(colours, 1)
                                                                    : colourSizes(solver, colours);
            std::vector<std::size_t> waveSizes;
            requireWavesAreColours(wavesOf(solver, *list, waveSizes), colours, sizes);
        }
        coloured.push_back(bothLists(solver));
        const auto lanes = [&](const Waves& w) { return solver.otherContacts.empty() ? "-" : (w.boxesInLanes ? "yes" : "no"); };
        std::printf("%s %zu %zu %zu %zu %zu %zu %.2f %.2f %s %s\n", scene.label, solver.roundContacts.size(),
                    solver.otherContacts.size(), found.back().sizes.size(), coloured.back().sizes.size(),
                    found.back().splitContacts, coloured.back().splitContacts, found.back().boxContactsPerWave,
                    coloured.back().boxContactsPerWave, lanes(found.back()), lanes(coloured.back()));
    }
    for (std::size_t s = 0; s < found.size(); ++s) {
        std::printf("\n\n# %s: wave contacts-in-wave-found contacts-in-wave-colours\n", scenes[s].label);
        const std::size_t n = std::max(found[s].sizes.size(), coloured[s].sizes.size());
        for (std::size_t k = 0; k < n; ++k)
            std::printf("%zu %zu %zu\n", k, k < found[s].sizes.size() ? found[s].sizes[k] : 0,
                        k < coloured[s].sizes.size() ? coloured[s].sizes[k] : 0);
    }
    return 0;
}

// ------------------------------------------------------------------ lecture 10

/// lesson10_gjk.scene, the narrowphase of step 1: GJK on spike–table and can–table, with the
/// simplex recorded after every iteration (gjk()'s record). For each iteration: |v|, the upper
/// bound on the distance, and v·w/|v|, the lower bound, with w = s(−v) the support point the next
/// iteration asks for (gjk.hpp, step 3). Both bounds must close on the gap worked out by hand from
/// where the step left each body: the spike's lowest vertex is 0.3 m below its centre, the can's
/// lowest rim point 0.2·cos 60° + 0.2·sin 60° below its centre, the table's top at y = 1.
/// Distances of the cores, m (neither shape has a margin).
int gjkBounds() {
    World world = loadWorld("lesson10_gjk.scene");
    const Real canReach = Real(0.2) * std::cos(kPi / 3) + Real(0.2) * std::sin(kPi / 3);
    int printed = 0;
    StageWatcher watcher(Stage::Narrowphase, [&](const StageEvent&, const World& w) {
        const Geometry table = geometryOf(w.kinematics()[0]);
        const Real tableTop = table.centre.y + table.halfExtents.y;
        for (const char* name : {"spike", "can"}) {
            const DynamicObject& body = w.dynamics()[dynamicIndex(w, name)];
            const Real below = std::string(name) == "spike" ? Real(0.3) : canReach;
            const Real gap = body.position.y - below - tableTop;
            const ConvexShape a = convexShapeOf(geometryOf(body));
            const ConvexShape b = convexShapeOf(table);
            std::vector<Simplex> record;
            const GjkResult result = gjk(a, b, &record);
            if (result.overlap || std::abs(double(result.distance - gap)) > 1e-9)
                throw FigureError(std::string("GJK's distance for ") + name + " is not the gap worked out by hand");
            if (printed++ > 0) std::printf("\n\n");
            std::printf("# %s|table, step 1: gap by hand %.9f m; GJK %.9f m in %d support queries\n", name, double(gap),
                        double(result.distance), result.iterations);
            std::printf("# iteration simplex-points upper=|v| lower=v.w/|v| (m)\n");
            for (std::size_t i = 0; i < record.size(); ++i) {
                const Vec3 v = record[i].closest;
                const Vec3 wPoint = coreSupport(a, -v) - coreSupport(b, v);
                const Real length = glm::length(v);
                std::printf("%zu %d %.12f %.12f\n", i + 1, record[i].count, double(length),
                            double(glm::dot(v, wPoint) / length));
            }
        }
        return true;
    });
    stepUntil(world, watcher, 1);
    return 0;
}

// ------------------------------------------------------------------ lecture 11

/// A flat box (0.4 × 0.2 × 0.4 m) sunk 5 cm into the top of lesson 11's table (2 × 1 × 2 m, top at
/// y = 1), slid along x from the middle to past the table's edge: the depth and the normal's y that
/// SAT (collideBoxBox), GJK+EPA and MPR give at each offset. By hand, the least overlap is
/// min(0.05, 1.2 − x) (the top face, or the side face x = 1 once the box hangs over), and MPR's
/// ray from the centres' difference v₀ = (x, 0.55, 0) to the origin leaves A − B through its
/// bottom face while x·0.05/0.55 < 1.2 − x, through its side face after.
int mprDepth() {
    const Real sunk = Real(0.05);
    Geometry table;
    table.type = GeometryType::Box;
    table.centre = Vec3(0, 0.5, 0);
    table.halfExtents = Vec3(1, 0.5, 1);
    Geometry brick = table;
    brick.halfExtents = Vec3(0.2, 0.1, 0.2);
    std::printf("# x (m)  least-overlap-by-hand  SAT-depth SAT-ny  EPA-depth EPA-ny  MPR-depth MPR-ny  MPR-by-hand (m)\n");
    constexpr int kSamples = 240;
    for (int i = 0; i <= kSamples; ++i) {
        const Real x = Real(0.8) + Real(0.39) * Real(i) / Real(kSamples);  // from 0.8 m to 1 cm short of falling off
        brick.centre = Vec3(x, 1 + brick.halfExtents.y - sunk, 0);
        const Real reachX = table.halfExtents.x + brick.halfExtents.x - x;  // overlap along x
        const Real least = std::min(sunk, reachX);
        const Real centresY = brick.centre.y - table.centre.y;
        const Real mprByHand = x * sunk / centresY < reachX ? sunk : reachX;
        ContactManifold sat;
        if (!collideBoxBox(brick, table, sat)) throw FigureError("SAT finds no contact");
        const ConvexShape a = convexShapeOf(brick), b = convexShapeOf(table);
        const GjkResult g = gjk(a, b);
        const EpaResult e = g.overlap ? epa(a, b, g.simplex) : EpaResult{};
        const MprResult m = mpr(a, b);
        if (!e.valid || !m.overlap) throw FigureError("EPA or MPR finds no overlap");
        Real satDepth = 0;
        for (int p = 0; p < sat.pointCount; ++p) satDepth = std::max(satDepth, sat.points[p].depth);
        if (std::abs(double(e.depth - least)) > 1e-6 || std::abs(double(satDepth - least)) > 1e-6)
            throw FigureError("SAT or EPA's depth is not the least overlap worked out by hand");
        if (std::abs(double(m.depth - mprByHand)) > 1e-6) throw FigureError("MPR's depth is not the face its ray leaves by");
        std::printf("%.6f %.9f %.9f %.6f %.9f %.6f %.9f %.6f %.9f\n", double(x), double(least), double(satDepth),
                    double(sat.normal.y), double(e.depth), double(e.normal.y), double(m.depth), double(m.normal.y),
                    double(mprByHand));
    }
    return 0;
}

int usage() {
    std::fprintf(stderr, "usage: stepwise-figures impulse-geometry | bounce-impulses | sat-axes | clipping | "
                         "waves [STEP] | colours [STEP] | gjk-bounds | mpr-depth\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) return usage();
    const std::string command = argv[1];
    try {
        if (command == "impulse-geometry" && argc == 2) return impulseGeometry();
        if (command == "bounce-impulses" && argc == 2) return bounceImpulses();
        if (command == "sat-axes" && argc == 2) return satAxes();
        if (command == "clipping" && argc == 2) return clipping();
        if (command == "gjk-bounds" && argc == 2) return gjkBounds();
        if (command == "mpr-depth" && argc == 2) return mprDepth();
        if (command == "waves" && argc <= 3) {
            const long step = argc == 3 ? std::strtol(argv[2], nullptr, 10) : 120;
            if (step < 1) return usage();
            return waves(static_cast<std::uint64_t>(step));
        }
        if (command == "colours" && argc <= 3) {
            const long step = argc == 3 ? std::strtol(argv[2], nullptr, 10) : 300;
            if (step < 1) return usage();
            return colours(static_cast<std::uint64_t>(step));
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "stepwise-figures %s: %s\n", command.c_str(), error.what());
        return 1;
    }
    return usage();
}
