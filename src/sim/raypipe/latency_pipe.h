#pragma once
// R1's `pipe_valid_stall` for the timed model: a fixed-latency pipe that never stalls inside, lazy
// in time (each item carries the cycle it was accepted; nothing happens between its entry and its
// exit, for which accept books the groups that take it out on the wake calendar). Timing rule:
// accepted in t, it leaves in t + depth into the FIFO behind it; us_stall = ds_stall & (one_cnt >=
// the FIFO's free slots), one_cnt the items accepted before t and not left before t (the one
// leaving in t included).

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "sim/raypipe/wake_calendar.h"

namespace rtu {
namespace raypipe_timed {

template <class T>
class LatencyPipe {
 public:
  explicit LatencyPipe(int depth) : depth_(depth) {
    size_t capacity = 1;
    while (capacity < static_cast<size_t>(depth) + 1) capacity *= 2;
    slots_.resize(capacity);
    mask_ = capacity - 1;
  }
  bool any() const { return count_ > 0; }
  int oneCount(int64_t now) const {
    return count_ - (lastAccept_ == now ? 1 : 0) + (lastTake_ == now ? 1 : 0);
  }
  bool usStall(int64_t now, bool dsStall, int numLeft) const {
    return dsStall && oneCount(now) >= numLeft;
  }
  bool exiting(int64_t now) const {
    return count_ > 0 && lastTake_ != now && slots_[head_].accepted + depth_ == now;
  }
  const T& front() const { return slots_[head_].item; }  // the item exiting(now) names
  T take(int64_t now) {
    T item = slots_[head_].item;
    head_ = (head_ + 1) & mask_;
    --count_;
    lastTake_ = now;
    return item;
  }
  // Each item accepted books `groups` for the cycle it leaves.
  void bookOn(WakeCalendar& calendar, uint32_t groups) {
    calendar_ = &calendar;
    groups_ = groups;
  }
  void accept(int64_t now, const T& item) {
    if (lastAccept_ == now) throw std::logic_error("raypipe timed model: two items into one pipe");
    Slot& slot = slots_[(head_ + static_cast<size_t>(count_)) & mask_];
    slot.item = item;
    slot.accepted = now;
    ++count_;
    lastAccept_ = now;
    if (calendar_) calendar_->book(groups_, now + depth_, now);
  }

 private:
  struct Slot {
    T item{};
    int64_t accepted = 0;
  };
  int depth_;
  std::vector<Slot> slots_;
  size_t head_ = 0, mask_ = 0;
  int count_ = 0;
  int64_t lastAccept_ = INT64_MIN, lastTake_ = INT64_MIN;
  WakeCalendar* calendar_ = nullptr;
  uint32_t groups_ = 0;
};

}  // namespace raypipe_timed
}  // namespace rtu
