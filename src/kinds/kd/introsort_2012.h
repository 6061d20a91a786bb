#pragma once
// The unstable sort R1's builder ran under (g++ 4.7's std::sort, 2012), so that edges equal under
// the comparator come out in the same order and leaves list their triangles as R1's files do
// (reading K6). Today's std::sort picks its pivot from (first + 1, middle, last - 1); the 2012
// library took the median of (first, middle, last - 1). Otherwise the same introsort: quicksort
// partitions (unguarded, around the median moved to the front) while a range holds more than 16
// elements and the depth budget 2 floor(log2 n) lasts, heapsort past the budget, then one
// insertion sort over the whole range.

#include <algorithm>
#include <cstddef>
#include <utility>

namespace rtu {
namespace introsort_2012 {

constexpr std::ptrdiff_t kThreshold = 16;

template <class It, class Less>
void medianToFirst(It a, It b, It c, Less less) {
  if (less(*a, *b)) {
    if (less(*b, *c))
      std::iter_swap(a, b);
    else if (less(*a, *c))
      std::iter_swap(a, c);
  } else if (less(*a, *c)) {
    return;
  } else if (less(*b, *c)) {
    std::iter_swap(a, c);
  } else {
    std::iter_swap(a, b);
  }
}

template <class It, class Less>
It partitionAroundFirst(It first, It last, Less less) {
  const It pivot = first;  // stays in place while [first + 1, last) is partitioned
  ++first;
  while (true) {
    while (less(*first, *pivot)) ++first;
    --last;
    while (less(*pivot, *last)) --last;
    if (!(first < last)) return first;
    std::iter_swap(first, last);
    ++first;
  }
}

template <class It, class Less>
void loop(It first, It last, int depth, Less less) {
  while (last - first > kThreshold) {
    if (depth == 0) {
      std::partial_sort(first, last, last, less);
      return;
    }
    --depth;
    medianToFirst(first, first + (last - first) / 2, last - 1, less);
    const It cut = partitionAroundFirst(first, last, less);
    loop(cut, last, depth, less);
    last = cut;
  }
}

// Insertion sort: each element moves left past the greater ones before it (stable).
template <class It, class Less>
void insertion(It first, It last, Less less) {
  for (It i = first; i != last; ++i) {
    auto value = std::move(*i);
    It hole = i;
    for (; hole != first && less(value, *(hole - 1)); --hole) *hole = std::move(*(hole - 1));
    *hole = std::move(value);
  }
}

}  // namespace introsort_2012

template <class It, class Less>
void sort2012(It first, It last, Less less) {
  if (last - first < 2) return;
  int lg = 0;
  for (auto n = last - first; n > 1; n >>= 1) ++lg;
  introsort_2012::loop(first, last, 2 * lg, less);
  introsort_2012::insertion(first, last, less);
}

}  // namespace rtu
