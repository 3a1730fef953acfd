// Materials: Material and MaterialPair records, Density instead of Mass, and the World's
// FrictionCombine and ElasticityCombine rules, against volumes, Coulomb's sliding distance
// v²/(2μg) and the bounce height e²·h. Tag: [materials].
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "config/scene_loader.hpp"
#include "objects/materials.hpp"
#include "test_support.hpp"

using namespace stepwise;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinRel;

namespace {

constexpr const char* kSource = "materials.scene";

/// The message of the ConfigError @p text raises ("" when it loads).
std::string loadError(const std::string& text) {
    try {
        (void)parseScene(text, kSource);
    } catch (const ConfigError& error) {
        return error.what();
    }
    return "";
}

/// The combined value of sides @p a and @p b under @p rule, written out independently of combine().
Real expectedCombine(CombineRule rule, Real a, Real b) {
    switch (rule) {
        case CombineRule::Product: return a * b;
        case CombineRule::Min: return std::min(a, b);
        case CombineRule::Max: return std::max(a, b);
        case CombineRule::Average: return (a + b) / 2;
        case CombineRule::GeometricMean: return std::sqrt(a * b);
    }
    return 0;
}

/// How far a 1 m box sliding at @p speed along the floor goes before it stops, m.
Real slideDistance(const std::string& text, Real speed) {
    World world(parseScene(text, kSource));
    const Real start = world.dynamics()[0].position.x;
    const Real tooLong = 4 * speed / (Real(0.05) * kStandardGravity);  // 4 times the stop at μ = 0.05
    while (world.time() < tooLong && (world.time() == 0 || std::abs(world.dynamics()[0].velocity.x) > 1e-6)) {
        world.step();
    }
    return world.dynamics()[0].position.x - start;
}

/// The scene of slideDistance(): a box of friction @p boxFriction sliding at @p speed on a floor of
/// friction @p floorFriction, with @p world (the World record) and @p extra records.
std::string slidingBox(Real boxFriction, Real floorFriction, Real speed, const std::string& world,
                       const std::string& extra = "") {
    return "World, TimeStep=1/240, " + world + "\n" + extra +
           "CollisionPlane, Name=floor, Friction=" + std::to_string(floorFriction) + "\n"
           "DynamicObject, Name=crate, Shape=Box, Position=(0, 0.5, 0), Velocity=(" + std::to_string(speed) +
           ", 0, 0), Mass=1, Friction=" + std::to_string(boxFriction) + "\n";
}

/// The height of the ball's lowest point at its first apex after the first bounce, m (dropped from 1 m).
Real firstBounceHeight(const std::string& text) {
    World world(parseScene(text, kSource));
    const Real radius = world.dynamics()[0].radius;
    bool bounced = false;
    Real apex = 0;
    while (world.time() < 4) {
        world.step();
        const DynamicObject& ball = world.dynamics()[0];
        if (!bounced) {
            bounced = ball.velocity.y > 0;
        } else if (ball.velocity.y <= 0) {
            break;  // past the apex
        }
        if (bounced) apex = std::max(apex, ball.position.y - radius);
    }
    return apex;
}

const CombineRule kRules[] = {CombineRule::Product, CombineRule::Min, CombineRule::Max, CombineRule::Average,
                              CombineRule::GeometricMean};

}  // namespace

TEST_CASE("Density gives a sphere 4/3 pi r^3 rho and a box abc rho, and the inertia that mass", "[materials]") {
    const Scene scene = parseScene("DynamicObject, Name=ball, Radius=0.3, Density=1100\n"
                                   "DynamicObject, Name=plank, Shape=Box, Scale=(2, 0.1, 0.5), Density=600\n"
                                   "Material, Name=steel, Density=7850\n"
                                   "DynamicObject, Name=cube, Shape=Box, Scale=(0.2, 0.2, 0.2), Material=steel\n",
                                   kSource);
    const Real ball = Real(4) / 3 * kPi * Real(0.027) * 1100;  // 124.4 kg
    CHECK_THAT(scene.dynamics[0].mass, WithinRel(double(ball), 1e-12));
    CHECK_THAT(scene.dynamics[1].mass, WithinRel(2 * 0.1 * 0.5 * 600.0, 1e-12));  // 60 kg
    CHECK_THAT(scene.dynamics[2].mass, WithinRel(0.008 * 7850.0, 1e-12));        // the material's density: 62.8 kg
    // The World fills the inertia from that mass: a box's I_x = m(b² + c²)/12.
    World world(scene);
    const Real m = 60;
    CHECK_THAT(world.dynamics()[1].inertiaBody.x, WithinRel(double(m * (0.01 + 0.25) / 12), 1e-12));
    CHECK_THAT(world.dynamics()[0].inertiaBody.x, WithinRel(double(Real(0.4) * ball * Real(0.09)), 1e-12));
}

