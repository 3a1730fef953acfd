// Friction and rolling: Coulomb friction at contact points with the angular
// terms, against the classical results of rigid-body mechanics. Tag: [friction].
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "test_support.hpp"

using namespace stepwise;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// A plane through the origin tilted by @p degrees about z: it descends towards +x.
CollisionPlane incline(Real degrees) {
    const Real theta = degrees * kPi / 180;
    CollisionPlane plane;
    plane.name = "incline";
    plane.normal = Vec3(std::sin(theta), std::cos(theta), 0);
    return plane;
}

/// Unit vector down the slope of incline(degrees).
Vec3 downSlope(Real degrees) {
    const Real theta = degrees * kPi / 180;
    return Vec3(std::cos(theta), -std::sin(theta), 0);
}

}  // namespace

TEST_CASE("A solid sphere rolls down a 30 degree incline at 5/7 g sin(theta)", "[friction]") {
    // Rolling without slipping: m·a = m·g·sinθ − F and I·α = F·R with a = α·R.
    // With I = ⅖·m·R² that gives a = g·sinθ / (1 + I/(m·R²)) = 5/7·g·sinθ.
    // It needs μ ≥ 2/7·tanθ = 0.165; the ball has μ = 0.5.
    const Real theta = 30, R = 0.5;
    for (Real h : {Real(1) / 60, Real(1) / 240}) {
        Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, h);
        scene.planes.push_back(incline(theta));
        scene.dynamics.push_back(test::sphere("ball", R * scene.planes[0].normal, Vec3(0), R, 1, 0, 0.5));
        World world(scene);
        while (world.time() < 2 - 1e-9) world.step();
        const Real expected = Real(5) / 7 * kStandardGravity * std::sin(theta * kPi / 180);
        const DynamicObject& ball = world.dynamics()[0];
        INFO("h = " << h);
        CHECK_THAT(glm::dot(ball.velocity, downSlope(theta)) / world.time(), WithinRel(double(expected), 0.01));
        // And it rolls: the contact point is at rest, v = ω × R.
        const Vec3 contactVelocity = ball.velocity + glm::cross(ball.angularVelocity, -R * scene.planes[0].normal);
        CHECK(glm::length(contactVelocity) < 0.01 * glm::length(ball.velocity));
    }
}

TEST_CASE("A ball rolling down an incline turns by the distance it rolls over its radius", "[friction]") {
    // Rolling without slipping, v = ω × (−R·n) = 0 at the contact: the ball turns about e = n × d by
    // the angle s/R when its centre has gone s down the slope. In a step the ball moves by h·v_{n+1}
    // and turns by h·ω_{n+1} with the solved velocities (velocity_change_drift.cpp), so the two sums
    // agree; a turn by free flight's ω alone would lag by h_s·(ω_end − ω_start), here 0.015 rad.
    const Real theta = 30, R = 0.5;
    for (const bool fastPath : {true, false}) {  // the fast path (on packed records) and the plain path
        for (Real h : {Real(1) / 60, Real(1) / 240}) {
            Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, h);
            scene.settings.fastPath = fastPath;
            scene.planes.push_back(incline(theta));
            scene.dynamics.push_back(test::sphere("ball", R * scene.planes[0].normal, Vec3(0), R, 1, 0, 0.5));
            World world(scene);
            const Vec3 start = world.dynamics()[0].position;
            while (world.time() < 2 - 1e-9) world.step();
            const DynamicObject& ball = world.dynamics()[0];
            const Real rolled = glm::dot(ball.position - start, downSlope(theta));
            const Vec3 axis = glm::cross(scene.planes[0].normal, downSlope(theta));
            const Quat expected = glm::angleAxis(rolled / R, axis);
            // The angle between the two orientations: 2·acos|q₁·q₂| (the ball started unturned)
            const Real apart = 2 * std::acos(std::min(Real(1), std::abs(glm::dot(ball.orientation, expected))));
            INFO("FastPath " << fastPath << ", h = " << h << ": rolled " << rolled << " m, " << rolled / R << " rad");
            CHECK(rolled > 6);  // 5/7·g·sin30°·(2 s)²/2 = 7.0 m
            CHECK(apart < 1e-3);
        }
    }
}

