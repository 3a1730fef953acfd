// Joints of the sequential-impulse solver, against the physics they model.
// Tags: [joints] (and [solver] for Newton's cradle, [config] for the scene records).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "config/scene_loader.hpp"
#include "dynamics/inertia.hpp"
#include "test_support.hpp"

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

/// Orientation that turns body +X onto the world direction (cos a, sin a, 0).
Quat turnAboutZ(Real angle) { return glm::angleAxis(angle, Vec3(0, 0, 1)); }

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
    INFO("T0 = " << T0 << " s, expected T = " << expected << " s, measured " << measured << " s");
    CHECK(std::abs(measured - expected) / expected < 0.005);
    CHECK(largestLengthError < 0.001);
    CHECK(measureJoint(world.joints()[0], world.dynamics()).distance < 0.001);
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
    Scene scene = solverScene(Vec3(0));
    scene.dynamics.push_back(test::sphere("left", Vec3(-0.5, 0, 0), Vec3(0, 1, 0.5), Real(0.2), Real(1)));
    scene.dynamics.push_back(test::sphere("right", Vec3(0.5, 0, 0), Vec3(1, -2, 0), Real(0.3), Real(3)));
    scene.dynamics[0].angularVelocity = Vec3(0, 0, 4);
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
    CHECK(glm::length(momentum() - p0) < 1e-12);
    CHECK(glm::length(angularMomentum() - L0) < 1e-3 * glm::length(L0));
    CHECK(worst < 0.001);
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
        CHECK(world.dynamics()[0].angularVelocity.z == Approx(target).epsilon(0.01));
        CHECK(world.dynamics()[0].position.y == Approx(1).margin(0.001));  // the axle held it up
    }
    SECTION("too little torque for the time: w = tau t / I, below the target") {
        World world = makeWorld(torque);
        const Real t = Real(0.5) * spinUpTime;
        runFor(world, t);
        const Real expected = torque * t / inertia;
        CHECK(world.dynamics()[0].angularVelocity.z <= expected * 1.01);
        CHECK(world.dynamics()[0].angularVelocity.z >= expected * 0.99);
        CHECK(world.dynamics()[0].angularVelocity.z < target);
    }
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
    CHECK(ball.angularVelocity.y >= expected * 1.01);  // negative speeds: |w| <= tau t / I * 1.01
    CHECK(ball.angularVelocity.y <= expected * 0.99);
    runFor(world, spinUpTime);
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

// ------------------------------------------------------------------ rope bridge

TEST_CASE("A rope bridge of 20 planks carries a 10 kg box stretching less than 2 %", "[joints]") {
    // 20 planks, 1 m from joint to joint (0.9 m boards with 0.1 m gaps), each
    // joined to the next by two ball joints, one at each edge, like the two
    // ropes of a real bridge (one rope would let the planks roll over). The
    // ends hang from the world 18 m apart, so the 20 m chain must sag; it
    // starts as a trough (9 planks down, 2 flat, 9 up) with the box on the
    // flat middle. The stretch is the length of the rope line through every
    // anchor, minus 20 m.
    constexpr int kPlanks = 20;
    const Real span = 18;
    const Real plankMass = 2;
    const Real halfWidth = Real(0.15);
    const Real slopeRun = (span - 2) / Real(kPlanks - 2);  // horizontal extent of a sloping plank
    const Real slopeDrop = std::sqrt(1 - slopeRun * slopeRun);
    std::vector<Vec3> points;  // joint points along the rope line, z = 0
    points.push_back(Vec3(-span / 2, 5, 0));
    for (int i = 0; i < kPlanks; ++i) {
        const bool flat = i == kPlanks / 2 - 1 || i == kPlanks / 2;
        const Vec3 step = flat ? Vec3(1, 0, 0) : Vec3(slopeRun, i < kPlanks / 2 ? -slopeDrop : slopeDrop, 0);
        points.push_back(points.back() + step);
    }
    REQUIRE(points.back().x == Approx(span / 2));
    REQUIRE(points.back().y == Approx(5));

    Scene scene = solverScene();
    for (int i = 0; i < kPlanks; ++i) {
        const Vec3 along = points[i + 1] - points[i];
        DynamicObject plank = test::dynamicBox("plank" + std::to_string(i), (points[i] + points[i + 1]) / Real(2),
                                               Vec3(0.9, 0.05, 2 * halfWidth), plankMass, 0.8);
        plank.orientation = turnAboutZ(std::atan2(along.y, along.x));
        scene.dynamics.push_back(plank);
    }
    const Real bottom = points[kPlanks / 2].y + Real(0.025);
    scene.dynamics.push_back(test::dynamicBox("load", Vec3(0, bottom + Real(0.2) + Real(0.001), 0), Vec3(0.4, 0.4, 0.4),
                                              10, 0.8));
    for (int i = 0; i <= kPlanks; ++i) {
        for (const Real z : {-halfWidth, halfWidth}) {
            // Joint i joins plank i (A; the right end uses plank 19) to plank i-1 (B; the world at the ends).
            const std::string a = "plank" + std::to_string(i < kPlanks ? i : kPlanks - 1);
            const std::string b = i == 0 || i == kPlanks ? "" : "plank" + std::to_string(i - 1);
            scene.joints.push_back(makeDef(JointKind::Ball, "rope" + std::to_string(i) + (z < 0 ? "near" : "far"), a,
                                           b, points[i] + Vec3(0, 0, z)));
        }
    }
    World world(scene);
    const Real restLength = kPlanks;  // 1 m from joint point to joint point on each plank
    Real worstStretch = 0;
    while (world.time() < 6) {
        world.step();
        for (const Real z : {-halfWidth, halfWidth}) {
            // The rope line along one edge: from anchor to anchor through every joint.
            Real length = 0;
            Vec3 previous = points.front() + Vec3(0, 0, z);
            for (const Joint& joint : world.joints()) {
                if ((joint.localAnchorA.z < 0) != (z < 0)) continue;
                const JointAnchors anchors = jointAnchors(joint, world.dynamics());
                length += glm::length(anchors.onA - previous) + glm::length(anchors.onB - anchors.onA);
                previous = anchors.onA;
            }
            worstStretch = std::max(worstStretch, (length - restLength) / restLength);
        }
    }
    const DynamicObject* load = world.findDynamic("load");
    INFO("largest stretch " << worstStretch * 100 << " %, load at " << load->position.x << ", " << load->position.y << ", speed " << glm::length(load->velocity));
    CHECK(worstStretch < 0.02);
    // Still on the two middle planks, above the lowest point the bridge started at.
    CHECK(std::abs(load->position.x) < 1);
    CHECK(std::abs(load->position.z) < halfWidth);
    CHECK(load->position.y > bottom);
}