TEST_CASE("Density fills a capsule, a compound body, a part and a hull", "[materials]") {
    const Scene scene = parseScene(
        "DynamicObject, Name=pill, Shape=Capsule, Radius=0.1, Height=0.5, Density=1000\n"
        "DynamicObject, Name=ell, Shape=Compound, Density=250\n"
        "Part, Body=ell, Shape=Box, Scale=(2, 1, 1)\n"
        "Part, Body=ell, Shape=Box, Position=(0.5, 1, 0), Scale=(1, 1, 1)\n"
        "DynamicObject, Name=hammer, Shape=Compound\n"
        "Part, Body=hammer, Shape=Box, Scale=(0.1, 0.1, 0.1), Density=7850\n"
        "Part, Body=hammer, Shape=Cylinder, Radius=0.02, Height=0.3, Position=(0, -0.2, 0), Mass=0.2\n"
        "DynamicObject, Name=corner, Shape=Hull, Vertices=(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), Density=600\n",
        kSource);
    const Real pill = (kPi * Real(0.01) * Real(0.5) + Real(4) / 3 * kPi * Real(0.001)) * 1000;
    CHECK_THAT(scene.dynamics[0].mass, WithinRel(double(pill), 1e-12));
    CHECK_THAT(scene.dynamics[1].mass, WithinRel(3 * 250.0, 1e-12));  // 3 m³ of parts
    CHECK_THAT(scene.dynamics[2].mass, WithinRel(0.001 * 7850 + 0.2, 1e-12));
    CHECK_THAT(scene.dynamics[3].mass, WithinRel(600.0 / 6, 1e-12));  // the unit corner tetrahedron: V = 1/6 m³
}

TEST_CASE("An object's own Friction, Elasticity and Mass win over its material's", "[materials]") {
    const Scene scene = parseScene("DynamicObject, Name=plain, Material=rubber\n"
                                   "DynamicObject, Name=own, Material=rubber, Friction=0.3, Mass=2\n"
                                   "CollisionPlane, Name=rink, Material=ice\n"
                                   "KinematicsObject, Name=paddle, Material=rubber, Elasticity=0.1\n"
                                   // declared after their use: materials may stand anywhere in the file
                                   "Material, Name=rubber, Density=1100, Friction=0.9, Elasticity=0.8\n"
                                   "Material, Name=ice, Friction=0.02\n",
                                   kSource);
    const DynamicObject& plain = scene.dynamics[0];
    CHECK(plain.friction == Real(0.9));
    CHECK(plain.elasticity == Real(0.8));
    CHECK_THAT(plain.mass, WithinRel(double(Real(4) / 3 * kPi * Real(0.125) * 1100), 1e-12));
    CHECK(plain.material == 0);
    const DynamicObject& own = scene.dynamics[1];
    CHECK(own.friction == Real(0.3));
    CHECK(own.elasticity == Real(0.8));
    CHECK(own.mass == 2);
    CHECK(scene.planes[0].friction == Real(0.02));
    CHECK(scene.planes[0].elasticity == 1);  // ice gives no Elasticity: the plane's default
    CHECK(scene.planes[0].material == 1);
    CHECK(scene.kinematics[0].friction == Real(0.9));
    CHECK(scene.kinematics[0].elasticity == Real(0.1));
}

