#pragma once
// The timed model's scheduler (docs/raypipe.md, "The timed model"): which unit groups act in which
// cycle. The channels book their groups as they are used (timed_queue.h, latency_pipe.h,
// staged_register.h: a FIFO write for the cycle it is shown, a read for the cycle the next head is
// shown, a head or register seen valid for the next cycle, a pipe's accept for the item's exit),
// so a group is called in the cycles one of its channels needs it (and a few more: an extra call
// does what the RTL does in a cycle with nothing to move, nothing), and a cycle with no group
// booked costs one look-up. The calendar is a ring of group masks longer than the longest booking
// ahead.

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace rtu {
namespace raypipe_timed {

class WakeCalendar {
 public:
  explicit WakeCalendar(int64_t horizon) {
    size_t size = 1;
    while (size < static_cast<size_t>(horizon) + 1) size *= 2;
    ring_.resize(size, 0);
  }
  // Books `groups` for `cycle` (after the current one, within the horizon).
  void book(uint32_t groups, int64_t cycle, int64_t now) {
    if (cycle <= now || cycle - now >= static_cast<int64_t>(ring_.size()))
      throw std::logic_error("raypipe timed model: a booking outside the calendar");
    ring_[static_cast<size_t>(cycle) & (ring_.size() - 1)] |= groups;
  }
  // The groups booked for `now`, taken off the calendar.
  uint32_t take(int64_t now) {
    uint32_t& slot = ring_[static_cast<size_t>(now) & (ring_.size() - 1)];
    const uint32_t groups = slot;
    slot = 0;
    return groups;
  }

 private:
  std::vector<uint32_t> ring_;
};

}  // namespace raypipe_timed
}  // namespace rtu
