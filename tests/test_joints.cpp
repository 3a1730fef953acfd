// Joints of the sequential-impulse solver, against the physics they model.
// Tags: [joints] (and [solver] for Newton's cradle, [config] for the scene records).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "command_runner.hpp"
#include "config/scene_loader.hpp"
#include "dynamics/joints/joint_parts.hpp"
#include "objects/inertia.hpp"
#include "test_support.hpp"
#include "world/measurements.hpp"

using namespace stepwise;
using Catch::Matchers::Contains;

namespace {

constexpr Real g = kStandardGravity;

/// A joint of @p kind from @p bodyA to @p bodyB ("" = the world), anchors in world space.
JointDef makeDef(JointKind kind, const std::string& name, const std::string& bodyA, const std::string& bodyB,
                 Vec3 anchorA, Vec3 anchorB = Vec3(0)) {
    JointDef def;
    def.kind = kind;
    def.name = name;
    def.bodyA = bodyA;
    def.bodyB = bodyB;
    def.anchorA = anchorA;
    def.anchorB = anchorB;
    return def;
}

/// A scene for the sequential-impulse solver (the default) with gravity @p gravity.
Scene solverScene(Vec3 gravity = Vec3(0, -g, 0)) {
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60, gravity);
    scene.settings.solver = SolverKind::SequentialImpulse;
    return scene;
}

/// Steps @p world until its clock reaches @p seconds (to the nearest step).
void runFor(World& world, Real seconds) {
    const auto steps = static_cast<int>(std::llround(seconds / world.settings().timeStep));
    for (int i = 0; i < steps; ++i) world.step();
}

/// A hinge from @p body to the world at its centre about world axis @p axis.
JointDef hingeAtCentre(const DynamicObject& body, Vec3 axis) {
    JointDef def = makeDef(JointKind::Hinge, "hinge", body.name, "", body.position);
    def.axis = axis;
    return def;
}

}  // namespace

// ------------------------------------------------------------------ distance joint

TEST_CASE("A pendulum on a DistanceJoint keeps its period and its length", "[joints]") {
    // A point bob (the rod is anchored at its centre, so nothing turns it) on
    // a massless 1 m rod, released from rest at 5 degrees. Small-angle period
    // T0 = 2 pi sqrt(L/g); at amplitude theta0 the exact period is
    // T = T0 (1 + theta0^2/16 + 11 theta0^4/3072 + ...) (the series of the
    // complete elliptic integral), here T0 * 1.000476.
    const Real L = 1;
    const Real theta0 = Real(5) * kPi / 180;
    const Vec3 pivot(0, 2, 0);
    Scene scene = solverScene();
    scene.dynamics.push_back(test::sphere("bob", pivot + L * Vec3(std::sin(theta0), -std::cos(theta0), 0), Vec3(0),
                                          Real(0.05), Real(1)));
    const DynamicObject& start = scene.dynamics[0];
    scene.joints.push_back(makeDef(JointKind::Distance, "rod", "bob", "", start.position, pivot));
    World world(scene);
    const DynamicObject& bob = world.dynamics()[0];

    const Real T0 = 2 * kPi * std::sqrt(L / g);
    const Real expected = T0 * (1 + theta0 * theta0 / 16 + 11 * std::pow(theta0, 4) / 3072);
    constexpr int kPeriods = 10;
    std::vector<Real> upwardCrossings;  // times x goes from - to + (one per period)
    Real largestLengthError = 0;
    Real previousX = bob.position.x - pivot.x;
    while (upwardCrossings.size() < kPeriods + 1 && world.time() < Real(kPeriods + 3) * T0) {
        world.step();
        const Real x = bob.position.x - pivot.x;
        if (previousX < 0 && x >= 0) {
            // Linear interpolation inside the step for the moment x = 0.
            const Real h = world.settings().timeStep;
            upwardCrossings.push_back(world.time() - h * x / (x - previousX));
        }
        previousX = x;
        largestLengthError = std::max(largestLengthError, std::abs(glm::length(bob.position - pivot) - L));
    }
    REQUIRE(upwardCrossings.size() == kPeriods + 1);
    const Real measured = (upwardCrossings.back() - upwardCrossings.front()) / kPeriods;
    INFO("T0 = " << T0 << " s, expected T = " << expected << " s, measured " << measured << " s; length off by at most "
                  << largestLengthError * 1000 << " mm");
    CHECK(std::abs(measured - expected) / expected < 0.005);
    CHECK(largestLengthError < 0.001);
    CHECK(measureJoint(world.joints()[0], world.dynamics()).distance < 0.001);
}

TEST_CASE("A soft rod gives way like a spring of JointHertz: a hanging weight stretches it by g/(2 pi f)^2",
          "[joints]") {
    // At rest the soft constraint's leak s_i * lambda balances its bias
    // s_m * m * b * C (softness.hpp), which works out to a spring of
    // stiffness m_eff * w^2, w = 2 pi f: a weight m g on a rod fixed to the
    // world (m_eff = m along the rod) stretches it by g / w^2, whatever the mass.
    for (const Real hertz : {Real(60), Real(15)}) {
        Scene scene = solverScene();
        scene.settings.jointHertz = hertz;
        scene.settings.sleeping = false;  // a sleeping body would hide the spring
        const Vec3 pivot(0, 2, 0);
        scene.dynamics.push_back(test::sphere("weight", pivot - Vec3(0, 1, 0), Vec3(0), Real(0.1), Real(7)));
        scene.joints.push_back(makeDef(JointKind::Distance, "rod", "weight", "", pivot - Vec3(0, 1, 0), pivot));
        World world(scene);
        runFor(world, 3);  // damping ratio 2: settled long before
        const Real omega = 2 * kPi * jointHertzInUse(world.settings());
        const Real stretch = measureJoint(world.joints()[0], world.dynamics()).distance;
        INFO(hertz << " Hz: stretched " << stretch * 1000 << " mm, g / w^2 = " << g / (omega * omega) * 1000 << " mm");
        CHECK(stretch == Approx(g / (omega * omega)).epsilon(0.01));
    }
}

// ------------------------------------------------------------------ rope

