// Counting every global operator new while a flag is up. The replacement of
// operator new lives in test_broadphase_allocations.cpp (a program may
// replace it only once); tests that count allocations share these two
// counters. Not under AddressSanitizer, which keeps its own operator new.
#pragma once

#include <atomic>
#include <cstddef>

namespace stepwise::test {

/// While true, every global operator new adds one to gAllocations.
extern std::atomic<bool> gCounting;
/// Allocations counted while gCounting was true.
extern std::atomic<std::size_t> gAllocations;

}  // namespace stepwise::test
