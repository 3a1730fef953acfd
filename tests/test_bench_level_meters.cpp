// The meters of the side-by-side scenes of issue #33 (bench/overlap_depth.cpp,
// bench/pile_metrics.cpp, bench/joint_metrics.cpp) and their scenes
// (bench/box_pile_scene.cpp, config/bench_chain.scene, config/bench_ragdoll.scene).
// The accuracy columns of docs/benchmarks.md's Bullet section come from these
// meters, for both engines, so each is checked against geometry worked out by
// hand. Tag: [bench].
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "box_pile_scene.hpp"
#include "config/scene_loader.hpp"
#include "joint_metrics.hpp"
#include "overlap_depth.hpp"
#include "pile_metrics.hpp"
#include "scenario_metrics.hpp"

using namespace stepwise;
using namespace stepwise::bench;

namespace {

constexpr Real kTight = Real(1e-9);  // a few exact operations on doubles, and one quaternion rotation
/// The shipped scenes print positions with 4 decimals: each coordinate is off by up to
/// 5e-5 m, a point built from two of them by at most 2·√3·5e-5 = 1.7e-4 m.
constexpr Real kFourDecimals = Real(2e-4);
constexpr Real kPiHere = Real(3.14159265358979323846);
const Real kHalfDiagonal = std::sqrt(Real(2)) / 2;  // a unit square's corner from its centre, m

Quat about(const Vec3& axis, Real degrees) { return glm::angleAxis(degrees * kPiHere / 180, glm::normalize(axis)); }

OrientedBox unitBox(const Vec3& centre, const Quat& turn = Quat(1, 0, 0, 0)) {
    return {centre, turn, Vec3(0.5, 0.5, 0.5)};
}

BodyState at(const Vec3& position, const Quat& orientation = Quat(1, 0, 0, 0)) {
    BodyState s;
    s.position = position;
    s.orientation = orientation;
    return s;
}

std::vector<BodyState> startOf(const Scene& scene) {
    std::vector<BodyState> states;
    for (const DynamicObject& b : scene.dynamics) states.push_back(at(b.position, b.orientation));
    return states;
}

}  // namespace

TEST_CASE("signedDistance and sphereBoxOverlap measure from the nearest face, edge or corner", "[bench]") {
    const OrientedBox box = unitBox({0, 0, 0});
    CHECK(signedDistance({1.3, 0, 0}, box) == Approx(0.8).margin(kTight));         // off a face
    CHECK(signedDistance({1.5, 1.5, 0}, box) == Approx(std::sqrt(2.0)).margin(kTight));  // off an edge: (1, 1, 0) away
    CHECK(signedDistance({0.3, 0.1, 0}, box) == Approx(-0.2).margin(kTight));      // inside: nearest face 0.2 away
    CHECK(sphereBoxOverlap({0.9, 0, 0}, 0.5, box) == Approx(0.1).margin(kTight));
    CHECK(sphereBoxOverlap({1.3, 0, 0}, 0.5, box) == Approx(-0.3).margin(kTight));
    // Turned 45° about z, the box's edge points along x, √2/2 from the centre.
    const OrientedBox diamond = unitBox({0, 0, 0}, about({0, 0, 1}, 45));
    CHECK(sphereBoxOverlap({1, 0, 0}, 0.5, diamond) == Approx(0.5 - (1 - kHalfDiagonal)).margin(kTight));
}

TEST_CASE("boxBoxOverlap is the least overlap of the two boxes' shadows over the 15 axes", "[bench]") {
    CHECK(boxBoxOverlap(unitBox({0, 0, 0}), unitBox({0.9, 0, 0})) == Approx(0.1).margin(kTight));
    CHECK(boxBoxOverlap(unitBox({0, 0, 0}), unitBox({0.2, 0.95, 0})) == Approx(0.05).margin(kTight));
    CHECK(boxBoxOverlap(unitBox({0, 0, 0}), unitBox({1.5, 0, 0})) == Approx(-0.5).margin(kTight));
    // A diamond's edge into a face: its edge reaches √2/2 along x.
    CHECK(boxBoxOverlap(unitBox({0, 0, 0}), unitBox({1.1, 0, 0}, about({0, 0, 1}, 45))) ==
          Approx(0.5 + kHalfDiagonal - 1.1).margin(kTight));
    // Edge against edge: A turned 45° about z, B 45° about x, B above A. A's top edge
    // (along z) and B's bottom edge (along x) cross; each reaches √2/2 along y, so the
    // depth is √2 − d, found on the cross-product axis y = z × x, not on a face normal
    // (along every face normal of either box the shadows overlap by 0.43 m or more).
    const OrientedBox a = unitBox({0, 0, 0}, about({0, 0, 1}, 45));
    const OrientedBox b = unitBox({0, 1.3, 0}, about({1, 0, 0}, 45));
    CHECK(boxBoxOverlap(a, b) == Approx(2 * kHalfDiagonal - 1.3).margin(kTight));
}