TEST_CASE("A slack rope exerts nothing: the body falls freely until the rope is taut", "[joints]") {
    // A ball 1 m below the anchor on a 2 m rope falls 1 m freely (v = -g t,
    // exact for the sub-stepped symplectic Euler), is caught, and then hangs
    // with the rope at most L * 1.001 long.
    const Vec3 anchor(0, 3, 0);
    const Real L = 2;
    Scene scene = solverScene();
    scene.dynamics.push_back(test::sphere("ball", anchor - Vec3(0, 1, 0), Vec3(0), Real(0.1), Real(1)));
    JointDef rope = makeDef(JointKind::Rope, "rope", "ball", "", anchor - Vec3(0, 1, 0), anchor);
    rope.length = L;
    scene.joints.push_back(rope);
    World world(scene);
    const DynamicObject& ball = world.dynamics()[0];

    // Taut when the ball has fallen 1 m: t = sqrt(2/g) ≈ 0.45 s.
    const Real tautTime = std::sqrt(Real(2) / g);
    int slackSteps = 0;
    Real longest = 0;
    while (world.time() < 3) {
        world.step();
        const Real length = glm::length(ball.position - anchor);
        longest = std::max(longest, length);
        if (world.time() < tautTime - world.settings().timeStep) {
            ++slackSteps;
            CHECK(ball.velocity.y == Approx(-g * world.time()).epsilon(1e-12));
            CHECK(world.joints()[0].axialImpulse == 0);
        }
    }
    INFO("longest " << longest << " m for L = " << L << " m");
    CHECK(slackSteps > 20);
    CHECK(longest <= L * 1.001);
    // Hanging at rest, taut.
    CHECK(glm::length(ball.position - anchor) == Approx(L).margin(0.001));
    CHECK(glm::length(ball.velocity) < 0.01);
}

TEST_CASE("A rope pulls but never pushes: a body thrown towards the anchor passes freely", "[joints]") {
    Scene scene = solverScene(Vec3(0));
    const Vec3 anchor(0, 0, 0);
    scene.dynamics.push_back(test::sphere("ball", Vec3(1, 0, 0), Vec3(-2, 0, 0), Real(0.1), Real(1)));
    scene.joints.push_back(makeDef(JointKind::Rope, "rope", "ball", "", Vec3(1, 0, 0), anchor));
    World world(scene);
    runFor(world, Real(0.5));  // passes the anchor at t = 0.5 s, 1 m from its start, never taut
    CHECK(world.dynamics()[0].velocity.x == Approx(-2).epsilon(1e-12));
    CHECK(world.dynamics()[0].position.x == Approx(0).margin(1e-9));
}

// ------------------------------------------------------------------ ball joint

TEST_CASE("A ball joint's K built from its six entries is J M^-1 J^T, and its symmetric solve inverts it", "[joints]") {
    // Two boxes' world inverse inertias R I^-1 R^T (turned, so that every entry is non-zero) and
    // lever arms of both signs. The definition, with [r]x = skew(r) and E the identity:
    //   K = (1/m_A + 1/m_B) E - [r_A]x I_A^-1 [r_A]x - [r_B]x I_B^-1 [r_B]x.
    // leverArmTerm() writes each term out entry by entry, solveSymmetric() solves K x = b by the
    // adjugate. Entries are of order 1 (1/kg, m), so both must agree with the matrix products to
    // round-off: a few dozen operations, within 64 epsilon.
    const Real tolerance = 64 * std::numeric_limits<Real>::epsilon();
    const Mat3 inverseInertiaA = worldInverseInertia(glm::angleAxis(Real(0.7), glm::normalize(Vec3(1, 2, 3))),
                                                     Vec3(Real(1) / 2, Real(1) / 3, Real(1) / 5));
    const Mat3 inverseInertiaB = worldInverseInertia(glm::angleAxis(Real(-1.9), glm::normalize(Vec3(-2, 1, 1))),
                                                     Vec3(Real(4), Real(1) / 7, Real(1) / 2));
    const Vec3 rA(Real(0.3), Real(-0.7), Real(1.1));
    const Vec3 rB(Real(-0.4), Real(0.2), Real(0.9));
    const Real inverseMasses = Real(1) / 2 + Real(1) / 3;
    const Mat3 expected = inverseMasses * Mat3(1) - skew(rA) * inverseInertiaA * skew(rA) -
                          skew(rB) * inverseInertiaB * skew(rB);

    SymmetricMat3 K = leverArmTerm(symmetricPart(inverseInertiaA), rA) + leverArmTerm(symmetricPart(inverseInertiaB), rB);
    K.xx += inverseMasses;
    K.yy += inverseMasses;
    K.zz += inverseMasses;
    const Real entries[3][3] = {{K.xx, K.xy, K.xz}, {K.xy, K.yy, K.yz}, {K.xz, K.yz, K.zz}};
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column) {
            INFO("row " << row << ", column " << column);
            CHECK(std::abs(entries[row][column] - expected[column][row]) < tolerance);
        }
    }

    const Vec3 b(1, -2, Real(0.5));
    Vec3 x(0);
    REQUIRE(solveSymmetric(K, b, x));
    CHECK(glm::length(expected * x - b) < tolerance * glm::length(b));
    // K of two bodies that cannot move (no mass, no inertia) is zero: there is nothing to solve.
    CHECK_FALSE(solveSymmetric(SymmetricMat3{}, b, x));
}

TEST_CASE("A ball joint holds its anchor within 1 mm under a swinging, spinning load", "[joints]") {
    // A 5 kg cube of 0.4 m hangs by one corner from a fixed point, released
    // with its centre 60 degrees out and spinning about the vertical.
    // Estimate: a soft joint of frequency f gives way like a spring,
    // by about a/(2 pi f)^2 under an acceleration a of the load; here a <= 2 g at the
    // bottom of the swing: 0.14 mm at 60 Hz.
    Scene scene = solverScene();
    const Vec3 pivot(0, 3, 0);
    const Real angle = Real(60) * kPi / 180;
    const Vec3 out(std::sin(angle), -std::cos(angle), 0);
    const Real halfDiagonal = std::sqrt(Real(3)) * Real(0.2);
    DynamicObject cube = test::dynamicBox("cube", pivot + halfDiagonal * out, Vec3(0.4), 5, 0.5);
    // Turn the cube so that its corner (-1, 1, -1) points back at the pivot.
    const Vec3 corner = glm::normalize(Vec3(-1, 1, -1));
    const Vec3 turnAxis = glm::normalize(glm::cross(corner, -out));
    cube.orientation = glm::angleAxis(std::acos(glm::dot(corner, -out)), turnAxis);
    cube.angularVelocity = Vec3(0, 3, 0);
    cube.velocity = glm::cross(cube.angularVelocity, halfDiagonal * out);
    scene.dynamics.push_back(cube);
    scene.joints.push_back(makeDef(JointKind::Ball, "socket", "cube", "", pivot));
    World world(scene);
    REQUIRE(glm::length(jointAnchors(world.joints()[0], world.dynamics()).onA - pivot) < 1e-12);
    Real worst = 0;
    Real lowest = pivot.y;
    while (world.time() < 5) {
        world.step();
        const JointAnchors anchors = jointAnchors(world.joints()[0], world.dynamics());
        worst = std::max(worst, glm::length(anchors.onB - anchors.onA));
        lowest = std::min(lowest, world.dynamics()[0].position.y);
    }
    INFO("largest anchor separation " << worst * 1000 << " mm");
    CHECK(worst < 0.001);
    CHECK(lowest < pivot.y - halfDiagonal * std::cos(angle) - Real(0.1));  // it did swing down
}

