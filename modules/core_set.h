#pragma once
// A set of core indices 0 .. n-1 with a cyclic search: the scheduler's ready cores, the result
// manager's full buffers. A bit per core, so a search costs n / 64 word tests instead of n
// channel queries, which kept 1024 cores five times slower than 16 (docs/performance.md).

#include <cstdint>
#include <vector>

namespace rtu {

class CoreSet {
 public:
  static constexpr int kNone = -1;

  explicit CoreSet(int size = 0) : size_(size), words_((static_cast<size_t>(size) + 63) / 64, 0) {}

  void assign(int core, bool member) {
    uint64_t& word = words_[static_cast<size_t>(core) / 64];
    const uint64_t bit = uint64_t{1} << (core % 64);
    if (((word & bit) != 0) == member) return;
    word ^= bit;
    count_ += member ? 1 : -1;
  }
  bool contains(int core) const {
    return (words_[static_cast<size_t>(core) / 64] >> (core % 64)) & 1;
  }
  bool empty() const { return count_ == 0; }
  int count() const { return count_; }

  // The first member at or after `start`, wrapping around past size - 1; kNone when empty.
  int firstFrom(int start) const {
    if (count_ == 0) return kNone;
    const int found = firstInRange(start, size_);
    return found != kNone ? found : firstInRange(0, start);
  }

 private:
  // The first member in [from, to), or kNone.
  int firstInRange(int from, int to) const {
    for (int core = from; core < to;) {
      const uint64_t word = words_[static_cast<size_t>(core) / 64] >> (core % 64);
      if (word != 0) {
        const int found = core + __builtin_ctzll(word);
        return found < to ? found : kNone;
      }
      core = (core / 64 + 1) * 64;
    }
    return kNone;
  }

  int size_;
  int count_ = 0;
  std::vector<uint64_t> words_;
};

}  // namespace rtu