TEST_CASE("A scene without materials keeps the mass, friction and elasticity defaults", "[materials]") {
    const Scene scene = parseScene("DynamicObject\nCollisionPlane\n", kSource);
    CHECK(scene.dynamics[0].mass == 1);
    CHECK(scene.dynamics[0].friction == Real(0.5));
    CHECK(scene.dynamics[0].material == kNoMaterial);
    CHECK(scene.planes[0].material == kNoMaterial);
    CHECK(scene.settings.frictionCombine == CombineRule::Product);
    CHECK(scene.settings.elasticityCombine == CombineRule::Product);
}

TEST_CASE("Mass and Density on one object is an error at the Density", "[materials]") {
    CHECK(loadError("DynamicObject, Name=ball, Mass=2, Density=1000\n") ==
          "materials.scene:1:43: error: Density: expected either Mass or Density, not both, found '1000'; "
          "Mass is given at column 32; with Density the mass is density x the shape's volume");
    CHECK_THAT(loadError("DynamicObject, Name=c, Shape=Compound, Mass=1\nPart, Body=c, Mass=1, Density=2\n"),
               Contains("materials.scene:2:31: error: Density: expected either Mass or Density, not both"));
    // A density whose mass the World cannot take: 1e-20 kg/m³ × 0.52 m³ is below 1e-12 kg.
    CHECK_THAT(loadError("DynamicObject, Density=1e-20\n"),
               Contains("1:24: error: Density: expected a mass from 1e-12 to 1e12 kg as density x volume"));
    // A hollow sphere has no volume for a density.
    CHECK_THAT(loadError("DynamicObject, Hollow=true, Density=100\n"),
               Contains("1:37: error: Density: expected Mass for a hollow sphere"));
}

TEST_CASE("An unknown material is an error naming it, with a spelling suggestion", "[materials]") {
    CHECK(loadError("Material, Name=rubber, Friction=0.9\nDynamicObject, Name=ball, Material=rubbr\n") ==
          "materials.scene:2:36: error: Material: expected the Name of a Material in this file, found 'rubbr'; "
          "did you mean 'rubber'?");
    CHECK_THAT(loadError("DynamicObject, Name=ball\nCollisionPlane, Material=ball\n"),
               Contains("2:26: error: Material: expected the Name of a Material in this file, found 'ball'; "
                        "'ball' is the DynamicObject on line 1, not a Material"));
    CHECK_THAT(loadError("Material, Name=ice\nMaterialPair, A=ice, B=rubber, Friction=0.1\n"),
               Contains("2:24: error: B: expected the Name of a Material in this file, found 'rubber'"));
    CHECK_THAT(loadError("Material, Friction=0.5\n"), Contains("1:1: error: Name: expected a Name for the Material"));
    CHECK_THAT(loadError("Material, Name=ice\nMaterialPair, A=ice, B=ice\n"),
               Contains("2:1: error: MaterialPair: expected Friction=..., Elasticity=... or both"));
    CHECK_THAT(loadError("World, FrictionCombine=Mean\n"), Contains("FrictionCombine"));
}

TEST_CASE("combine() gives each rule's formula, symmetric in its sides", "[materials]") {
    for (const CombineRule rule : kRules) {
        INFO(toString(rule));
        for (const auto& [a, b] : {std::pair<Real, Real>{0.2, 0.8}, {1, 0.5}, {0, 0.7}, {1.5, 0.4}}) {
            CHECK_THAT(combine(rule, a, b), WithinRel(double(expectedCombine(rule, a, b)), 1e-15));
            CHECK(combine(rule, a, b) == combine(rule, b, a));
        }
    }
}

