#pragma once
// Slots of a resource that serves one request per slot (the loosely-timed model's dispatches,
// one a cycle, and output-link records), taken out of order: a ring of bits from the first slot
// not yet forgotten, grown (a power of two long) when a slot lies further ahead. Two bit
// operations a request, where an ordered map of booked runs (resource_booking.h) costs a tree
// node; slots are the same length, so there are no gaps to fit.

#include <algorithm>
#include <cstdint>
#include <vector>

namespace rtu {

class SlotCalendar {
 public:
  // The first free slot at or after `from`, taken.
  uint64_t takeFirstFree(uint64_t from) {
    uint64_t slot = std::max(from, base_);
    while (taken(slot)) ++slot;
    take(slot);
    return slot;
  }
  // Takes `slot` if it is free (a slot before the forgotten ones counts as taken).
  bool takeIfFree(uint64_t slot) {
    if (slot < base_ || taken(slot)) return false;
    take(slot);
    return true;
  }
  // No later request asks for a slot before `slot`.
  void forgetBefore(uint64_t slot) {
    for (; base_ < slot && base_ < end_; ++base_) clear(base_);
    base_ = std::max(base_, slot);
    end_ = std::max(end_, base_);
  }

 private:
  bool taken(uint64_t slot) const {
    if (slot >= end_) return false;
    const uint64_t bit = slot & (bits_.size() * 64 - 1);
    return (bits_[bit / 64] >> (bit % 64)) & 1;
  }
  void take(uint64_t slot) {
    if (slot - base_ >= bits_.size() * 64) grow(slot - base_ + 1);
    const uint64_t bit = slot & (bits_.size() * 64 - 1);
    bits_[bit / 64] |= uint64_t{1} << (bit % 64);
    end_ = std::max(end_, slot + 1);
  }
  void clear(uint64_t slot) {
    const uint64_t bit = slot & (bits_.size() * 64 - 1);
    bits_[bit / 64] &= ~(uint64_t{1} << (bit % 64));
  }
  void grow(uint64_t needed) {
    size_t words = bits_.size();
    while (words * 64 < needed) words *= 2;
    std::vector<uint64_t> larger(words, 0);
    const uint64_t size = words * 64;
    for (uint64_t slot = base_; slot < end_; ++slot)
      if (taken(slot)) larger[(slot & (size - 1)) / 64] |= uint64_t{1} << (slot % 64);
    bits_.swap(larger);
  }

  std::vector<uint64_t> bits_ = std::vector<uint64_t>(16, 0);  // ring: slot s at s mod size
  uint64_t base_ = 0;  // slots before it are forgotten
  uint64_t end_ = 0;   // no slot at or after it is taken
};

}  // namespace rtu