TEST_CASE("A ball joint between two free bodies is an internal force: momentum is kept", "[joints]") {
    // A dumbbell in zero gravity: two balls joined at the point between them,
    // thrown spinning. The joint's impulses are equal and opposite, so the
    // total momentum stays exactly what it was, and the angular momentum
    // nearly so (the two anchors are apart by the joint's tiny error).
    // The start satisfies the joint: both anchors (at the origin) move at
    // V = (0.3, 0, 0.5), i.e. v = V - w x r for each ball.
    Scene scene = solverScene(Vec3(0));
    const Vec3 V(0.3, 0, 0.5);
    DynamicObject left = test::sphere("left", Vec3(-0.5, 0, 0), Vec3(0), Real(0.2), Real(1));
    left.angularVelocity = Vec3(0, 3, 4);
    left.velocity = V - glm::cross(left.angularVelocity, Vec3(0.5, 0, 0));
    DynamicObject right = test::sphere("right", Vec3(0.5, 0, 0), Vec3(0), Real(0.3), Real(3));
    right.angularVelocity = Vec3(1, 0, 0);
    right.velocity = V - glm::cross(right.angularVelocity, Vec3(-0.5, 0, 0));
    scene.dynamics.push_back(left);
    scene.dynamics.push_back(right);
    scene.joints.push_back(makeDef(JointKind::Ball, "middle", "left", "right", Vec3(0)));
    World world(scene);
    auto momentum = [&] {
        Vec3 p(0);
        for (const DynamicObject& b : world.dynamics()) p += b.mass * b.velocity;
        return p;
    };
    auto angularMomentum = [&] {
        Vec3 L(0);
        for (const DynamicObject& b : world.dynamics()) L += b.angularMomentum + b.mass * glm::cross(b.position, b.velocity);
        return L;
    };
    const Vec3 p0 = momentum();
    const Vec3 L0 = angularMomentum();
    Real worst = 0;
    while (world.time() < 3) {
        world.step();
        const JointAnchors anchors = jointAnchors(world.joints()[0], world.dynamics());
        worst = std::max(worst, glm::length(anchors.onB - anchors.onA));
    }
    INFO("momentum change " << glm::length(momentum() - p0) << ", angular momentum change "
                             << glm::length(angularMomentum() - L0) << " of " << glm::length(L0)
                             << ", joint apart by at most " << worst * 1000 << " mm");
    CHECK(glm::length(momentum() - p0) < 1e-12);
    CHECK(glm::length(angularMomentum() - L0) < 1e-3 * glm::length(L0));
    CHECK(worst < 0.001);
}

namespace {

/// What a swinging chain did: its energy's largest rise above the start, J (negative: it never
/// rose), the widest gap of any joint, m, and how low its last link's centre came, m.
struct ChainSwing {
    Real worstRise = 0;
    Real worstGap = 0;
    Real lowestTip = 0;
};

/// Steps @p world for @p seconds, its energy finite at every step, measuring each step.
ChainSwing swingChain(World& world, Real seconds) {
    const Real start = energyOf(world).total();
    ChainSwing swing{-std::numeric_limits<Real>::infinity(), 0, world.dynamics().back().position.y};
    while (world.time() < seconds) {
        world.step();
        const Real energy = energyOf(world).total();
        REQUIRE(std::isfinite(energy));
        swing.worstRise = std::max(swing.worstRise, energy - start);
        for (const Joint& joint : world.joints()) {
            swing.worstGap = std::max(swing.worstGap, measureJoint(joint, world.dynamics()).distance);
        }
        swing.lowestTip = std::min(swing.lowestTip, world.dynamics().back().position.y);
    }
    return swing;
}

}  // namespace

TEST_CASE("A chain of ball-jointed links released horizontal swings without gaining energy or opening", "[joints]") {
    // config/bench_chain.scene with 10 links: boxes 0.2 x 0.05 x 0.05 m of 1 kg, neighbours joined
    // at their common end, the first hanging from the world; released horizontal, no damping, no
    // floor. Nothing drives it, so its energy must never rise above the start's: the tolerance,
    // 1 % of m g L / 2 (the energy it gives up falling from horizontal to hanging, 98 J), is
    // rounding and the solver's O(h) wobble, far below what a fault shows. The gap bound, 20 mm
    // (10 % of a link), leaves room for the soft 60 Hz joints, which give way by a / (2 pi f)^2
    // under an acceleration a (10 mm measured: a = 1400 m/s^2 where the free end whips), and none
    // for a joint torn open. Before the continuous stage skipped jointed pairs (continuous.hpp,
    // SweepWorkspace::unsweptPairs), a fast link was put back where its path met its neighbour's
    // end, the joint opened by what it lost (127 mm) and its soft spring pumped that back in as
    // speed: +312 J over the start here, and the 100-link bench chain went to NaN at 4.6 s.
    constexpr int kLinks = 10;
    constexpr Real kLink = Real(0.2);
    const bool fastPath = GENERATE(false, true);
    Scene scene = solverScene();
    scene.settings.sleeping = false;
    scene.settings.fastPath = fastPath;
    const Vec3 pivot(0, 22, 0);
    for (int i = 0; i < kLinks; ++i) {
        const std::string name = "link" + std::to_string(i);
        scene.dynamics.push_back(test::dynamicBox(name, pivot + Vec3(kLink * (Real(i) + Real(0.5)), 0, 0),
                                                  Vec3(kLink, Real(0.05), Real(0.05)), 1, Real(0.5)));
        scene.joints.push_back(makeDef(JointKind::Ball, "j" + std::to_string(i), name,
                                       i == 0 ? "" : "link" + std::to_string(i - 1), pivot + Vec3(kLink * Real(i), 0, 0)));
    }
    World world(scene);
    const Real drop = kLinks * g * (kLinks * kLink) / 2;  // m g L / 2, J
    const ChainSwing swing = swingChain(world, 10);
    INFO("fast path " << fastPath << ": energy at most " << swing.worstRise << " J above the start (of " << drop
                      << " J given up falling), widest joint gap " << swing.worstGap * 1000 << " mm");
    CHECK(swing.worstRise < Real(0.01) * drop);
    CHECK(swing.worstGap < Real(0.1) * kLink);
    CHECK(swing.lowestTip < pivot.y - Real(1.5));  // it did swing down
}