TEST_CASE("Each FrictionCombine rule sets the contact's mu: a box slides v^2/(2 mu g) before it stops", "[materials]") {
    // Coulomb: a box sliding at v on a level floor decelerates at μ·g and stops after v²/(2μg).
    // The box's μ is 0.2, the floor's 0.8: products 0.16, min 0.2, max 0.8, mean 0.5, geometric 0.4.
    // Tolerance: the stop falls within one step, so the distance may be off by v·h (1.25 cm at
    // 3 m/s and h = 1/240 s), plus 1 % for the soft contact's sag into the floor.
    const Real v = 3, h = Real(1) / 240;
    for (const CombineRule rule : kRules) {
        const Real mu = expectedCombine(rule, Real(0.2), Real(0.8));
        const Real expected = v * v / (2 * mu * kStandardGravity);
        for (const char* solver : {"SequentialImpulse", "Impulse"}) {
            const std::string world = std::string("FrictionCombine=") + toString(rule) + ", Solver=" + solver;
            const Real distance = slideDistance(slidingBox(0.2, 0.8, v, world), v);
            INFO(world << ": mu = " << mu << ", slid " << distance << " m, expected " << expected << " m");
            CHECK(std::abs(distance - expected) <= v * h + Real(0.01) * expected);
        }
    }
}

TEST_CASE("The fast path and the plain path slide a box on a material pair alike, bit for bit", "[materials][fast]") {
    const std::string extra = "Material, Name=wood, Friction=0.6\nMaterial, Name=ice, Friction=0.05\n"
                              "MaterialPair, A=ice, B=wood, Friction=0.3\n";
    const std::string base = "World, TimeStep=1/240, FrictionCombine=GeometricMean, FastPath=";
    const std::string bodies = "CollisionPlane, Name=floor, Material=ice\n"
                               "DynamicObject, Name=a, Shape=Box, Position=(0, 0.5, 0), Velocity=(3, 0, 0), Material=wood\n"
                               "DynamicObject, Name=b, Position=(0, 0.5, 3), Velocity=(3, 0, 0), Material=wood\n";
    World fast(parseScene(base + "true\n" + extra + bodies, kSource));
    World plain(parseScene(base + "false\n" + extra + bodies, kSource));
    for (int i = 0; i < 240; ++i) {
        fast.step();
        plain.step();
    }
    for (std::size_t k = 0; k < 2; ++k) {
        INFO(plain.dynamics()[k].name);
        CHECK(fast.dynamics()[k].position == plain.dynamics()[k].position);
        CHECK(fast.dynamics()[k].velocity == plain.dynamics()[k].velocity);
    }
    // The pair's μ = 0.3 acts, not the geometric mean √(0.6·0.05) = 0.17: after 1 s the box has
    // slowed by μ·g·t = 2.94 m/s, to 0.06 m/s.
    CHECK(std::abs(plain.dynamics()[0].velocity.x - (3 - Real(0.3) * kStandardGravity)) < 0.02);
}

TEST_CASE("Each ElasticityCombine rule sets the contact's e: a ball dropped 1 m rebounds to e^2 m", "[materials]") {
    // The ball's elasticity is 0.4, the floor's 0.9: products 0.36, min 0.4, max 0.9, mean 0.65,
    // geometric 0.6. The bounce keeps e² of the drop height (lecture 3, whose v_c makes it
    // independent of the step); tolerance 5 mm, a sixth of the closest two rules' difference.
    for (const CombineRule rule : kRules) {
        const Real e = expectedCombine(rule, Real(0.4), Real(0.9));
        const std::string text = std::string("World, TimeStep=1/240, ElasticityCombine=") + toString(rule) +
                                 "\nCollisionPlane, Elasticity=0.9\nDynamicObject, Position=(0, 1.5, 0), Elasticity=0.4\n";
        const Real height = firstBounceHeight(text);
        INFO(toString(rule) << ": e = " << e << ", rebounds to " << height << " m");
        CHECK(std::abs(height - e * e) <= Real(0.005));
    }
}