TEST_CASE("RainMeter measures spheres against walls of static boxes and counts those that left the level", "[bench]") {
    // A floor slab whose top is y = 0, and one wall on it.
    const std::vector<OrientedBox> walls{{{5, -0.5, 5}, Quat(1, 0, 0, 0), {5, 0.5, 5}},
                                         {{-0.5, 2, 5}, Quat(1, 0, 0, 0), {0.5, 2, 5}}};
    RainMeter meter({}, Real(0.5), walls);
    const std::vector<BodyState> spheres{at({5, 0.495, 5}), at({0.47, 2, 3})};  // 5 mm into the floor, 3 cm into the wall
    meter.observe(spheres);
    CHECK(meter.worstOverlap() == Approx(0.03).margin(kTight));
    CHECK(meter.escaped(spheres) == 0);
    const std::vector<BodyState> gone{at({5, -20, 5}), at({-0.5, 2, 5}), at({5, 1, 5})};  // fell out; in the wall; inside
    CHECK(meter.escaped(gone) == 2);
}

TEST_CASE("BoxPileMeter finds the deepest box-box and box-wall overlap, and boxes that left", "[bench]") {
    // A floor whose top is y = 0 and one wall 10 m high: the level reaches from y = -1 to 10.
    const std::vector<OrientedBox> level{{{0, -0.5, 0}, Quat(1, 0, 0, 0), {10, 0.5, 10}},
                                         {{-10.5, 5, 0}, Quat(1, 0, 0, 0), {0.5, 5, 10}}};
    std::vector<Vec3> half(4, Vec3(0.5, 0.5, 0.5));
    BoxPileMeter meter(half, level);
    // Two boxes 0.1 m into each other, one 2 cm into the floor, one far from all.
    std::vector<BodyState> boxes{at({0, 3, 0}), at({0.9, 3, 0}), at({4, 0.48, 0}), at({-6, 0.5, 0})};
    meter.observe(boxes);
    CHECK(meter.worstBoxOverlap() == Approx(0.1).margin(kTight));
    CHECK(meter.worstWallOverlap() == Approx(0.02).margin(kTight));
    // The worst is kept; the last step's is its own.
    boxes[1] = at({1.5, 3, 0});
    boxes[2] = at({4, 0.5, 0});
    meter.observe(boxes);
    CHECK(meter.worstBoxOverlap() == Approx(0.1).margin(kTight));
    CHECK(meter.lastBoxOverlap() == Approx(0).margin(kTight));  // no pair overlaps now (apart counts as 0)
    CHECK(meter.escaped(boxes) == 0);
    boxes[3] = at({-6, -30, 0});
    CHECK(meter.escaped(boxes) == 1);
    boxes[0].velocity = Vec3(0, -0.3, 0.4);
    CHECK(largestSpeed(boxes) == Approx(0.5).margin(kTight));
}

TEST_CASE("JointMeter: 0 for a joint whose anchors coincide, d for anchors d apart, a hinge's axis angle", "[bench]") {
    Scene scene = parseScene("DynamicObject, Name=a, Shape=Box, Position=(0, 2, 0)\n"
                             "DynamicObject, Name=b, Shape=Box, Position=(0, 1, 0)\n"
                             "BallJoint, Name=top, BodyA=a, Anchor=(0, 2.5, 0)\n"
                             "HingeJoint, Name=knee, BodyA=b, BodyB=a, Anchor=(0, 1.5, 0), Axis=(1, 0, 0)\n",
                             "joints");
    JointMeter meter(scene);
    REQUIRE(meter.jointCount() == 2);
    std::vector<BodyState> bodies = startOf(scene);
    meter.observe(bodies);
    CHECK(meter.worstSeparation() == Approx(0).margin(kTight));
    CHECK(meter.worstAxisAngle() == Approx(0).margin(kTight));
    // b turns about the hinge point by 30° about the hinge axis: a free turn, no error.
    const Quat turn = about({1, 0, 0}, 30);
    bodies[1] = at(Vec3(0, 1.5, 0) + turn * Vec3(0, -0.5, 0), turn);
    meter.observe(bodies);
    CHECK(meter.worstSeparation() == Approx(0).margin(kTight));
    CHECK(meter.worstAxisAngle() == Approx(0).margin(kTight));
    // b slides down by d = 7 mm and tilts 10° about z: the gap is d, the axes 10° apart.
    const Real d = Real(0.007);
    bodies[1] = at(Vec3(0, 1 - d, 0), about({0, 0, 1}, 10));
    meter.observe(bodies);
    CHECK(meter.lastSeparation() == Approx(glm::length(about({0, 0, 1}, 10) * Vec3(0, 0.5, 0) - Vec3(0, 0.5 + d, 0)))
                                        .margin(kTight));
    CHECK(meter.worstAxisAngle() == Approx(10 * kPiHere / 180).margin(kTight));
    // a drops by d from its fixed point: the world joint's gap is d.
    bodies = startOf(scene);
    bodies[0].position.y -= d;
    bodies[1].position.y -= d;
    JointMeter fresh(scene);
    fresh.observe(bodies);
    CHECK(fresh.worstSeparation() == Approx(d).margin(kTight));
    CHECK(fresh.worstStretch() == Approx(d).margin(kTight));  // the hinge still holds: only one gap
}