TEST_CASE("The 100-link bench chain whips at 4 substeps without gaining energy or tearing", "[joints]") {
    // config/bench_chain.scene invites Substeps=4. Its whip sends the free end's links tumbling at
    // 100 to 300 rad/s: 0.4 to 1.2 rad a substep, 2 to 5 rad a step. While the joints took each
    // body's world inverse inertia once a step, a link turned since then answered an impulse with
    // Δω = I⁻¹(q₀)·ΔL where the integrator then sets ω = I⁻¹(q)·L: for these rods, whose moments
    // differ 8.5:1 (m·(0.2² + 0.05²)/12 against m·(0.05² + 0.05²)/12), up to 8.5 times the turn
    // the joint asked for, and every warm start fed that back. The chain went to NaN at 9 s.
    // warmStartJoints() takes I⁻¹ at each substep's start.
    //
    // Nothing drives the chain, so its energy must never rise above the start's (1 % of
    // m g L / 2 = 9810 J for rounding and the O(h) wobble); a joint may give way under the whip's
    // accelerations (about 80 mm measured; 50 mm at 16 substeps), but not open by half a link.
    Scene scene = loadSceneFile(STEPWISE_SOURCE_DIR "/config/bench_chain.scene");
    scene.settings.substeps = 4;
    const bool fastPath = GENERATE(false, true);
    scene.settings.fastPath = fastPath;
    World world(scene);
    const Real drop = Real(world.dynamics().size()) * g * Real(20) / 2;  // 100 kg, 20 m: m g L / 2, J
    const ChainSwing swing = swingChain(world, 10);
    INFO("fast path " << fastPath << ": energy at most " << swing.worstRise << " J above the start (of " << drop
                      << " J given up falling), widest joint gap " << swing.worstGap * 1000 << " mm");
    CHECK(swing.worstRise < Real(0.01) * drop);
    CHECK(swing.worstGap < Real(0.1));
}

TEST_CASE("The bench ragdoll lands on its floor with its joints closed to a few centimetres", "[joints]") {
    // config/bench_ragdoll.scene: 20 boxes, ball and hinge joints, dropped 1 m onto a kinematic box.
    // Its limbs hit the floor fast (over their inner radius in a step), so the continuous stage
    // sweeps them; put back at the floor alone, a limb tore its joints open by what it lost
    // (191 mm). A jointed body is swept against the floor only when its centre's path reaches it
    // (continuous.hpp): measured 14 mm. The bound, 30 mm, is what Bullet shows on this scene.
    World world(loadSceneFile(STEPWISE_SOURCE_DIR "/config/bench_ragdoll.scene"));
    Real worstGap = 0;
    while (world.time() < 3) {
        world.step();
        for (const Joint& joint : world.joints()) worstGap = std::max(worstGap, measureJoint(joint, world.dynamics()).distance);
    }
    INFO("widest joint gap " << worstGap * 1000 << " mm");
    CHECK(worstGap < Real(0.03));
}

// ------------------------------------------------------------------ hinge

TEST_CASE("A hinge keeps its axis aligned and its angle within its limits", "[joints]") {
    // A 1 m bar hinged to the world at its end, axis Z, limits -30..+30 degrees,
    // released horizontal and given a twist about X that the hinge must refuse.
    const Vec3 pivot(0, 2, 0);
    const Real limit = Real(30) * kPi / 180;
    const Real overrunTolerance = Real(0.5) * kPi / 180;
    for (const Real spin : {Real(0), Real(8)}) {  // 0: gravity swings it onto the lower limit; 8 rad/s: onto the upper
        INFO("initial spin about Z " << spin << " rad/s");
        Scene scene = solverScene();
        DynamicObject bar = test::dynamicBox("bar", pivot + Vec3(0.5, 0, 0), Vec3(1, 0.1, 0.1), 1, 0.5);
        bar.angularVelocity = Vec3(2, 0, spin);
        bar.velocity = glm::cross(bar.angularVelocity, Vec3(0.5, 0, 0));
        scene.dynamics.push_back(bar);
        JointDef hinge = makeDef(JointKind::Hinge, "hinge", "bar", "", pivot);
        hinge.axis = Vec3(0, 0, 1);
        hinge.lowerAngle = -limit;
        hinge.upperAngle = limit;
        scene.joints.push_back(hinge);
        World world(scene);
        const Joint& joint = world.joints()[0];
        const DynamicObject& body = world.dynamics()[0];
        Real lowest = 0, highest = 0, worstAxis = 0, worstPoint = 0;
        while (world.time() < 3) {
            world.step();
            const Real angle = hingeAngle(joint, body.orientation, Quat(1, 0, 0, 0));
            lowest = std::min(lowest, angle);
            highest = std::max(highest, angle);
            const Vec3 axis = body.orientation * Vec3(0, 0, 1);
            worstAxis = std::max(worstAxis, std::acos(std::min(axis.z, Real(1))));
            const JointAnchors anchors = jointAnchors(joint, world.dynamics());
            worstPoint = std::max(worstPoint, glm::length(anchors.onB - anchors.onA));
        }
        INFO("angle from " << lowest * 180 / kPi << " to " << highest * 180 / kPi << " deg, axis off by at most "
                           << worstAxis * 180 / kPi << " deg, anchor apart by at most " << worstPoint * 1000 << " mm");
        CHECK(lowest >= -limit - overrunTolerance);
        CHECK(highest <= limit + overrunTolerance);
        if (spin == 0) CHECK(lowest < -limit + overrunTolerance);  // it reached the lower limit
        else CHECK(highest > limit - overrunTolerance);            // and this one the upper
        CHECK(worstAxis < overrunTolerance);
        // Hitting a limit is an impact: the soft point (f = 60 Hz, damping ratio 2)
        // gives way like an overdamped spring struck at speed v, by at most
        // 0.22 v / (2 pi f) (the peak of e^(-2x) sinh(sqrt(3) x) / sqrt(3)).
        // v is at most the speed of the bar's centre, 0.5 m times the spin the
        // bar can have (its start spin plus what falling 0.25 m adds).
        const Real pivotInertia = Real(1) / 3;  // m L^2 / 3 for the 1 kg, 1 m bar
        const Real fastestSpin = std::sqrt(spin * spin + 2 * g * Real(0.25) / pivotInertia);
        const Real giveWay = Real(0.22) * Real(0.5) * fastestSpin / (2 * kPi * jointHertzInUse(world.settings()));
        CHECK(worstPoint < 2 * giveWay);
    }
}

