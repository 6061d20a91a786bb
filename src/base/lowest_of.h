#pragma once
// The lowest of a fixed number of values that change one at a time: a tournament tree, so a
// change costs log2(count) comparisons and the lowest is there at once, whether 1 or 1024 cores
// publish their bounds (memory_system.h).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rtu {

class LowestOf {
 public:
  LowestOf(size_t count, uint64_t initial) : leaves_(firstPowerOfTwo(count)) {
    values_.assign(2 * leaves_, UINT64_MAX);  // the leaves past `count` never win
    for (size_t i = 0; i < count; ++i) set(i, initial);
  }

  void set(size_t index, uint64_t value) {
    size_t node = leaves_ + index;
    values_[node] = value;
    for (node /= 2; node > 0; node /= 2) {
      const uint64_t lowest = std::min(values_[2 * node], values_[2 * node + 1]);
      if (values_[node] == lowest) return;  // nor do the nodes above change
      values_[node] = lowest;
    }
  }
  uint64_t lowest() const { return values_[1]; }
  uint64_t value(size_t index) const { return values_[leaves_ + index]; }

 private:
  static size_t firstPowerOfTwo(size_t count) {
    size_t power = 1;
    while (power < count) power *= 2;
    return power;
  }

  size_t leaves_;
  std::vector<uint64_t> values_;  // node n's children are 2n and 2n + 1; the root is 1
};

}  // namespace rtu
