#include "resource_booking.h"

#include <algorithm>
#include <iterator>

namespace rtu {

uint64_t ResourceBooking::book(uint64_t from, uint64_t cycles) {
  const uint64_t start = firstFree(from, cycles);
  if (order_ == RequestOrder::Cycle)
    free_ = start + cycles;
  else
    insertRun(start, start + cycles);
  return start;
}

uint64_t ResourceBooking::firstFree(uint64_t from, uint64_t cycles) const {
  if (order_ == RequestOrder::Cycle) return std::max(from, free_);
  uint64_t start = from;
  // The run that starts last at or before `from` may still cover it.
  auto next = busy_.upper_bound(from);
  if (next != busy_.begin()) start = std::max(start, std::prev(next)->second);
  for (; next != busy_.end() && next->first < start + cycles; ++next)
    start = std::max(start, next->second);
  return start;
}

// Books the free run [start, end), merged with the runs it touches to keep the map small.
void ResourceBooking::insertRun(uint64_t start, uint64_t end) {
  auto next = busy_.lower_bound(start);
  if (next != busy_.end() && next->first == end) {
    end = next->second;
    next = busy_.erase(next);
  }
  if (next != busy_.begin()) {
    const auto before = std::prev(next);
    if (before->second == start) {
      before->second = end;
      return;
    }
  }
  busy_.emplace_hint(next, start, end);
}

void ResourceBooking::forgetBefore(uint64_t cycle) {
  if (order_ == RequestOrder::Cycle) return;
  while (!busy_.empty() && busy_.begin()->second <= cycle) busy_.erase(busy_.begin());
}

}  // namespace rtu
