#pragma once
// The most entries a buffer held at once, from entries and exits decided ahead of simulated time
// and not in cycle order. Changes are summed per cycle in a calendar from the first unsettled
// cycle on (changes are decided a look-ahead or a traversal ahead, so it stays short); settling
// applies them in cycle order, exits before entries within a cycle. The calendar is a ring
// indexed by cycle (a power of two long, grown when a change lies further ahead), as it is
// touched twice per ray.

#include <algorithm>
#include <cstdint>
#include <vector>

namespace rtu {

class OccupancyPeak {
 public:
  void enter(uint64_t cycle) { at(cycle).entries += 1; }
  void leave(uint64_t cycle) { at(cycle).exits += 1; }
  // Applies every change before `before`.
  void settle(uint64_t before) {
    const uint64_t settled = before > base_ ? std::min(length_, before - base_) : 0;
    const uint64_t end = base_ + settled;
    for (uint64_t cycle = base_; cycle < end; ++cycle) apply(slot(cycle));
    base_ = end;
    length_ -= settled;
    if (length_ == 0) base_ = std::max(base_, before);
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
    const uint64_t offset = cycle - base_;
    if (offset >= calendar_.size()) grow(offset + 1);
    length_ = std::max(length_, offset + 1);
    return slot(cycle);
  }
  Changes& slot(uint64_t cycle) { return calendar_[cycle & (calendar_.size() - 1)]; }
  // Most cycles change nothing (a run settles every cycle it simulates): those only pass.
  void apply(Changes& changes) {
    if (changes.entries == 0 && changes.exits == 0) return;
    current_ -= changes.exits;
    current_ += changes.entries;
    peak_ = std::max(peak_, current_);
    changes = Changes{};
  }
  void grow(uint64_t needed) {
    size_t size = std::max<size_t>(calendar_.size(), 64);
    while (size < needed) size *= 2;
    std::vector<Changes> larger(size);
    for (uint64_t cycle = base_; cycle < base_ + length_; ++cycle)
      larger[cycle & (size - 1)] = slot(cycle);
    calendar_.swap(larger);
  }

  std::vector<Changes> calendar_;  // ring: cycle c at c mod size, cycles [base_, base_ + length_)
  uint64_t length_ = 0;
  uint64_t base_ = 0;
  uint64_t current_ = 0, peak_ = 0;
};

}  // namespace rtu
