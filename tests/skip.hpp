// A test case that cannot run on this build says why, and CTest reports it as skipped, not passed.
//
// Catch2 v2 has no skip of its own: a test case that returns early passes. STEPWISE_SKIP(reason)
// prints the reason in a WARN that starts with "STEPWISE-SKIPPED:" and returns from the test case;
// tests/CMakeLists.txt gives every Catch2 test case's CTest test that text as its
// SKIP_REGULAR_EXPRESSION, so CTest lists it as "Skipped" under "The following tests did not run".
// (Run without CTest, stepwise_tests prints the warning and counts the test case as passed.)
//
// Skip before the test case's first check: CTest reports a test whose output holds the marker as
// skipped even if a check had failed. Skip only for what the build cannot do (a Release build
// has no locals for gdb to print), never for what is missing but should be there: a test whose
// tool is missing on a build that needs it fails, saying how to install it.
#pragma once

#include <catch2/catch.hpp>

#define STEPWISE_SKIP(reason)                       \
    do {                                            \
        WARN("STEPWISE-SKIPPED: " << reason);       \
        return;                                     \
    } while (false)
