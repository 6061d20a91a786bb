#include "sim/memory/resource_booking.h"

#include <algorithm>

namespace rtu {

uint64_t ResourceBooking::bookAnyOrder(uint64_t from, uint64_t cycles) {
  const uint64_t start = firstFree(from, cycles);
  if (start + cycles - base_ > ringCycles()) grow(start + cycles - base_);
  for (uint64_t cycle = start; cycle < start + cycles; ++cycle) mark(cycle);
  end_ = std::max(end_, start + cycles);
  return start;
}

uint64_t ResourceBooking::bookSpreadAnyOrder(uint64_t from, uint64_t cycles) {
  uint64_t cycle = std::max(from, base_), left = cycles;
  for (; left > 0 && cycle < end_; ++cycle) {
    if (booked(cycle)) continue;
    mark(cycle);
    --left;
  }
  // Beyond the last booking every cycle is free.
  if (left > 0) {
    if (cycle + left - base_ > ringCycles()) grow(cycle + left - base_);
    for (const uint64_t stop = cycle + left; cycle < stop; ++cycle) mark(cycle);
  }
  end_ = std::max(end_, cycle);
  return cycle;
}

uint64_t ResourceBooking::firstFree(uint64_t from, uint64_t cycles) const {
  if (order_ == RequestOrder::Cycle) return std::max(from, free_);
  uint64_t start = std::max(from, base_);
  for (uint64_t cycle = start; cycle < start + cycles && cycle < end_; ++cycle)
    if (booked(cycle)) start = cycle + 1;  // the run must begin after it
  return start;
}

void ResourceBooking::forgetBefore(uint64_t cycle) {
  if (order_ == RequestOrder::Cycle) return;
  const uint64_t stop = std::min(cycle, end_);
  while (base_ < stop) {  // whole words at once where they are all behind
    if (base_ % 64 == 0 && stop - base_ >= 64) {
      word(base_) = 0;
      base_ += 64;
    } else {
      word(base_) &= ~(uint64_t{1} << (base_ % 64));
      ++base_;
    }
  }
  base_ = std::max(base_, cycle);
  end_ = std::max(end_, base_);
}

bool ResourceBooking::booked(uint64_t cycle) const {
  return (bits_[(cycle & (ringCycles() - 1)) / 64] >> (cycle % 64)) & 1;
}

// Room for cycles [base_, base_ + span), the booked ones kept.
void ResourceBooking::grow(uint64_t span) {
  ResourceBooking larger(order_);
  size_t words = bits_.size();
  while (words * 64 < span) words *= 2;
  larger.bits_.assign(words, 0);
  larger.base_ = base_;
  larger.end_ = end_;
  for (uint64_t cycle = base_; cycle < end_; ++cycle)
    if (booked(cycle)) larger.word(cycle) |= uint64_t{1} << (cycle % 64);
  *this = std::move(larger);
}

}  // namespace rtu
