#pragma once
// The most entries a buffer held at once, from entries and exits decided ahead of simulated time
// and not in cycle order. Changes are summed per cycle in a calendar from the first unsettled
// cycle on (changes are decided a look-ahead or a traversal ahead, so it stays short); settling
// applies them in cycle order, exits before entries within a cycle.

#include <algorithm>
#include <cstdint>
#include <deque>

namespace rtu {

class OccupancyPeak {
 public:
  void enter(uint64_t cycle) { at(cycle).entries += 1; }
  void leave(uint64_t cycle) { at(cycle).exits += 1; }
  // Applies every change before `before`.
  void settle(uint64_t before) {
    while (!calendar_.empty() && base_ < before) {
      current_ -= calendar_.front().exits;
      current_ += calendar_.front().entries;
      peak_ = std::max(peak_, current_);
      calendar_.pop_front();
      ++base_;
    }
    if (calendar_.empty()) base_ = std::max(base_, before);
  }
  // The peak with every change applied.
  uint64_t peak() const {
    OccupancyPeak all = *this;
    all.settle(UINT64_MAX);
    return all.peak_;
  }

 private:
  struct Changes {
    uint32_t entries = 0, exits = 0;
  };
  Changes& at(uint64_t cycle) {
    if (cycle < base_) cycle = base_;  // (not expected: changes come at or after settled cycles)
    if (cycle - base_ >= calendar_.size()) calendar_.resize(cycle - base_ + 1);
    return calendar_[cycle - base_];
  }

  std::deque<Changes> calendar_;  // from base_ on
  uint64_t base_ = 0;
  uint64_t current_ = 0, peak_ = 0;
};

}  // namespace rtu
