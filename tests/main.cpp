// The Catch2 runner for every test file in this folder, with one listing Catch2 v2 does not have.
//
// `stepwise_tests --list-labels` prints one line per test case that a plain run would run (hidden
// ones left out): its tags as Catch2 writes them, "[solver][slow]", a tab, and its name. It is what
// tests/catch_tags_as_labels.cmake turns into CTest labels after each build, in one run of the
// program. Catch2's own listings would take a run per tag: --list-tests wraps long names and tag
// lists over several lines, so only "[tag]" --list-test-names-only gives them unbroken, and a
// sanitized build of this program takes over half a second to start.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <cstring>
#include <iostream>

int main(int argc, char* argv[]) {
    if (argc == 2 && std::strcmp(argv[1], "--list-labels") == 0) {
        for (const Catch::TestCase& test : Catch::getRegistryHub().getTestCaseRegistry().getAllTests()) {
            if (test.isHidden()) continue;
            std::cout << test.tagsAsString() << '\t' << test.name << '\n';
        }
        return 0;
    }
    return Catch::Session().run(argc, argv);
}