namespace {

/// The ball's orientation after each substep's solve (its drift), for one step.
struct OrientationsAfterDrift : StepObserver {
    std::vector<Quat> orientations;
    void afterStage(const StageEvent& event, const World& world) override {
        if (event.stage == Stage::SolveConstraints) orientations.push_back(world.dynamics()[0].orientation);
    }
};

}  // namespace

TEST_CASE("A rolling ball keeps its orientation through a step's substeps and turns once, in the last", "[friction][observer]") {
    // Nothing in a step reads a ball's orientation (velocity_change_drift.cpp, "A ball turns once
    // a step"), so the drift holds it and turns it in the last substep, by the substeps' turns
    // summed. Rolling without slipping, that turn is the step's distance over the radius.
    const Real theta = 30, R = 0.5;
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
    scene.planes.push_back(incline(theta));
    scene.dynamics.push_back(test::sphere("ball", R * scene.planes[0].normal, Vec3(0), R, 1, 0, 0.5));
    World world(scene);
    while (world.time() < 1 - 1e-9) world.step();  // rolling at about 3.5 m/s
    const Quat before = world.dynamics()[0].orientation;
    const Vec3 start = world.dynamics()[0].position;
    OrientationsAfterDrift watcher;
    world.setObserver(&watcher);
    world.step();
    REQUIRE(watcher.orientations.size() == std::size_t(scene.settings.substeps));
    for (std::size_t k = 0; k + 1 < watcher.orientations.size(); ++k) {
        INFO("substep " << k);
        CHECK(watcher.orientations[k] == before);
    }
    const Quat after = world.dynamics()[0].orientation;
    CHECK(watcher.orientations.back() == after);
    const Real rolled = glm::dot(world.dynamics()[0].position - start, downSlope(theta));
    const Real turned = 2 * std::acos(std::min(Real(1), std::abs(glm::dot(after, before))));
    CHECK(rolled > Real(0.05));
    CHECK_THAT(turned, WithinRel(double(rolled / R), 0.01));  // the slip at the contact is under 1 % of v (above)
}

TEST_CASE("With a spring in the scene a rolling ball turns in every substep: the spring's anchor turns with it", "[friction][observer]") {
    // A spring reads its anchor on the ball at every substep (x + R·r): an orientation held
    // for the step would pull from where the anchor was. So does a joint ([joints]).
    const Real theta = 30, R = 0.5;
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
    scene.planes.push_back(incline(theta));
    scene.dynamics.push_back(test::sphere("ball", R * scene.planes[0].normal, Vec3(0), R, 1, 0, 0.5));
    Spring spring;
    spring.name = "weak";
    spring.anchorA = Vec3(0, R, 0);             // on the ball's surface, off its centre
    spring.anchorB = Vec3(0, 100, 0);           // a world point far above
    spring.stiffness = Real(1e-3);              // N/m: a pull of a tenth of a newton at most
    spring.restLength = Real(100);
    scene.springs.push_back(spring);
    World world(scene);
    while (world.time() < 1 - 1e-9) world.step();
    OrientationsAfterDrift watcher;
    world.setObserver(&watcher);
    const Quat before = world.dynamics()[0].orientation;
    world.step();
    REQUIRE(watcher.orientations.size() == std::size_t(scene.settings.substeps));
    Quat last = before;
    for (std::size_t k = 0; k < watcher.orientations.size(); ++k) {
        INFO("substep " << k);
        CHECK(watcher.orientations[k] != last);  // rolling at about 7 rad/s: every substep turns it
        last = watcher.orientations[k];
    }
}

TEST_CASE("A hollow sphere rolls slower: 3/5 g sin(theta)", "[friction]") {
    // I = ⅔·m·R² ⇒ a = g·sinθ / (1 + 2/3) = 3/5·g·sinθ.
    const Real theta = 30, R = 0.5;
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 120);
    scene.planes.push_back(incline(theta));
    DynamicObject shell = test::sphere("shell", R * scene.planes[0].normal, Vec3(0), R, 1, 0, 0.8);
    shell.hollow = true;
    scene.dynamics.push_back(shell);
    World world(scene);
    while (world.time() < 2 - 1e-9) world.step();
    const Real expected = Real(3) / 5 * kStandardGravity * std::sin(theta * kPi / 180);
    CHECK_THAT(glm::dot(world.dynamics()[0].velocity, downSlope(theta)) / world.time(), WithinRel(double(expected), 0.01));
}