TEST_CASE("A MaterialPair's values beat the rule, whichever order it names A and B", "[materials]") {
    // Rubber (μ 0.9) on ice (μ 0.02) would be 0.018 by product; the pair says 0.5.
    const std::string materials = "Material, Name=rubber, Friction=0.9, Elasticity=0.8\n"
                                  "Material, Name=ice, Friction=0.02, Elasticity=0.1\n";
    const Real v = 3, h = Real(1) / 240;
    const Real expected = v * v / (2 * Real(0.5) * kStandardGravity);  // 0.917 m
    for (const char* pair : {"MaterialPair, A=rubber, B=ice, Friction=0.5\n",
                             "MaterialPair, A=ice, B=rubber, Friction=0.5\n"}) {
        const std::string text = std::string("World, TimeStep=1/240\n") + materials + pair +
                                 "CollisionPlane, Material=ice\n"
                                 "DynamicObject, Shape=Box, Position=(0, 0.5, 0), Velocity=(3, 0, 0), Material=rubber\n";
        const Real distance = slideDistance(text, v);
        INFO(pair << "slid " << distance << " m, expected " << expected << " m");
        CHECK(std::abs(distance - expected) <= v * h + Real(0.01) * expected);
    }
    // The table itself: the pair's μ in both orders, the rule's e where the pair gives none.
    WorldSettings settings;
    settings.elasticityCombine = CombineRule::Max;
    const MaterialPair pair{1, 0, Real(0.5), std::nullopt};
    const ContactMaterials table(settings, 2, std::span<const MaterialPair>(&pair, 1));
    const ContactCoefficients ab = table.mix(0, Real(0.9), Real(0.8), 1, Real(0.02), Real(0.1));
    const ContactCoefficients ba = table.mix(1, Real(0.02), Real(0.1), 0, Real(0.9), Real(0.8));
    CHECK(ab.friction == Real(0.5));
    CHECK(ba.friction == Real(0.5));
    CHECK(ab.elasticity == Real(0.8));
    CHECK(ba.elasticity == Real(0.8));
    // Rubber on rubber is not the pair: the rule (Product) decides.
    CHECK(table.mix(0, Real(0.9), Real(0.8), 0, Real(0.9), Real(0.8)).friction == Real(0.9) * Real(0.9));
}

TEST_CASE("Under FrictionCombine=Max a frictionless ball on a rough floor is made to roll", "[materials][plan]") {
    // With the product μ = 0·0.5 = 0 and the ball slides for ever; the step plan then skips its
    // rotation. With Max μ = 0.5: friction turns it until it rolls at 5/7 of its speed.
    const std::string bodies = "CollisionPlane, Friction=0.5\nDynamicObject, Position=(0, 0.5, 0), Velocity=(2, 0, 0), Friction=0\n";
    World product(parseScene("World, FrictionCombine=Product\n" + bodies, kSource));
    World max(parseScene("World, FrictionCombine=Max\n" + bodies, kSource));
    for (int i = 0; i < 120; ++i) {
        product.step();
        max.step();
    }
    CHECK(product.dynamics()[0].velocity.x == Real(2));
    CHECK_THAT(max.dynamics()[0].velocity.x, WithinRel(2.0 * 5 / 7, 0.01));
}

TEST_CASE("A scene's trajectory is the same, bit for bit, when materials are declared but give the products",
          "[materials]") {
    // The unused pair makes every contact go through ContactMaterials::mix() with the Product rule;
    // the bodies must move exactly as on the plain products.
    const std::string bodies = "World, Duration=2\nCollisionPlane, Friction=0.7\n"
                               "DynamicObject, Shape=Box, Position=(0, 0.6, 0), Velocity=(2, 0, 1), Rotation=(10, 20, 5), Friction=0.4, Elasticity=0.6\n"
                               "DynamicObject, Position=(1, 2, 0), Velocity=(-1, 0, 0), Elasticity=0.9\n";
    const std::string unused = "Material, Name=a, Friction=0.1\nMaterial, Name=b\nMaterialPair, A=a, B=b, Friction=1\n";
    World plain(parseScene(bodies, kSource));
    World mixed(parseScene(bodies + unused, kSource));
    for (int i = 0; i < 120; ++i) {
        plain.step();
        mixed.step();
    }
    for (std::size_t k = 0; k < 2; ++k) {
        CHECK(plain.dynamics()[k].position == mixed.dynamics()[k].position);
        CHECK(plain.dynamics()[k].orientation == mixed.dynamics()[k].orientation);
        CHECK(plain.dynamics()[k].velocity == mixed.dynamics()[k].velocity);
    }
}

