#pragma once
// The most entries a buffer held at once, from entries and exits decided ahead of simulated time
// and not in cycle order. Changes are summed per cycle in a calendar from the first unsettled
// cycle on (changes are decided a look-ahead or a traversal ahead, so it stays short); settling
// applies them in cycle order, exits before entries within a cycle. The calendar is a ring
// indexed by cycle (a power of two long, at least 64, grown when a change lies further ahead), as
// it is touched twice per ray; a bit per slot marks those with changes, so that settling costs
// the changes and a word per 64 cycles, not a visit per cycle (a run settles every cycle it
// simulates, and most change nothing).

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
    applyChanged(base_, end);
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
    const uint64_t index = cycle & (calendar_.size() - 1);
    changed_[index / 64] |= uint64_t{1} << (index % 64);
    return calendar_[index];
  }
  // Applies the changes of cycles [from, to) in cycle order, a word of marks at a time (the
  // ring's length is a multiple of 64, so a word's slots are consecutive cycles).
  void applyChanged(uint64_t from, uint64_t to) {
    while (from < to) {
      const uint64_t index = from & (calendar_.size() - 1);
      const unsigned offset = index % 64;
      const uint64_t span = std::min<uint64_t>(64 - offset, to - from);
      const uint64_t mask = (span == 64 ? ~uint64_t{0} : (uint64_t{1} << span) - 1) << offset;
      uint64_t& word = changed_[index / 64];
      for (uint64_t marks = word & mask; marks != 0; marks &= marks - 1)
        apply(calendar_[index - offset + static_cast<uint64_t>(__builtin_ctzll(marks))]);
      word &= ~mask;
      from += span;
    }
  }
  void apply(Changes& changes) {
    current_ -= changes.exits;
    current_ += changes.entries;
    peak_ = std::max(peak_, current_);
    changes = Changes{};
  }
  void grow(uint64_t needed) {
    size_t size = std::max<size_t>(calendar_.size(), 64);
    while (size < needed) size *= 2;
    std::vector<Changes> larger(size);
    std::vector<uint64_t> changed(size / 64, 0);
    for (uint64_t cycle = base_; cycle < base_ + length_; ++cycle) {
      const uint64_t index = cycle & (calendar_.size() - 1);
      if (!(changed_[index / 64] >> (index % 64) & 1)) continue;
      const uint64_t moved = cycle & (size - 1);
      larger[moved] = calendar_[index];
      changed[moved / 64] |= uint64_t{1} << (moved % 64);
    }
    calendar_.swap(larger);
    changed_.swap(changed);
  }

  std::vector<Changes> calendar_;  // ring: cycle c at c mod size, cycles [base_, base_ + length_)
  std::vector<uint64_t> changed_;  // a bit per slot of calendar_: it holds changes
  uint64_t length_ = 0;
  uint64_t base_ = 0;
  uint64_t current_ = 0, peak_ = 0;
};

}  // namespace rtu