TEST_CASE("A sphere too slippery to roll slides at g(sin(theta) - mu cos(theta)) while spinning up", "[friction]") {
    // With μ < 2/7·tanθ friction cannot keep up: kinetic friction μ·m·g·cosθ acts
    // throughout, so the centre accelerates at g(sinθ − μcosθ).
    const Real theta = 30, R = 0.5, mu = 0.1;
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 120);
    scene.planes.push_back(incline(theta));
    scene.dynamics.push_back(test::sphere("ball", R * scene.planes[0].normal, Vec3(0), R, 1, 0, mu));
    World world(scene);
    while (world.time() < 1 - 1e-9) world.step();
    const Real t = theta * kPi / 180;
    const Real expected = kStandardGravity * (std::sin(t) - mu * std::cos(t));
    CHECK_THAT(glm::dot(world.dynamics()[0].velocity, downSlope(theta)) / world.time(), WithinRel(double(expected), 0.01));
}

TEST_CASE("A sliding, non-spinning sphere ends rolling at 5/7 of its speed", "[friction]") {
    // Kinetic friction slows the centre (a = −μg) and spins the ball up
    // (α = μ·m·g·R/I) until v = ω·R. Angular momentum about the contact line
    // is conserved through it (friction acts through that line):
    // m·v0·R = m·v·R + I·v/R ⇒ v = v0 / (1 + 2/5) = 5/7·v0, whatever μ is.
    // Tolerance 1e-6: the contact point is the ball's own lowest point, so the
    // lever arm is exactly R and the discrete impulses conserve that momentum too.
    const Real v0 = 5;
    for (Real mu : {Real(0.1), Real(0.3), Real(0.8)}) {
        Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 240);
        scene.planes.push_back(test::ground());
        scene.dynamics.push_back(test::sphere("bowl", Vec3(0, 0.5, 0), Vec3(v0, 0, 0), 0.5, 2, 0, mu));
        World world(scene);
        while (world.time() < 6) world.step();
        const DynamicObject& ball = world.dynamics()[0];
        INFO("mu = " << mu);
        CHECK_THAT(ball.velocity.x, WithinRel(double(Real(5) / 7 * v0), 1e-6));
        CHECK_THAT(ball.angularVelocity.z * 0.5, WithinRel(double(-ball.velocity.x), 1e-6));  // rolling: v = −ω_z·R
    }
}

namespace {

/// A solid cube of edge @p size resting flat on incline(degrees), its centre above the origin.
DynamicObject boxOnIncline(Real degrees, Real size, Real mu) {
    const Real theta = degrees * kPi / 180;
    DynamicObject box = test::dynamicBox("crate", Real(0.5) * size * Vec3(std::sin(theta), std::cos(theta), 0),
                                         Vec3(size), 2, mu);
    // Turn the box's up axis (0,1,0) onto the incline's normal (sinθ, cosθ, 0): −θ about z.
    box.orientation = glm::angleAxis(-theta, Vec3(0, 0, 1));
    return box;
}

/// Angle between the box's up axis and its starting up axis, degrees.
Real tiltDegrees(const DynamicObject& box, const Quat& start) {
    const Vec3 up = box.orientation * Vec3(0, 1, 0);
    const Vec3 up0 = start * Vec3(0, 1, 0);
    return std::acos(std::clamp(glm::dot(up, up0), Real(-1), Real(1))) * 180 / kPi;
}

}  // namespace

TEST_CASE("A box slides down a 30 degree incline at g(sin(theta) - mu cos(theta))", "[friction]") {
    // A sliding block feels kinetic friction μ·m·g·cosθ up the slope, spread over
    // its four corners; the total, not the split, sets the acceleration.
    const Real theta = 30, mu = 0.3;
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
    scene.planes.push_back(incline(theta));
    scene.dynamics.push_back(boxOnIncline(theta, 1, mu));
    World world(scene);
    const Quat start = world.dynamics()[0].orientation;
    while (world.time() < 2 - 1e-9) world.step();
    const Real t = theta * kPi / 180;
    const Real expected = kStandardGravity * (std::sin(t) - mu * std::cos(t));
    const DynamicObject& box = world.dynamics()[0];
    CHECK_THAT(glm::dot(box.velocity, downSlope(theta)) / world.time(), WithinRel(double(expected), 0.01));
    CHECK(tiltDegrees(box, start) < 0.5);  // it slides flat: no tumbling
}

