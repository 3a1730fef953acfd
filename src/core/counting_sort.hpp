/// @file counting_sort.hpp
/// @brief Counting sort of a list by small keys, stable: how colours and waves put contacts in their order.
///
/// When every item of a list has a key in [0, K) and K is small (a contact's
/// colour or wave: a few tens), counting sort orders the list in O(n + K)
/// with no comparison: count the items of each key, turn the counts into
/// where each key's items start (a running sum), then walk the list once and
/// put every item at its key's next place. Walking the list in order keeps the
/// items of one key in their order (the sort is *stable*), which is what lets
/// a colour or a wave keep the order a pass met its contacts in (Cormen et al.,
/// *Introduction to Algorithms*, §8.2).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace stepwise {

/// @brief Puts @p items in @p sorted ordered by @p keys (key k of items[k], each < @p keyCount), stable.
///
/// Fills @p ends with where each key's items *end* in @p sorted: key j runs from ends[j − 1] (or 0)
/// to ends[j]. (The placing walk moves each key's start to its end, so the starts are not kept.)
/// @p ends holds keyCount + 1 entries; the last is the item count. The vectors keep their capacity,
/// so a caller that reuses them allocates nothing once they have grown.
template <class Item>
void countingSort(std::span<const Item> items, std::span<const std::uint32_t> keys, std::uint32_t keyCount,
                  std::vector<std::uint32_t>& ends, std::vector<Item>& sorted) {
    // 1. ends[j + 1] = items of key j, then the running sum: ends[j] = where key j starts
    ends.assign(keyCount + 1, 0);
    for (const std::uint32_t key : keys) ++ends[key + 1];
    for (std::uint32_t key = 0; key < keyCount; ++key) ends[key + 1] += ends[key];
    // 2. Each item at its key's next place, in the list's order; each start moves to its key's end
    sorted.resize(items.size());
    for (std::size_t k = 0; k < items.size(); ++k) sorted[ends[keys[k]]++] = items[k];
}

}  // namespace stepwise
