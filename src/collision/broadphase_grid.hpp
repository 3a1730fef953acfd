/// @file broadphase_grid.hpp
/// @brief Broadphase with a uniform grid of cells, stored as a hash table, and the pairs it found kept from step to step.
#pragma once

#include <span>
#include <vector>

#include "collision/broadphase_proxies.hpp"

namespace stepwise {

/// @brief A uniform grid (Ericson, RTCD §7.1): dense where the bodies are packed, hashed where they are spread.
///
/// Space is cut into cubes of side `cellSize`, at least as large as any body
/// listed in it. Each body is listed once, in the cell that holds the lowest
/// corner of its box. If boxes A and B overlap, their lowest corners are less
/// than one cell apart on every axis (B.min < A.max ≤ A.min + cellSize), so
/// they lie in the same cell or in neighbouring ones: a body's partners are
/// in the 3 × 3 × 3 cells around its own.
///
/// **Cell size.** Sized from the bodies each step: the largest box among the
/// bodies no larger than kGridOversizeRatio × the median size. A larger body
/// (a floor slab, a wall, a boulder among pebbles) is *oversize*: it is not
/// listed. In the dense grid it looks for partners in the cells its box
/// covers (grown by one cell below, as for any body), and the oversize bodies
/// are tested among themselves; in the hashed grid, which has no cell ranges
/// to walk, it is tested against every other body. Either way that is cheaper
/// than making every cell big enough to hold it.
///
/// **Storage.** Entries are placed by a counting sort, so all of them sit in
/// one array, cell after cell: count the entries of each cell, take the
/// running sum as each cell's start, then place them. Rebuilt in O(n) in
/// every step where a body moved (below), into arrays that keep their
/// capacity: no allocation once running.
/// Which cell goes where depends on how the bodies are spread:
/// - **Dense** (a pile, a rain, a room full of bodies): when the box around
///   the bodies' lowest corners holds at most kGridDenseCellsPerBody cells per
///   body, every cell of it has a slot, numbered x-major, (x·n_y + y)·n_z + z.
///   Cells along z are then neighbours in the array too, so the three cells
///   z − 1, z, z + 1 of one (x, y) column are *one* run of entries. A body
///   looks at its own cell's entries after itself and at the cells ahead of it
///   in that order, 13 of the 26 neighbours (the other 13 look at it): five
///   runs, no hashing, no check of which cell an entry is in.
/// - **Hashed** (a few bodies kilometres apart, whose box would need more
///   cells than memory): cell (i, j, k) goes to bucket hash(i, j, k) of a
///   table of B ≥ 2n buckets, B a power of two (Teschner et al. 2003).
///   Different cells may share a bucket, so each entry keeps its cell's
///   coordinates and the search checks them, and a body looks in all 27
///   cells, keeping only partners of higher index, so each pair is met once.
///
/// **Kept pairs (temporal coherence).** From one step to the next most bodies
/// move a few millimetres, and their pairs stay the same. So the grid files
/// each proxy under a *fat* box, its box grown by kGridFatMarginFraction of its
/// size on every side, and keeps the pairs whose fat boxes overlap. Next step,
/// a proxy whose box is still inside its fat box has not *moved*. If A and B
/// overlap now, their boxes lie inside their fat boxes, which then overlap
/// too: every overlapping pair is among the kept ones, unless A or B moved.
/// So a step
/// 1. refits the fat box of each moved proxy, and finds its pairs again:
///    the cells are filled anew (the counting sort above, on the fat boxes),
///    and only the moved proxies look for partners, in all 27 cells around
///    their own; the kept pairs of a moved proxy are dropped and the new ones
///    merged in (both lists sorted by proxy, so one pass);
/// 2. returns the kept pairs whose *exact* boxes overlap, exactly the pairs
///    the search on the exact boxes would return.
///
/// A step in which nothing moved skips the cells altogether; when many
/// proxies moved (more than one in kGridRefindAllShare), or where the fat
/// boxes need the hashed grid or leave some body oversize, every pair is
/// found again on the fat boxes, as on the first step. Box2D keeps its pairs
/// the same way, with fat boxes in its dynamic tree (Catto, "Dynamic BVH",
/// GDC 2019); Bullet keeps a pair cache (btHashedOverlappingPairCache).
class UniformGrid {
public:
    /// @brief Appends every overlapping pair of proxies (not kinematic–kinematic) to
    /// @p pairs, sorted by lower proxy, then higher: the kept pairs, brought up to
    /// date for the proxies that moved out of their fat boxes.
    void findOverlaps(const ProxySet& proxies, std::vector<ProxyPair>& pairs, BroadphaseCounters& counters);
    /// @brief Proxies that left their fat box in the last call (all of them when every pair was found again).
    std::size_t movedCount() const { return movedCount_; }
    /// @brief Whether the last call found every pair again (the first call, or too many moved).
    bool refoundAll() const { return refoundAll_; }

    /// @brief Appends to @p hits every proxy whose box in @p boxes overlaps @p box, in the grid's order.
    ///
    /// A listed proxy's fat box F (which holds its box) can overlap @p box only
    /// if its lowest corner lies between box.min − cellSize and box.max on every
    /// axis (F is at most one cell wide), so only the cells of that range are
    /// read: in the dense grid the (x, y) columns of the range, one run each; in
    /// the hashed grid each cell's bucket, or every entry when the range has
    /// more cells than there are entries (a box larger than the scene). The
    /// oversize proxies are tested one by one. @p boxes must be the boxes of
    /// the last findOverlaps().
    void query(const Aabb& box, std::span<const Aabb> boxes, std::vector<std::uint32_t>& hits,
               BroadphaseCounters& counters) const;