TEST_CASE("A box slides at g(sin(theta) - mu cos(theta)) whichever way the slope faces, and straight down it", "[friction]") {
    // Physics does not care which way the incline faces: the same incline and box turned about
    // the vertical by phi must slide the same way. The contact's two friction rows share one
    // effective mass (frictionPairMass()); with a mass of its own on each, a box's friction was
    // not against its sliding where the slope lay between the tangents: up to 7 % fast, and
    // drifting sideways.
    const Real theta = 30, mu = 0.3, t = theta * kPi / 180;
    const Real expected = kStandardGravity * (std::sin(t) - mu * std::cos(t));
    for (const Real phi : {Real(0), Real(15), Real(30), Real(45), Real(60), Real(90)}) {
        const Quat turn = glm::angleAxis(phi * kPi / 180, Vec3(0, 1, 0));
        Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
        CollisionPlane plane = incline(theta);
        plane.normal = turn * plane.normal;
        scene.planes.push_back(plane);
        DynamicObject box = boxOnIncline(theta, 1, mu);
        box.position = turn * box.position;
        box.orientation = turn * box.orientation;
        scene.dynamics.push_back(box);
        World world(scene);
        while (world.time() < 2 - 1e-9) world.step();
        const Vec3 down = turn * downSlope(theta);
        const Vec3 across = glm::cross(plane.normal, down);
        const Vec3 v = world.dynamics()[0].velocity;
        INFO("slope turned by " << phi << " degrees");
        CHECK_THAT(glm::dot(v, down) / world.time(), WithinRel(double(expected), 0.01));
        CHECK(std::abs(glm::dot(v, across)) < 0.01 * glm::dot(v, down));
    }
}

TEST_CASE("A box with mu > tan(theta) stays put on the incline", "[friction]") {
    // Static friction can hold up to μ·m·g·cosθ ≥ m·g·sinθ when μ ≥ tanθ = 0.577.
    const Real theta = 30;
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
    scene.planes.push_back(incline(theta));
    scene.dynamics.push_back(boxOnIncline(theta, 1, 0.8));
    World world(scene);
    const Vec3 start = world.dynamics()[0].position;
    Real drift = 0;
    while (world.time() < 2) {
        world.step();
        drift = std::max(drift, glm::length(world.dynamics()[0].position - start));
    }
    CHECK(drift < 1e-3);
}

TEST_CASE("A box on a table tips once its centre of mass overhangs the edge, not before", "[friction][contacts]") {
    // Resting on a support, gravity's torque about the table edge is m·g·(x_c − x_edge):
    // it turns the box over the edge only when the centre of mass x_c is past it.
    const Real edge = 1, size = 0.5;
    for (Real overhang : {Real(-0.02), Real(0.02)}) {
        Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
        scene.kinematics.push_back(test::kinematicBox("table", Vec3(0, -0.5, 0), Vec3(2 * edge, 1, 2)));
        scene.dynamics.push_back(test::dynamicBox("crate", Vec3(edge + overhang, size / 2, 0), Vec3(size), 1, 0.6));
        World world(scene);
        Real tilt = 0;  // the largest tilt seen: once over the edge the box tumbles as it falls
        while (world.time() < 2) {
            world.step();
            tilt = std::max(tilt, tiltDegrees(world.dynamics()[0], Quat(1, 0, 0, 0)));
        }
        const Real height = world.dynamics()[0].position.y;
        INFO("overhang " << overhang << " m, largest tilt " << tilt << " degrees, final height " << height << " m");
        if (overhang < 0) {
            CHECK(tilt < 1);
            CHECK(std::abs(height - size / 2) < 1e-3);
        } else {
            CHECK(tilt > 45);  // tipped over the edge...
            CHECK(height < -1);  // ...and fell off the table
        }
    }
}