TEST_CASE("mechanicalEnergy sums ½·m·v², ½·ω·L and −m·g·x", "[bench]") {
    const Scene scene = parseScene("World, Gravity=(0, -10, 0)\nDynamicObject, Name=a, Position=(0, 3, 0), Mass=2\n", "e");
    BodyState s = at({0, 3, 0});
    s.velocity = {1, 0, 0};
    s.angularVelocity = {0, 2, 0};
    s.angularMomentum = {0, 0.5, 0};
    const std::vector<BodyState> bodies{s};
    CHECK(mechanicalEnergy(bodies, scene) == Approx(0.5 * 2 * 1 + 0.5 * 2 * 0.5 + 2 * 10 * 3).margin(kTight));
}

TEST_CASE("The box pile starts with no box touching another or a wall, all inside", "[bench]") {
    constexpr std::size_t kBoxes = 300;
    const Scene scene = parseScene(boxPileSceneText(kBoxes, 1), "pile");
    REQUIRE(scene.dynamics.size() == kBoxes);
    REQUIRE(scene.kinematics.size() == 5);
    BoxPileMeter meter(boxHalfExtentsOf(scene), staticBoxesOf(scene));
    const std::vector<BodyState> start = startOf(scene);
    meter.observe(start);
    CHECK(meter.lastBoxOverlap() == 0);    // apart counts as 0: a positive figure is a real overlap
    CHECK(meter.worstWallOverlap() == 0);
    CHECK(meter.escaped(start) == 0);
}

TEST_CASE("The shipped chain and ragdoll hold every joint at the start, the ragdoll 1 m above its floor", "[bench]") {
    for (const char* file : {"/config/bench_chain.scene", "/config/bench_ragdoll.scene"}) {
        const Scene scene = loadSceneFile(std::string(STEPWISE_SOURCE_DIR) + file);
        JointMeter meter(scene);
        meter.observe(startOf(scene));
        INFO(file);
        CHECK(meter.jointCount() == scene.joints.size());
        CHECK(meter.worstSeparation() < kFourDecimals);
        CHECK(meter.worstAxisAngle() < kFourDecimals);
    }
    const Scene ragdoll = loadSceneFile(std::string(STEPWISE_SOURCE_DIR) + "/config/bench_ragdoll.scene");
    CHECK(ragdoll.dynamics.size() == 20);
    BoxPileMeter floor(boxHalfExtentsOf(ragdoll), staticBoxesOf(ragdoll));
    floor.observe(startOf(ragdoll));
    CHECK(floor.lastWallOverlap() == Approx(0).margin(kTight));  // kept at 0 when every box is above
}

TEST_CASE("A body at NaN counts as an infinite gap and overlap, not as none", "[bench]") {
    const Scene scene = parseScene("DynamicObject, Name=a, Shape=Box, Position=(0, 2, 0)\n"
                                   "BallJoint, Name=top, BodyA=a, Anchor=(0, 2.5, 0)\n",
                                   "nan");
    JointMeter joints(scene);
    std::vector<BodyState> bodies = startOf(scene);
    bodies[0].position.x = std::numeric_limits<Real>::quiet_NaN();
    joints.observe(bodies);
    CHECK(std::isinf(joints.worstSeparation()));
    BoxPileMeter pile(boxHalfExtentsOf(scene), {});
    pile.observe(bodies);
    CHECK(std::isinf(pile.worstBoxOverlap()));
}