    /// @brief Side of a cell in the last call, m.
    Real cellSize() const { return cellSize_; }
    /// @brief Number of oversize bodies in the last call (tested against all others).
    std::size_t oversizeCount() const { return oversize_.size(); }
    /// @brief True when the last call stored the cells densely, false when it hashed them.
    bool dense() const { return dense_; }

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
    bool fitDenseGrid(const ProxySet& proxies);
    std::uint32_t slotOf(std::int32_t x, std::int32_t y, std::int32_t z) const;
    bool cellRange(Real low, Real high, int axis, std::int32_t& first, std::int32_t& last) const;
    /// Calls `visit(entry)` for each entry of the dense grid in the cells from the one of @p low to
    /// the one of @p high (clipped to the grid), column by column; false when they miss the grid.
    template <class Visit>
    bool visitDenseCells(const Vec3& low, const Vec3& high, Visit&& visit) const;
    /// Calls `visit(entry)` for each entry of the hashed grid in the cells from @p low to @p high,
    /// skipping the entries of other cells that share a bucket.
    template <class Visit>
    void visitHashedCells(const Cell& low, const Cell& high, Visit&& visit) const;
    void findAllFatPairs(const ProxySet& fat, BroadphaseCounters& counters);
    void findFatPairsOfMoved(const ProxySet& fat, BroadphaseCounters& counters);
    void fileProxies(const ProxySet& proxies);
    void fillDenseCells(const ProxySet& proxies);
    void findOverlapsDense(const ProxySet& proxies, std::vector<ProxyPair>& pairs, BroadphaseCounters& counters);
    void findOversizeOverlapsDense(const ProxySet& proxies, std::vector<ProxyPair>& pairs,
                                   BroadphaseCounters& counters);
    void findOverlapsHashed(const ProxySet& proxies, std::vector<ProxyPair>& pairs, BroadphaseCounters& counters);

    Real cellSize_ = 1;                        ///< Side of a cell, m.
    Real oversizeLimit_ = 1;                   ///< Bodies larger than this are oversize, m.
    std::vector<Real> sizes_;                  ///< Scratch: longest side of each box (for the median).
    std::vector<Cell> cells_;                  ///< The cell of each proxy's lowest corner.
    std::vector<std::uint32_t> oversize_;      ///< The oversize proxies.
    std::vector<std::uint8_t> isOversize_;     ///< 1 for a proxy not listed in the grid.
    std::vector<std::uint32_t> bucketStart_;   ///< Start of each bucket in entries_; one extra at the end.
    std::vector<Entry> entries_;               ///< Every listed proxy, bucket after bucket.
    int bucketBits_ = 0;                       ///< B = 2^bucketBits_ buckets (hashed).
    bool dense_ = false;                       ///< Whether the last call stored the cells densely.
    Vec3 origin_{0, 0, 0};                     ///< Lowest corner of the dense grid's cell (0, 0, 0), m.
    std::int32_t columns_[3] = {1, 1, 1};      ///< Dense grid: number of cells along x, y, z.
    // Kept pairs
    std::vector<Aabb> fat_;                    ///< Each proxy's fat box: where it was filed.
    std::vector<std::uint8_t> moved_;          ///< 1 for a proxy that left its fat box this call.
    std::vector<ProxyPair> kept_;              ///< Pairs whose fat boxes overlap, sorted by a, then b.
    std::vector<ProxyPair> found_;             ///< Scratch: pairs found this call.
    std::vector<ProxyPair> merged_;            ///< Scratch: kept_ without the moved proxies' pairs, then with the new ones.
    std::vector<std::uint32_t> pairStart_;     ///< Scratch: counting sort of found_ by a.
    std::uint32_t keptDynamicCount_ = 0;       ///< ProxySet::dynamicCount when kept_ was made.
    bool keeping_ = false;                     ///< Whether kept_ and fat_ hold the last call's pairs.
    std::size_t movedCount_ = 0;               ///< Proxies that moved in the last call.
    bool refoundAll_ = true;                   ///< Whether the last call found every pair again.
};

/// Bodies up to this many times the median size share the grid, and the
/// cells are as large as the largest of them; larger bodies are oversize.
/// With 2, a grid of spheres whose radii vary by ±50 % lists them all.
inline constexpr Real kGridOversizeRatio = Real(2);
/// The dense grid is used when the box around the listed bodies needs at
/// most this many cells per body; a sparser scene is hashed. In a pile there
/// is about one cell per body, so 8 leaves room for a scene twice as wide on
/// every axis, while clearing the cell starts (4 bytes each) stays cheaper
/// than the bodies' own entries.
inline constexpr Real kGridDenseCellsPerBody = Real(8);
/// Buckets per listed body, at least: most buckets hold one cell, so a
/// lookup rarely walks past entries of other cells.
inline constexpr std::size_t kGridBucketsPerBody = 2;
/// A proxy's fat box is its box grown by this fraction of its longest side on every
/// side. At 0.1 a ball of radius 0.5 m may move 10 cm before its pairs are looked
/// for again: in the settled 1k sphere rain, in 6 of its last 300 steps.
inline constexpr Real kGridFatMarginFraction = Real(0.1);
/// When more than one proxy in this many moved, every pair is found again (a full
/// search costs about as much as that many 27-cell searches).
inline constexpr std::uint32_t kGridRefindAllShare = 4;
/// Cell coordinates are clamped to ±this, so a body flung far away cannot
/// overflow a 32-bit index: beyond it all cells merge, which costs time, not correctness.
inline constexpr Real kGridMaxCellIndex = Real(1 << 30);

}  // namespace stepwise
