// The order of a pass: greedy colouring of the contacts (src/dynamics/contact_colours.hpp).
// Tags: [solver], [colours].
//
// Claims: the colour order is a permutation of the contacts; no two contacts
// of one colour share a dynamic body (a plane or a kinematic body may be
// shared); each colour keeps the order found; every contact took the lowest
// colour free when it came (greedy); a body in more than kColourCount
// colours sends its further contacts to one last group, in order; and with
// ContactOrder=Found the lists are left as found.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "collision/broadphase.hpp"
#include "collision/narrowphase.hpp"
#include "config/scene_loader.hpp"
#include "dynamics/contact_colours.hpp"
#include "dynamics/contact_solver.hpp"
#include "objects/inertia.hpp"
#include "test_support.hpp"
#include "world/world.hpp"

using namespace stepwise;

namespace {

/// The colours of @p ordered (a list in colour order) worked out again from scratch, independently of
/// orderByColour(): greedy colouring of @p found, in its order, with a set of colours per body.
std::vector<std::uint32_t> greedyColours(const SolverWorkspace& w, const std::vector<std::uint32_t>& found) {
    std::vector<std::vector<std::uint32_t>> used(w.bodies.size());
    std::vector<std::uint32_t> colour(w.contacts.size(), 0);
    for (const std::uint32_t index : found) {
        const SolverContact& c = w.contacts[index];
        auto taken = [&](std::uint32_t k) {
            auto in = [&](std::uint32_t record) {
                return record != kStaticSolverBody && std::count(used[record].begin(), used[record].end(), k) > 0;
            };
            return in(c.bodyA) || in(c.bodyB);
        };
        std::uint32_t k = 0;
        while (k < kColourCount && taken(k)) ++k;
        colour[index] = k;
        if (k == kColourCount) continue;  // the last group: no colour taken
        for (const std::uint32_t record : {c.bodyA, c.bodyB}) {
            if (record != kStaticSolverBody) used[record].push_back(k);
        }
    }
    return colour;
}

/// Checks @p ordered against @p found: a permutation, sorted by the greedy colour, found order within a colour,
/// no dynamic body twice in a colour. Returns how many colours it uses.
std::uint32_t requireColourOrder(const SolverWorkspace& w, const std::vector<std::uint32_t>& found,
                                 const std::vector<std::uint32_t>& ordered) {
    REQUIRE(ordered.size() == found.size());
    std::vector<std::uint32_t> a = found, b = ordered;
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    REQUIRE(a == b);
    std::vector<std::int64_t> foundAt(w.contacts.size(), -1);
    for (std::size_t k = 0; k < found.size(); ++k) foundAt[found[k]] = std::int64_t(k);
    const std::vector<std::uint32_t> colour = greedyColours(w, found);
    std::vector<std::uint32_t> inColour;  // dynamic records of the current colour
    std::uint32_t colours = 0;
    for (std::size_t k = 0; k < ordered.size(); ++k) {
        const std::uint32_t index = ordered[k];
        INFO("place " << k << ", contact " << index << ", colour " << colour[index]);
        if (k > 0) {
            const std::uint32_t before = ordered[k - 1];
            REQUIRE(colour[before] <= colour[index]);                                        // colour by colour
            if (colour[before] == colour[index]) CHECK(foundAt[before] < foundAt[index]);    // in the order found
            if (colour[before] != colour[index]) inColour.clear();
        }
        colours = std::max(colours, colour[index] + 1);
        if (colour[index] == kColourCount) continue;  // the last group is solved one by one: it may share bodies
        const SolverContact& c = w.contacts[index];
        for (const std::uint32_t record : {c.bodyA, c.bodyB}) {
            if (record == kStaticSolverBody) continue;
            CHECK(std::count(inColour.begin(), inColour.end(), record) == 0);  // no body twice in a colour
            inColour.push_back(record);
        }
    }
    return colours;
}

/// The pass lists as found, and as orderByColour() puts them, for the scene file @p name.
struct Lists {
    SolverWorkspace found;
    SolverWorkspace coloured;
};

void prepareBoth(const BodySet& bodies, const std::vector<Contact>& contacts, Lists& lists) {
    lists.found.colourOrder = false;
    prepareContacts(bodies, contacts, {}, Real(1) / 60, false, lists.found);
    prepareContacts(bodies, contacts, {}, Real(1) / 60, false, lists.coloured);  // colourOrder: the default
}

}  // namespace