TEST_CASE("A hinge motor reaches its target speed when its torque allows, and accelerates at tau/I when not",
          "[joints]") {
    // A square plate 1 x 1 x 0.2 m of 2 kg on an axle through its centre along Z:
    // I = m (a^2 + b^2) / 12 = 1/3 kg m^2. Gravity pulls through the axle.
    const Real mass = 2;
    const Real inertia = mass * (1 + 1) / 12;
    const Real target = 10;
    const Real torque = 1;
    const Real spinUpTime = inertia * target / torque;  // 3.33 s at full torque
    auto makeWorld = [&](Real maxTorque) {
        Scene scene = solverScene();
        scene.dynamics.push_back(test::dynamicBox("wheel", Vec3(0, 1, 0), Vec3(1, 1, 0.2), mass, 0.5));
        JointDef hinge = hingeAtCentre(scene.dynamics[0], Vec3(0, 0, 1));
        hinge.motor = true;
        hinge.motorSpeed = target;
        hinge.maxMotorTorque = maxTorque;
        scene.joints.push_back(hinge);
        return World(scene);
    };
    SECTION("enough torque: at the target after I w / tau") {
        World world = makeWorld(torque);
        runFor(world, spinUpTime + 1);
        INFO("w = " << world.dynamics()[0].angularVelocity.z << " rad/s after " << world.time() << " s");
        CHECK(world.dynamics()[0].angularVelocity.z == Approx(target).epsilon(0.01));
        CHECK(world.dynamics()[0].position.y == Approx(1).margin(0.001));  // the axle held it up
    }
    SECTION("too little torque for the time: w = tau t / I, below the target") {
        World world = makeWorld(torque);
        const Real t = Real(0.5) * spinUpTime;
        runFor(world, t);
        const Real expected = torque * t / inertia;
        INFO("w = " << world.dynamics()[0].angularVelocity.z << " rad/s, tau t / I = " << expected << " rad/s");
        CHECK(world.dynamics()[0].angularVelocity.z <= expected * 1.01);
        CHECK(world.dynamics()[0].angularVelocity.z >= expected * 0.99);
        CHECK(world.dynamics()[0].angularVelocity.z < target);
    }
}

TEST_CASE("A hinge motor between two free bodies turns them apart, keeping the angular momentum at zero",
          "[joints]") {
    // In zero gravity a wheel (1 x 1 x 0.2 m, 1 kg: I_w = 1/6 kg m^2 about Z)
    // is hinged on the face of a block (1 m cube, 4 kg: I_b = 2/3 kg m^2),
    // axis Z through both centres. The motor's torque acts on both, equal and
    // opposite: the relative speed grows at tau (1/I_w + 1/I_b) = 3.75 rad/s^2
    // to the target 5 rad/s, and the two spin in opposite senses with
    // I_w w_w = -I_b w_b, so the angular momentum stays zero.
    Scene scene = solverScene(Vec3(0));
    scene.dynamics.push_back(test::dynamicBox("wheel", Vec3(0, 0, 0.6), Vec3(1, 1, 0.2), 1, 0.5));
    scene.dynamics.push_back(test::dynamicBox("block", Vec3(0), Vec3(1), 4, 0.5));
    JointDef hinge = makeDef(JointKind::Hinge, "axle", "wheel", "block", Vec3(0, 0, 0.6));
    hinge.axis = Vec3(0, 0, 1);
    hinge.motor = true;
    hinge.motorSpeed = 5;
    hinge.maxMotorTorque = Real(0.5);
    scene.joints.push_back(hinge);
    World world(scene);
    const DynamicObject& wheel = world.dynamics()[0];
    const DynamicObject& block = world.dynamics()[1];
    const Real wheelInertia = Real(1) / 6;
    const Real blockInertia = Real(2) / 3;

    runFor(world, Real(0.5));  // 0.5 s x 3.75 rad/s^2 = 1.875 rad/s, still accelerating
    const Real expected = Real(0.5) * world.time() * (1 / wheelInertia + 1 / blockInertia);
    CHECK(wheel.angularVelocity.z - block.angularVelocity.z == Approx(expected).epsilon(0.01));
    runFor(world, 2);
    const Real relative = wheel.angularVelocity.z - block.angularVelocity.z;
    const Real total = wheelInertia * wheel.angularVelocity.z + blockInertia * block.angularVelocity.z;
    INFO("relative spin " << relative << " rad/s, wheel " << wheel.angularVelocity.z << ", block "
                          << block.angularVelocity.z << ", I w summed " << total);
    CHECK(relative == Approx(5).epsilon(0.01));
    CHECK(wheel.angularVelocity.z == Approx(-4 * block.angularVelocity.z).epsilon(0.01));
    CHECK(std::abs(total) < 1e-6);
    CHECK(measureJoint(world.joints()[0], world.dynamics()).distance < 0.001);
}

// ------------------------------------------------------------------ angular motor

