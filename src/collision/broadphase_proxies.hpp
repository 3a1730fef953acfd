/// @file broadphase_proxies.hpp
/// @brief What the sweep-and-prune, tree and grid broadphases share: proxies and the pairs they report.
///
/// A *proxy* is one body as a broadphase sees it: an index and a bounding box.
/// The dynamic bodies come first (proxy i is dynamic body i), then the
/// kinematic ones (proxy dynamicCount + k is kinematic body k). Planes are not
/// proxies: an infinite plane has no bounding box, so every broadphase tests
/// each dynamic body against each plane directly (src/collision/broadphase.cpp).
/// The World's Broadphase hands the structures the dynamic bodies only and
/// keeps the kinematic ones in a tree of their own (broadphase_static.hpp); the
/// structures still take kinematic proxies, which they never pair together.
#pragma once

#include <cstdint>
#include <span>

#include "collision/aabb.hpp"

namespace stepwise {

/// @brief The boxes a broadphase sorts this step.
struct ProxySet {
    std::span<const Aabb> boxes;     ///< One per proxy: dynamic bodies, then kinematic bodies (broadphaseBounds()).
    std::uint32_t dynamicCount = 0;  ///< Proxies below this index are dynamic.

    /// @brief Number of proxies.
    std::uint32_t size() const { return static_cast<std::uint32_t>(boxes.size()); }
    /// @brief True for a kinematic body's proxy.
    bool isKinematic(std::uint32_t proxy) const { return proxy >= dynamicCount; }
};

/// @brief Two proxies whose boxes overlap, lower index first.
///
/// Because dynamic proxies come first, `a` is always a dynamic body; `b` is
/// a dynamic body (b < dynamicCount) or a kinematic one. Two kinematic bodies
/// never make a pair: neither can be pushed.
struct ProxyPair {
    std::uint32_t a = 0;  ///< Lower proxy index: a dynamic body.
    std::uint32_t b = 0;  ///< Higher proxy index.
};

/// @brief The pair of proxies @p p and @p q, lower index first.
inline ProxyPair orderedPair(std::uint32_t p, std::uint32_t q) { return p < q ? ProxyPair{p, q} : ProxyPair{q, p}; }

/// @brief The work one broadphase call did, for the broadphase tracker.
struct BroadphaseCounters {
    std::uint64_t pairTests = 0;       ///< Body pairs whose exact boxes were compared (including planes).
    std::uint64_t structureTests = 0;  ///< Other box tests: tree nodes visited (tree only).
    std::uint64_t reinsertions = 0;    ///< Tree leaves moved because a body left its fat box (tree only).
};

}  // namespace stepwise