TEST_CASE("A compound's part takes its Material's density, and its contacts its friction", "[materials][shapes]") {
    // A sled: a wide runner under a smaller box, sliding at v on a floor of μ = 1 (products).
    // The body's Friction is 0.8; a runner of Material=ice (μ 0.05) touches the floor with the
    // ice's μ: it slides v²/(2·0.05·g) = 9.17 m, where the body's own μ would stop it after
    // v²/(2·0.8·g) = 0.57 m. Tolerance as in the FrictionCombine test above: one step's v·h and 1 %.
    const Real v = 3, h = Real(1) / 240;
    const auto sled = [](const std::string& runner, const std::string& solver) {
        return "World, TimeStep=1/240, Solver=" + solver + "\n"
               "Material, Name=ice, Friction=0.05\n"
               "CollisionPlane, Name=floor, Friction=1\n"
               "DynamicObject, Name=sled, Shape=Compound, Position=(0, 0.3, 0), Velocity=(3, 0, 0), Mass=1, "
               "Friction=0.8\n"
               "Part, Body=sled, Shape=Box, Position=(0, -0.2, 0), Scale=(1, 0.2, 1)" + runner + "\n"
               "Part, Body=sled, Shape=Box, Position=(0, 0.1, 0), Scale=(0.6, 0.4, 0.6)\n";
    };
    for (const char* solver : {"SequentialImpulse", "Impulse"}) {
        INFO(solver);
        for (const auto& [runner, mu] : {std::pair<std::string, Real>{", Material=ice", Real(0.05)}, {"", Real(0.8)}}) {
            const Real expected = v * v / (2 * mu * kStandardGravity);
            const Real distance = slideDistance(sled(runner, solver), v);
            INFO("runner '" << runner << "': mu = " << mu << ", slid " << distance << " m, expected " << expected);
            CHECK(std::abs(distance - expected) <= v * h + Real(0.01) * expected);
        }
    }

    // Density: every part with a Material of its own is ρ·V (a part's material density counts as its Mass).
    const Scene scene = parseScene("Material, Name=ice, Density=900\nMaterial, Name=oak, Density=700\n"
                                   "DynamicObject, Name=sled, Shape=Compound\n"
                                   "Part, Body=sled, Shape=Box, Scale=(1, 0.2, 1), Material=ice\n"
                                   "Part, Body=sled, Shape=Sphere, Radius=0.5, Position=(0, 1, 0), Material=oak\n",
                                   kSource);
    const Real expectedMass = 900 * Real(0.2) + 700 * Real(4) / 3 * kPi * Real(0.125);
    CHECK_THAT(double(scene.dynamics[0].mass), WithinRel(double(expectedMass), 1e-12));
}

TEST_CASE("A compound's part bounces with its Material's elasticity: e^2 of the drop", "[materials][shapes]") {
    // A compound of one ball part (radius 0.5 m, so firstBounceHeight()'s radius) dropped 1 m onto a
    // floor of e = 1 (products). The body's Elasticity is 0.2; the part's material gives 0.8, and the
    // bounce keeps e² = 0.64 of the drop (0.04 with the body's). Tolerance 5 mm, as above.
    for (const auto& [material, e] : {std::pair<std::string, Real>{", Material=rubber", Real(0.8)}, {"", Real(0.2)}}) {
        const std::string text = "World, TimeStep=1/240\nMaterial, Name=rubber, Elasticity=0.8\n"
                                 "CollisionPlane, Elasticity=1\n"
                                 "DynamicObject, Name=ball, Shape=Compound, Position=(0, 1.5, 0), Elasticity=0.2\n"
                                 "Part, Body=ball, Shape=Sphere, Radius=0.5" + material + "\n";
        const Real height = firstBounceHeight(text);
        INFO("part '" << material << "': e = " << e << ", rebounds to " << height << " m");
        CHECK(std::abs(height - e * e) <= Real(0.005));
    }
}

TEST_CASE("An unknown material on a part is an error naming it", "[materials][shapes]") {
    CHECK_THAT(loadError("Material, Name=ice, Friction=0.05\nDynamicObject, Name=sled, Shape=Compound\n"
                         "Part, Body=sled, Shape=Box, Material=icy\n"),
               Contains("materials.scene:3:38: error: Material: expected the Name of a Material in this file, "
                        "found 'icy'; did you mean 'ice'?"));
}