TEST_CASE("An AngularMotor spins a free body up at tau/I and holds the target speed", "[joints]") {
    // A solid ball of 3 kg and radius 0.5 m in zero gravity: I = 2/5 m r^2 = 0.3 kg m^2.
    const Real inertia = Real(0.4) * 3 * Real(0.25);
    const Real target = -6;  // about +Y, turning clockwise seen from above
    const Real torque = Real(0.9);
    const Real spinUpTime = inertia * std::abs(target) / torque;  // 2 s
    Scene scene = solverScene(Vec3(0));
    scene.dynamics.push_back(test::sphere("ball", Vec3(0), Vec3(0), Real(0.5), Real(3)));
    JointDef motor = makeDef(JointKind::AngularMotor, "motor", "ball", "", Vec3(0));
    motor.axis = Vec3(0, 1, 0);
    motor.motorSpeed = target;
    motor.maxMotorTorque = torque;
    scene.joints.push_back(motor);
    World world(scene);
    const DynamicObject& ball = world.dynamics()[0];

    runFor(world, Real(0.5) * spinUpTime);
    const Real expected = -torque * world.time() / inertia;
    INFO("w = " << ball.angularVelocity.y << " rad/s, -tau t / I = " << expected << " rad/s");
    CHECK(ball.angularVelocity.y >= expected * 1.01);  // negative speeds: |w| <= tau t / I * 1.01
    CHECK(ball.angularVelocity.y <= expected * 0.99);
    runFor(world, spinUpTime);
    INFO("then w = " << ball.angularVelocity.y << " rad/s at t = " << world.time() << " s");
    CHECK(ball.angularVelocity.y == Approx(target).epsilon(0.01));
    CHECK(std::abs(ball.angularVelocity.x) + std::abs(ball.angularVelocity.z) < 1e-9);  // only about its axis
    CHECK(measureJoint(world.joints()[0], world.dynamics()).speed == Approx(target).epsilon(0.01));
}

// ------------------------------------------------------------------ breaking

TEST_CASE("A joint breaks when its force exceeds MaxForce, and holds below it", "[joints]") {
    // A 2 kg ball hanging at rest 1 m below a fixed point: the rod carries m g = 19.6 N.
    const Real mass = 2;
    const Vec3 pivot(0, 2, 0);
    auto makeWorld = [&](Real maxForce) {
        Scene scene = solverScene();
        scene.dynamics.push_back(test::sphere("weight", pivot - Vec3(0, 1, 0), Vec3(0), Real(0.1), mass));
        JointDef rod = makeDef(JointKind::Distance, "rod", "weight", "", pivot - Vec3(0, 1, 0), pivot);
        rod.maxForce = maxForce;
        scene.joints.push_back(rod);
        return World(scene);
    };
    SECTION("MaxForce < m g: breaks in the first step, then the ball falls freely") {
        World world = makeWorld(Real(0.5) * mass * g);
        const Real h = world.settings().timeStep;
        world.step();
        const Joint& rod = world.joints()[0];
        INFO("force in the first step " << rod.brokenForce << " N, m g = " << mass * g << " N");
        REQUIRE(rod.broken);
        CHECK(rod.brokenAtStep == 1);
        CHECK(rod.brokenAtTime == Approx(h));
        CHECK(rod.brokenForce == Approx(mass * g).epsilon(0.05));
        const Real v1 = world.dynamics()[0].velocity.y;
        CHECK(std::abs(v1) < g * h);  // it was held during that step
        runFor(world, 1);
        CHECK(world.dynamics()[0].velocity.y - v1 == Approx(-g * (world.time() - h)).epsilon(1e-9));
    }
    SECTION("MaxForce > 2 m g: it holds") {
        World world = makeWorld(Real(2.5) * mass * g);
        runFor(world, 2);
        CHECK_FALSE(world.joints()[0].broken);
        CHECK(world.dynamics()[0].position.y == Approx(pivot.y - 1).margin(0.001));
    }
}

TEST_CASE("A weak rod breaks where its tension first exceeds MaxForce", "[joints]") {
    // A bob released from horizontal on a rod of length L: at angle theta from
    // the bottom its speed is v^2 = 2 g L cos(theta), and the rod's tension
    // m g cos(theta) + m v^2 / L = 3 m g cos(theta). With MaxForce = 2 m g it breaks
    // when cos(theta) = 2/3, 48.2 degrees before the bottom, within one step's swing.
    const Real mass = 1;
    const Real L = 1;
    const Vec3 pivot(0, 3, 0);
    Scene scene = solverScene();
    scene.dynamics.push_back(test::sphere("bob", pivot + Vec3(L, 0, 0), Vec3(0), Real(0.05), mass));
    JointDef rod = makeDef(JointKind::Distance, "rod", "bob", "", pivot + Vec3(L, 0, 0), pivot);
    rod.maxForce = 2 * mass * g;
    scene.joints.push_back(rod);
    World world(scene);
    const Joint& joint = world.joints()[0];
    const DynamicObject& bob = world.dynamics()[0];
    Real angleAtBreak = 0;
    Real swingPerStep = 0;
    while (!joint.broken && world.time() < 1) {
        world.step();
        const Vec3 arm = bob.position - pivot;
        angleAtBreak = std::atan2(arm.x, -arm.y);
        swingPerStep = glm::length(bob.velocity) / L * world.settings().timeStep;
    }
    REQUIRE(joint.broken);
    INFO("broke at " << angleAtBreak * 180 / kPi << " degrees from the bottom, force " << joint.brokenForce << " N");
    CHECK(angleAtBreak == Approx(std::acos(Real(2) / 3)).margin(swingPerStep));
    CHECK(joint.brokenForce > 2 * mass * g);
    CHECK(joint.brokenAtTime == Approx(world.time()));
}

// ------------------------------------------------------------------ rope bridge

namespace {

/// Length of one rope of a bridge: the polyline from the world anchor at one
/// end, through both anchors of every joint of that rope in order, to the
/// world anchor at the other end. Each plank's two anchors are a rigid 1 m
/// apart, so what exceeds 1 m per plank is the joints' stretch.
Real ropeLength(const World& world, const std::vector<std::size_t>& rope) {
    std::vector<Vec3> points;
    for (std::size_t k = 0; k < rope.size(); ++k) {
        const JointAnchors anchors = jointAnchors(world.joints()[rope[k]], world.dynamics());
        const bool last = k + 1 == rope.size();  // there A is the last plank and B the world
        points.push_back(last ? anchors.onA : anchors.onB);
        points.push_back(last ? anchors.onB : anchors.onA);
    }
    Real length = 0;
    for (std::size_t k = 1; k < points.size(); ++k) length += glm::length(points[k] - points[k - 1]);
    return length;
}

}  // namespace

