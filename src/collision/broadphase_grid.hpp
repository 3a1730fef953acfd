/// @file broadphase_grid.hpp
/// @brief Broadphase with a uniform grid of cells, stored as a hash table rebuilt every step.
#pragma once

#include <vector>

#include "collision/broadphase_proxies.hpp"

namespace stepwise {

/// @brief A uniform grid (Ericson, RTCD §7.1), hashed so that it needs no bounds (Teschner et al. 2003).
///
/// Space is cut into cubes of side `cellSize`, at least as large as any body
/// listed in it. Each body is listed once, in the cell that holds the lowest
/// corner of its box. If boxes A and B overlap, B's lowest corner lies
/// between A.min − size_B and A.max on every axis, so it is in one of the
/// cells from cell(A.min − cellSize) to cell(A.max): 2 or 3 cells per axis,
/// at most 27. A body looks for partners only there, and only among bodies
/// with a higher index (a lower one found the pair already), so each pair is
/// met exactly once.
///
/// **Cell size.** Sized from the bodies each step: the largest box among the
/// bodies no larger than kGridOversizeRatio × the median size. A larger body
/// (a floor slab, a wall, a boulder among pebbles) is *oversize*: it is not
/// listed, and is tested against every other body directly, which is cheaper
/// than making every cell big enough to hold it.
///
/// **Storage.** The grid has no bounds: cell (i, j, k) goes to bucket
/// hash(i, j, k) of a table of B ≥ 2n buckets, B a power of two. Buckets are
/// filled by a counting sort, so all entries sit in one array, bucket after
/// bucket: count the entries of each bucket, take the running sum as each
/// bucket's start, then place the entries. Different cells may share a
/// bucket, so each entry keeps its cell's coordinates. Rebuilt every step
/// in O(n), into arrays that keep their capacity: no allocation once running.
class UniformGrid {
public:
    /// @brief Rebuilds the grid for this step's boxes, then appends every
    /// overlapping pair of proxies (not kinematic–kinematic) to @p pairs.
    void findOverlaps(const ProxySet& proxies, std::vector<ProxyPair>& pairs, BroadphaseCounters& counters);

    /// @brief Side of a cell in the last call, m.
    Real cellSize() const { return cellSize_; }
    /// @brief Number of oversize bodies in the last call (tested against all others).
    std::size_t oversizeCount() const { return oversize_.size(); }

private:
    /// Integer coordinates of a cell.
    struct Cell {
        std::int32_t x = 0, y = 0, z = 0;  ///< Cell index along x, y, z.
        bool operator==(const Cell&) const = default;
    };
    /// One body listed in its cell. Its box is copied here so that the
    /// search reads one place in memory, not two far apart.
    struct Entry {
        Aabb box;                  ///< The proxy's box.
        Cell cell;                 ///< The cell of the body's lowest corner.
        std::uint32_t proxy = 0;   ///< Which proxy.
    };

    Cell cellOf(const Vec3& point) const;
    std::size_t bucketOf(const Cell& cell) const;
    void chooseCellSize(const ProxySet& proxies);

    Real cellSize_ = 1;                        ///< Side of a cell, m.
    Real oversizeLimit_ = 1;                   ///< Bodies larger than this are oversize, m.
    std::vector<Real> sizes_;                  ///< Scratch: longest side of each box (for the median).
    std::vector<Cell> cells_;                  ///< The cell of each proxy's lowest corner.
    std::vector<std::uint32_t> oversize_;      ///< The oversize proxies.
    std::vector<std::uint8_t> isOversize_;     ///< 1 for a proxy not listed in the grid.
    std::vector<std::uint32_t> bucketStart_;   ///< Start of each bucket in entries_; one extra at the end.
    std::vector<Entry> entries_;               ///< Every listed proxy, bucket after bucket.
    int bucketBits_ = 0;                       ///< B = 2^bucketBits_ buckets.
};

/// Bodies up to this many times the median size share the grid, and the
/// cells are as large as the largest of them; larger bodies are oversize.
/// With 2, a grid of spheres whose radii vary by ±50 % lists them all.
inline constexpr Real kGridOversizeRatio = Real(2);
/// Buckets per listed body, at least: most buckets hold one cell, so a
/// lookup rarely walks past entries of other cells.
inline constexpr std::size_t kGridBucketsPerBody = 2;
/// Cell coordinates are clamped to ±this, so a body flung far away cannot
/// overflow a 32-bit index: beyond it all cells merge, which costs time, not correctness.
inline constexpr Real kGridMaxCellIndex = Real(1 << 30);

}  // namespace stepwise