TEST_CASE("A box pushed slowly towards a table edge starts to tip as its centre passes the edge", "[friction][contacts]") {
    // A kinematic pusher at v = 0.1 m/s slides the box along the table. Not
    // before its centre crosses the edge (x = 1) may it tilt (< 0.5°). After,
    // linearising the turn φ about the edge while the push goes on,
    //   I_e·φ'' = m·g·(v·t + (a/2)·φ),  I_e = ⅔·m·a²  (cube of edge a about an edge)
    // gives φ(t) = (v/(a/2))·(sinh(k·t)/k − t) with k = √(m·g·(a/2)/I_e) = 3.84/s:
    // 2° after 0.32 s, when the centre is 3.2 cm past the edge. The test
    // allows up to 5 cm (the pusher, low on the box, keeps it from turning freely).
    const Real edge = 1, size = 0.5;
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 120);
    KinematicsObject table = test::kinematicBox("table", Vec3(0, -0.5, 0), Vec3(2 * edge, 1, 2));
    table.friction = 0.3;
    scene.kinematics.push_back(table);
    // Touching the box's left face (x = 0.25), low down.
    KinematicsObject pusher = test::kinematicBox("pusher", Vec3(0.25 - 0.05, 0.1, 0), Vec3(0.1, 0.2, 0.6), Vec3(0.1, 0, 0));
    pusher.friction = 0;
    scene.kinematics.push_back(pusher);
    scene.dynamics.push_back(test::dynamicBox("crate", Vec3(0.5, size / 2, 0), Vec3(size), 1, 1));
    World world(scene);
    Real tippedAt = -1, tiltBeforeEdge = 0;
    while (world.time() < 12 && tippedAt < 0) {
        world.step();
        const Real tilt = tiltDegrees(world.dynamics()[0], Quat(1, 0, 0, 0));
        if (world.dynamics()[0].position.x < edge) tiltBeforeEdge = std::max(tiltBeforeEdge, tilt);
        if (tilt > 2) tippedAt = world.dynamics()[0].position.x;
    }
    INFO("centre of mass at x = " << tippedAt << " when the tilt passed 2 degrees");
    CHECK(tiltBeforeEdge < 0.5);
    CHECK(tippedAt >= edge);
    CHECK(tippedAt < edge + 0.05);
}

TEST_CASE("A ball dropped with spin-free sideways speed ends rolling at 5/7 of it, however deep it lands", "[friction]") {
    // The landing is an impact (it may sink several cm into the floor in one
    // step), then the ball slides and spins up. Friction acts at the ball's own
    // lowest point, so angular momentum about the contact line gives 5/7·v0
    // whatever the landing depth: the same at a coarse and a fine step.
    // (The sequential-impulse ball rests within its soft contact's sag g/ω².)
    for (SolverKind solver : {SolverKind::Impulse, SolverKind::SequentialImpulse}) {
        for (Real h : {Real(1) / 60, Real(1) / 1000}) {
            Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, h);
            scene.settings.solver = solver;
            scene.settings.sleeping = false;
            scene.planes.push_back(test::ground());
            scene.dynamics.push_back(test::sphere("ball", Vec3(0, 1.1, 0), Vec3(2, 0, 0), 0.1, 1, 0, 0.3));
            World world(scene);
            while (world.time() < 3) world.step();
            INFO(toString(solver) << ", h = " << h);
            const Real sag = solver == SolverKind::Impulse ? Real(0) : restingSag(scene.settings);
            CHECK_THAT(world.dynamics()[0].velocity.x, WithinRel(double(Real(5) / 7 * 2), 1e-6));
            CHECK_THAT(world.dynamics()[0].position.y, WithinAbs(0.1 - sag, 1e-9 + 0.1 * sag));  // on the floor, not above it
        }
    }
}

TEST_CASE("A box resting on a box on the floor stays put for 10 s", "[friction][contacts]") {
    // Static equilibrium: every contact holds its share of the weight, nothing
    // slides or turns. The top box may move by no more than 2 mm in 10 s and
    // tilt by no more than 0.5°. (Before speculative points and angular
    // position correction it wandered 7 cm and never came to rest.)
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
    scene.planes.push_back(test::ground());
    scene.dynamics.push_back(test::dynamicBox("bottom", Vec3(0, 0.5, 0), Vec3(1), 1, 0.5));
    scene.dynamics.push_back(test::dynamicBox("top", Vec3(0, 1.5, 0), Vec3(1), 1, 0.5));
    World world(scene);
    Real drift = 0, tilt = 0;
    while (world.time() < 10) {
        world.step();
        drift = std::max(drift, glm::length(world.dynamics()[1].position - Vec3(0, 1.5, 0)));
        tilt = std::max(tilt, tiltDegrees(world.dynamics()[1], Quat(1, 0, 0, 0)));
    }
    CHECK(drift < 2e-3);
    CHECK(tilt < 0.5);
}

