/// @file prefetch.hpp
/// @brief Asking for a body's cache lines a few loop turns before they are read.
///
/// A walk over pairs or contacts reads body A in order, which the memory
/// prefetcher follows, and body B out of order: in a pile, B is often a
/// layer of the pile further on in the dynamic array. Once the bodies
/// outgrow the processor's caches (a DynamicObject is some 440 bytes: 27 MB
/// at 64 000 bodies) each B is a wait for main memory of about 100 ns, and
/// the loop asks for the next B only when it gets there. Naming B's lines
/// a few turns ahead lets those waits overlap. A prefetch is only a hint:
/// it changes no result, only when the lines arrive.
#pragma once

#include <cstddef>

namespace stepwise {

/// Bytes in a cache line of the x86-64 and ARMv8 processors this is built for: how far apart two
/// prefetches must be to ask for different lines.
inline constexpr std::size_t kPrefetchLine = 64;

/// @brief Asks for the cache lines that hold the bytes from @p first up to @p last (both included), to be read.
inline void prefetchRange(const void* first, const void* last) {
#if defined(__GNUC__)  // GCC and clang
    const char* from = static_cast<const char*>(first);
    const char* to = static_cast<const char*>(last);
    for (const char* byte = from; byte < to; byte += kPrefetchLine) __builtin_prefetch(byte);
    __builtin_prefetch(to);  // the line of the last byte, whichever line the first began on
#else
    (void)first, (void)last;
#endif
}

}  // namespace stepwise
