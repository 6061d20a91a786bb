#pragma once
// The most result buffers full at once, as the result manager counts them, found while the
// recurrence (rtu_recurrence.h) runs rather than from a frame's columns afterwards: a result
// counts from its handover cycle to the cycle after it drained, [K_i, R_i + 1), and the count is
// taken at each handover, after the results that ended by then. The recurrence learns these
// cycles out of order, but it can say below which cycle no start or end is still to come; events
// before that are swept in cycle order (ends before starts in one cycle), so what is held is the
// results in flight, not the frame.

#include <algorithm>
#include <cstdint>
#include <deque>

namespace rtu {

class BuffersFull {
 public:
  // Handovers come nearly in cycle order: each is put in its place from the back.
  void started(uint64_t handover) {
    auto place = starts_.end();
    while (place != starts_.begin() && *(place - 1) > handover) --place;
    starts_.insert(place, handover);
  }
  // Drains come in cycle order.
  void ended(uint64_t drain) { ends_.push_back(drain + 1); }

  // No start or end before `cycle` is still to come: those before it are counted, in cycle
  // order, ends before starts in one cycle.
  void settleBefore(uint64_t cycle) {
    for (;;) {
      const bool end = !ends_.empty() && ends_.front() < cycle &&
                       (starts_.empty() || ends_.front() <= starts_.front());
      if (end) {
        --full_;
        ends_.pop_front();
      } else if (!starts_.empty() && starts_.front() < cycle) {
        most_ = std::max(most_, ++full_);
        starts_.pop_front();
      } else {
        return;
      }
    }
  }

  // Once every result has drained.
  uint64_t most() {
    settleBefore(~uint64_t{0});
    return most_;
  }

 private:
  std::deque<uint64_t> starts_, ends_;  // cycles not yet counted, each in order
  uint64_t full_ = 0, most_ = 0;
};

}  // namespace rtu