TEST_CASE("A ball rolling slowly into a wall bounces back: gravity does not make a sideways contact resting", "[friction]") {
    // Rolling without slipping at 0.2 m/s into a wall with e = 1, no friction at
    // the wall: the normal velocity reverses. 0.2 m/s is below 2·g·h = 0.33 m/s,
    // the resting threshold a vertical contact would have, but gravity has no
    // component along the wall's normal, so this is an impact.
    Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
    scene.planes.push_back(test::ground());
    CollisionPlane wall = test::ground("wall");
    wall.position = Vec3(1, 0, 0);
    wall.normal = Vec3(-1, 0, 0);
    wall.friction = 0;
    scene.planes.push_back(wall);
    DynamicObject ball = test::sphere("ball", Vec3(0, 0.25, 0), Vec3(0.2, 0, 0), 0.25, 1, 1, 0.5);
    ball.angularVelocity = Vec3(0, 0, -0.2 / 0.25);  // rolling: v = −ω_z·R
    scene.dynamics.push_back(ball);
    World world(scene);  // the World derives L = I·ω from the rolling ω
    // It reaches the wall (x = 0.75) at t = 3.75 s and rolls back at 5/7·0.2 − 2/7·0.2 ≈ 0.086 m/s
    // (the ground's friction turns the reversed slide with forward spin into rolling): x ≈ 0.39 at 8 s.
    while (world.time() < 8) world.step();
    CHECK(world.dynamics()[0].velocity.x < -0.05);  // came back off the wall
    CHECK(world.dynamics()[0].position.x < 0.5);
}

TEST_CASE("Three balls stacked as a triangle stand when mu reaches 2 - sqrt(3) between them, and fall apart below it", "[friction][contacts]") {
    // Two balls side by side on the floor, just touching, a third resting on both: its centre
    // is √3·R above theirs and each upper contact's normal is 60° above the horizontal. The top
    // ball pushes the lower ones apart; only friction holds them (their own contact can only
    // push). Per lower ball, with N and F the normal and friction force from the top ball and
    // f the floor's friction: the torques about its centre give f = F, the horizontal forces
    // N/2 = F·(1 + √3/2), the top ball's weight N·√3 + F = m·g. So F/N = 1/(2 + √3) = 2 − √3
    // = 0.268 between the balls, and f/N_floor = (2 − √3)/3 = 0.089 on the floor (N_floor = 3/2·m·g).
    // Coulomb: the stack stands if μ_balls ≥ 2 − √3 (and μ_floor ≥ 0.089), else the top ball
    // slides down between the lower ones. A contact's μ is the product of its bodies' (the
    // floor's factor is 1): balls of friction √μ give μ between them and √μ on the floor.
    // Both kinds of relax pass (RelaxBallFriction) must put the line between 0.25 and 0.29
    // (measured: at 0.2703 by default, 0.2698 with the relax's friction; exact 0.2679).
    const Real R = 0.5;
    const Real threshold = 2 - std::sqrt(Real(3));
    const bool relaxBallFriction = GENERATE(false, true);
    for (const Real mu : {Real(0.25), Real(0.29)}) {  // 7 % below and 8 % above the threshold
        Scene scene = test::emptyScene(IntegratorKind::SymplecticEuler, Real(1) / 60);
        scene.settings.relaxBallFriction = relaxBallFriction;
        scene.settings.sleeping = false;  // a stack that creeps must not be saved by falling asleep
        scene.planes.push_back(test::ground());
        const Real f = std::sqrt(mu);
        const Vec3 topStart(0, R + std::sqrt(Real(3)) * R, 0);
        scene.dynamics.push_back(test::sphere("left", Vec3(-R, R, 0), Vec3(0), R, 1, 0, f));
        scene.dynamics.push_back(test::sphere("right", Vec3(R, R, 0), Vec3(0), R, 1, 0, f));
        scene.dynamics.push_back(test::sphere("top", topStart, Vec3(0), R, 1, 0, f));
        World world(scene);
        while (world.time() < 4) world.step();
        const Real drop = topStart.y - world.dynamics()[2].position.y;
        INFO("mu between the balls " << mu << " (threshold " << threshold << "), RelaxBallFriction " << relaxBallFriction
                                     << ": the top ball dropped " << drop << " m in 4 s");
        if (mu > threshold) CHECK(drop < 1e-3);  // stands: a millimetre at most in 4 s
        else CHECK(drop > R);                     // falls apart: the top ball comes down between the others
    }
}
