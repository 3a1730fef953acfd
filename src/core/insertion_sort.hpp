/// @file insertion_sort.hpp
/// @brief Insertion sort, for arrays that are already nearly in order.
///
/// A broadphase sorts its bodies along an axis every step, and from one step
/// to the next the bodies rarely pass each other: last step's order is almost
/// this step's. Insertion sort costs O(n + k), k the number of pairs out of
/// order, so on such input it is linear, where std::sort is O(n log n)
/// whatever the input (Ericson, *Real-Time Collision Detection*, §7.5.1;
/// Baraff's thesis, 1992, on sort-and-sweep coherence). It is stable.
#pragma once

#include <cstddef>
#include <span>

namespace stepwise {

/// @brief Sorts @p items by @p less in place; O(n + out-of-order pairs), stable.
template <class T, class Less>
void insertionSort(std::span<T> items, Less less) {
    for (std::size_t i = 1; i < items.size(); ++i) {
        const T moving = items[i];
        std::size_t j = i;
        while (j > 0 && less(moving, items[j - 1])) {  // shift the larger ones right
            items[j] = items[j - 1];
            --j;
        }
        items[j] = moving;
    }
}

}  // namespace stepwise
