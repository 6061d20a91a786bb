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
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace rtu {

class BuffersFull {
 public:
  void started(uint64_t handover) { events_.emplace(handover, kStart); }
  void ended(uint64_t drain) { events_.emplace(drain + 1, kEnd); }

  // No start or end before `cycle` is still to come: those before it are counted.
  void settleBefore(uint64_t cycle) {
    while (!events_.empty() && events_.top().first < cycle) {
      if (events_.top().second == kEnd) {
        --full_;
      } else {
        most_ = std::max(most_, ++full_);
      }
      events_.pop();
    }
  }

  // Once every result has drained.
  uint64_t most() {
    settleBefore(~uint64_t{0});
    return most_;
  }

 private:
  static constexpr int kEnd = 0, kStart = 1;  // in one cycle, ends come first
  using Event = std::pair<uint64_t, int>;     // (cycle, kind)

  std::priority_queue<Event, std::vector<Event>, std::greater<>> events_;
  uint64_t full_ = 0, most_ = 0;
};

}  // namespace rtu