TEST_CASE("A rope bridge of 20 planks carries a 10 kg crate stretching less than 2 %", "[joints]") {
    // config/lesson08_bridge.scene: 20 planks 1 m from joint point to joint
    // point, each joined to the next by two ball joints (one per edge, the
    // two ropes), the ends hanging from the world 18 m apart, a 10 kg crate
    // on the middle. Rest length of each rope: 20 m.
    World world(loadSceneFile(STEPWISE_SOURCE_DIR "/config/lesson08_bridge.scene"));
    constexpr int kPlanks = 20;
    const Real restLength = kPlanks;
    std::vector<std::size_t> near, far;  // joint indices of each rope, left to right
    for (std::size_t i = 0; i < world.joints().size(); ++i) {
        REQUIRE(world.joints()[i].kind == JointKind::Ball);
        (jointAnchors(world.joints()[i], world.dynamics()).onA.z < 0 ? near : far).push_back(i);
    }
    REQUIRE(near.size() == kPlanks + 1);
    REQUIRE(far.size() == kPlanks + 1);
    REQUIRE(ropeLength(world, near) == Approx(restLength).margin(0.01));  // the scene starts unstretched

    const DynamicObject* crate = world.findDynamic("crate");
    REQUIRE(crate != nullptr);
    const Real startHeight = crate->position.y;
    Real worstStretch = 0;
    while (world.time() < 10) {
        world.step();
        for (const auto* rope : {&near, &far}) {
            worstStretch = std::max(worstStretch, (ropeLength(world, *rope) - restLength) / restLength);
        }
    }
    INFO("largest stretch " << worstStretch * 100 << " %; crate at " << crate->position.x << ", "
                            << crate->position.y << ", " << crate->position.z);
    CHECK(worstStretch < 0.02);
    // The crate is still on the two middle planks, held above the riverbed (y = -2).
    CHECK(std::abs(crate->position.x) < 1);
    CHECK(std::abs(crate->position.z) < Real(0.3));
    CHECK(crate->position.y > startHeight - 1);
    for (const Joint& joint : world.joints()) CHECK_FALSE(joint.broken);
}

// ------------------------------------------------------------------ Newton's cradle

TEST_CASE("Newton's cradle: the last ball leaves with the first ball's speed, the others stay", "[joints][solver]") {
    // config/lesson08_cradle.scene: five equal balls with e = 1 on 1 m strings,
    // 4 cm apart; ball 1 released at 30 degrees. Equal masses in an elastic
    // collision swap velocities, so the momentum runs down the line and ball 5
    // leaves at ball 1's speed v = sqrt(2 g L (1 - cos 30 deg)), the rest at rest.
    World world(loadSceneFile(STEPWISE_SOURCE_DIR "/config/lesson08_cradle.scene"));
    std::vector<const DynamicObject*> balls;
    for (int i = 1; i <= 5; ++i) {
        balls.push_back(world.findDynamic("ball" + std::to_string(i)));
        REQUIRE(balls.back() != nullptr);
    }
    auto speed = [&](int i) { return glm::length(balls[static_cast<std::size_t>(i)]->velocity); };
    Real incoming = 0;
    while (world.contacts().empty() && world.time() < 2) {
        incoming = std::max(incoming, speed(0));
        world.step();
    }
    REQUIRE_FALSE(world.contacts().empty());
    CHECK(incoming == Approx(std::sqrt(2 * g * (1 - std::cos(kPi / 6)))).epsilon(0.01));

    // Ball 5 is fastest the moment it leaves; gravity slows it from then on.
    Real peak = 0;
    Real othersAtPeak = 0;
    while (world.time() < 2) {
        world.step();
        if (speed(4) < peak) break;
        peak = speed(4);
        othersAtPeak = std::max({speed(0), speed(1), speed(2), speed(3)});
    }
    INFO("incoming " << incoming << " m/s, ball 5 leaves at " << peak << " m/s, the others at most " << othersAtPeak
                     << " m/s");
    CHECK(peak >= 0.95 * incoming);
    CHECK(othersAtPeak < 0.05 * incoming);
}

// ------------------------------------------------------------------ scene records

namespace {

Scene parse(const std::string& text) { return parseScene(text, "joints.scene"); }

std::string firstError(const std::string& text) {
    try {
        (void)parse(text);
    } catch (const ConfigError& error) {
        return error.diagnostics().front().message();
    }
    return "";
}

}  // namespace

TEST_CASE("Joint records load into JointDefs: bodies by name, points in world space, angles in degrees",
          "[joints][config]") {
    const Scene scene = parse(
        "DynamicObject, Name=bob, Position=(1, 0, 0)\n"
        "DynamicObject, Name=arm, Position=(0, 1, 0)\n"
        "DistanceJoint, Name=rod, BodyA=bob, BodyB=arm, AnchorA=(1, 0.5, 0), AnchorB=(0, 2, 0), Length=2, MaxForce=50\n"
        "Rope, BodyA=bob, AnchorB=(0, 5, 0)\n"
        "BallJoint, Name=socket, BodyA=arm, Anchor=(0, 3, 0), CollideConnected=yes\n"
        "HingeJoint, Name=axle, BodyA=bob, BodyB=arm, Axis=(0, 2, 0), LowerAngle=-45, UpperAngle=90, MotorSpeed=3, "
        "MaxMotorTorque=4\n"
        "AngularMotor, Name=spin, BodyA=arm, Axis=(1, 0, 0), MotorSpeed=-2, MaxMotorTorque=0.5\n");
    REQUIRE(scene.joints.size() == 5);
    const JointDef& rod = scene.joints[0];
    CHECK(rod.kind == JointKind::Distance);
    CHECK(rod.bodyA == "bob");
    CHECK(rod.bodyB == "arm");
    CHECK(rod.anchorA == Vec3(1, 0.5, 0));
    CHECK(rod.anchorB == Vec3(0, 2, 0));
    CHECK(rod.length == Real(2));
    CHECK(rod.maxForce == 50);
    CHECK_FALSE(rod.collideConnected);

    const JointDef& rope = scene.joints[1];
    CHECK(rope.kind == JointKind::Rope);
    CHECK(rope.name == "Rope0");           // default names count per record type
    CHECK(rope.bodyB.empty());             // fixed to the world
    CHECK(rope.anchorA == Vec3(1, 0, 0));  // default: BodyA's centre
    CHECK_FALSE(rope.length.has_value());  // default: the distance at the start
    CHECK(rope.maxForce == kUnbreakable);

    const JointDef& socket = scene.joints[2];
    CHECK(socket.kind == JointKind::Ball);
    CHECK(socket.anchorA == Vec3(0, 3, 0));
    CHECK(socket.collideConnected);

    const JointDef& axle = scene.joints[3];
    CHECK(axle.kind == JointKind::Hinge);
    CHECK(axle.anchorA == Vec3(1, 0, 0));  // default: BodyA's centre
    CHECK(axle.axis == Vec3(0, 1, 0));     // normalised
    CHECK(*axle.lowerAngle == Approx(-kPi / 4));
    CHECK(*axle.upperAngle == Approx(kPi / 2));
    CHECK(axle.motor);
    CHECK(axle.motorSpeed == 3);
    CHECK(axle.maxMotorTorque == 4);

    const JointDef& spin = scene.joints[4];
    CHECK(spin.kind == JointKind::AngularMotor);
    CHECK(spin.axis == Vec3(1, 0, 0));
    CHECK(spin.motorSpeed == -2);
    CHECK(spin.maxMotorTorque == Real(0.5));

    // The World turns them into body frames; the rope's length is the distance at the start.
    const World world(scene);
    REQUIRE(world.joints().size() == 5);
    CHECK(world.joints()[1].length == Approx(std::sqrt(Real(26))));
    CHECK(world.joints()[1].bodyB == kWorldAnchor);
    CHECK(world.joints()[0].localAnchorA == Vec3(0, 0.5, 0));
    CHECK(world.joints()[0].localAnchorB == Vec3(0, 1, 0));
}