TEST_CASE("Colour order: each colour shares no dynamic body and keeps the order found", "[solver][colours]") {
    // Each scene run for a while (the pile and the rain fall into place), then its contacts
    // prepared twice: as found, and in colour order.
    const char* name = GENERATE("lesson08_pyramid.scene", "lesson08_tower.scene", "bench_box_pile_1k.scene",
                                "bench_sphere_rain_1k.scene");
    INFO(name);
    World world(loadSceneFile(std::string(STEPWISE_SOURCE_DIR "/config/") + name));
    for (int step = 0; step < 90; ++step) world.step();
    std::vector<DynamicObject> dynamics = world.dynamics();
    const BodySet bodies{dynamics, world.kinematics(), world.planes()};
    const std::vector<Contact>& contacts = world.contacts();
    Lists lists;
    prepareBoth(bodies, contacts, lists);
    REQUIRE(lists.found.contacts.size() > 50);  // bodies in touch: something to colour
    // With ContactOrder=Found the lists are the contacts in index order
    CHECK(std::is_sorted(lists.found.otherContacts.begin(), lists.found.otherContacts.end()));
    CHECK(std::is_sorted(lists.found.roundContacts.begin(), lists.found.roundContacts.end()));
    requireColourOrder(lists.coloured, lists.found.roundContacts, lists.coloured.roundContacts);
    const std::uint32_t colours = requireColourOrder(lists.coloured, lists.found.otherContacts, lists.coloured.otherContacts);
    if (lists.found.otherContacts.empty()) return;  // the rain: balls only
    // Greedy needs at most 2·d − 1 colours for bodies of at most d contacts each
    std::vector<std::uint32_t> degree(lists.coloured.bodies.size(), 0);
    for (const std::uint32_t index : lists.coloured.otherContacts) {
        const SolverContact& c = lists.coloured.contacts[index];
        ++degree[c.bodyA];
        if (c.bodyB != kStaticSolverBody) ++degree[c.bodyB];
    }
    degree[kStaticSolverBody] = 0;
    const std::uint32_t most = *std::max_element(degree.begin(), degree.end());
    INFO(colours << " colours, at most " << most << " contacts on one body");
    CHECK(colours <= 2 * most - 1);
}

TEST_CASE("Colour order: a body in more than 64 colours sends its further contacts to one last group",
          "[solver][colours]") {
    // A heavy dynamic slab with 70 balls resting on it: every ball contact shares the slab, so each
    // takes a colour of its own until the slab's 64 bits are used up; the last 6 go to the last group.
    std::vector<DynamicObject> dynamics;
    DynamicObject slab = test::sphere("slab", Vec3(0, 0.5, 0), Vec3(0), 0.5, 100);
    slab.shape = Shape::Box;
    slab.scale = Vec3(20, 1, 20);
    dynamics.push_back(slab);
    for (int i = 0; i < 70; ++i) {
        dynamics.push_back(test::sphere("ball" + std::to_string(i), Vec3(-9 + 1.2 * (i % 14), 1.19, -4 + 1.2 * (i / 14)),
                                        Vec3(0), 0.2));
    }
    for (DynamicObject& body : dynamics) initialiseMassProperties(body);
    std::vector<KinematicsObject> kinematics;
    std::vector<CollisionPlane> planes;
    const BodySet bodies{dynamics, kinematics, planes};
    const std::vector<Contact> contacts = test::contactsOf(bodies);
    REQUIRE(contacts.size() == 70);
    Lists lists;
    prepareBoth(bodies, contacts, lists);
    const std::vector<std::uint32_t>& found = lists.found.otherContacts;
    const std::vector<std::uint32_t>& ordered = lists.coloured.otherContacts;
    REQUIRE(found.size() == 70);
    CHECK(requireColourOrder(lists.coloured, found, ordered) == kColourCount + 1);
    // One contact per colour, in the order found, then the six that found none, in order
    CHECK(ordered == found);
}