TEST_CASE("A joint may name a body defined later in the file, ignoring case", "[joints][config]") {
    const Scene scene = parse("BallJoint, BodyA=LATER, Anchor=(0, 1, 0)\nDynamicObject, Name=later\n");
    REQUIRE(scene.joints.size() == 1);
    CHECK(scene.joints[0].bodyA == "later");
}

TEST_CASE("A joint naming a missing body is an error at the name, with a did-you-mean", "[joints][config]") {
    CHECK(firstError("DynamicObject, Name=pendulum\nDistanceJoint, BodyA=pendulm, AnchorB=(0, 2, 0)\n") ==
          "joints.scene:2:22: error: BodyA: expected the name of a DynamicObject, found 'pendulm'; did you mean "
          "'pendulum'?");
    CHECK_THAT(firstError("DynamicObject, Name=a\nBallJoint, BodyA=a, BodyB=zzz\n"),
               Contains("2:27: error: BodyB") && Contains("no DynamicObject has that name"));
    CHECK_THAT(firstError("DynamicObject, Name=a\nCollisionPlane, Name=floor\nBallJoint, BodyA=a, BodyB=floor\n"),
               Contains("'floor' is the CollisionPlane on line 2") && Contains("leave BodyB out"));
    CHECK_THAT(firstError("DynamicObject, Name=a\nHingeJoint, Anchor=(0, 1, 0)\n"),
               Contains("2:1: error: BodyA: expected the name of a DynamicObject, found ''"));
    CHECK_THAT(firstError("DynamicObject, Name=a\nBallJoint, BodyA=a, BodyB=a\n"),
               Contains("BodyB: expected a body other than BodyA"));
}

TEST_CASE("Joint records check what spans their fields", "[joints][config]") {
    CHECK_THAT(firstError("DynamicObject, Name=a\nRope, BodyA=a\n"),
               Contains("AnchorB: expected a point (x, y, z)") && Contains("fixed to the world"));
    CHECK_THAT(firstError("DynamicObject, Name=a\nDistanceJoint, BodyA=a, AnchorB=(0, 0, 0)\n"),
               Contains("Length: expected a length of at least 1e-6 m") && Contains("anchors (almost) coincide"));
    CHECK_THAT(firstError("DynamicObject, Name=a\nHingeJoint, BodyA=a, Axis=(0, 0, 0)\n"),
               Contains("Axis: expected a direction (a vector of length > 0"));
    CHECK_THAT(firstError("DynamicObject, Name=a\nHingeJoint, BodyA=a, LowerAngle=30, UpperAngle=10\n"),
               Contains("UpperAngle: expected an angle >= LowerAngle (30), found '10'"));
    CHECK_THAT(firstError("DynamicObject, Name=a\nHingeJoint, BodyA=a, UpperAngle=270\n"),
               Contains("UpperAngle: expected an angle from -180 to 180 degrees, found '270'"));
    CHECK_THAT(firstError("DynamicObject, Name=a\nBallJoint, BodyA=a, MaxForce=0\n"),
               Contains("MaxForce: expected a number > 0"));
    CHECK_THAT(firstError("DynamicObject, Name=a\nAngularMotor, BodyA=a, MaxForce=10\n"),
               Contains("AngularMotor: expected one of its fields"));
}

TEST_CASE("Joints need the sequential-impulse solver, in a file and in code", "[joints][config]") {
    CHECK(firstError("World, Solver=Impulse\nDynamicObject, Name=a\nBallJoint, BodyA=a\n") ==
          "joints.scene:3:1: error: BallJoint: expected a World with Solver=SequentialImpulse, found 'Solver=Impulse'; "
          "joints are solved only by the sequential-impulse solver; remove Solver=Impulse from the World record on "
          "line 1");
    Scene scene = solverScene();
    scene.settings.solver = SolverKind::Impulse;
    scene.dynamics.push_back(test::sphere("a", Vec3(0)));
    scene.joints.push_back(makeDef(JointKind::Ball, "socket", "a", "", Vec3(0, 1, 0)));
    CHECK_THROWS_WITH(World(scene), Contains("socket") && Contains("SequentialImpulse"));
    scene.settings.solver = SolverKind::SequentialImpulse;
    scene.joints[0].bodyA = "ghost";
    CHECK_THROWS_WITH(World(scene), Contains("socket") && Contains("no dynamic body called 'ghost'"));
}

TEST_CASE("stepwise run lists the joints, their errors, and when a joint broke", "[joints][cli]") {
    // lesson08_pendulum.scene's "weakRod" (MaxForce = 2 m g, released horizontal)
    // breaks on its first swing, about 0.4 s in (the bob reaches 48 degrees
    // from the bottom after about a fifth of a period).
    const test::CommandResult r = test::shell(std::string("'") + STEPWISE_CLI_PATH + "' run '" STEPWISE_SOURCE_DIR
                                              "/config/lesson08_pendulum.scene' --duration 1");
    CHECK(r.exitCode == 0);
    CHECK_THAT(r.output, Contains("4 joint(s) at 60 Hz") && Contains("Joints") &&
                             Contains("smallRod         DistanceJoint  small - world") &&
                             Contains("ropeLine         Rope") && Contains("intact") &&
                             Contains("weakRod") && Contains("broken at t = 0.") && Contains("> MaxForce 19.62 N"));
}
