#pragma once
// The ray pipe's FIFOs for the timed model (docs/raypipe.md, "The timed model"), lazy in time:
// every item carries the cycle it was written, so a FIFO nobody touches costs nothing and needs no
// tick. Timing rule: an item written in cycle t is shown at the head from t + showDelay (1 for
// R1's register `fifo`, 2 for the show-ahead BRAM scfifo, whose next item after a read in r is
// shown in r + 1 when written by r - 1: the same rule); `full` and the free slots are the counts
// at the cycle's start (a read frees its slot from the next cycle, a write counts from the next).
// A unit reads a FIFO at most once a cycle and writes it at most once. On the wake calendar it
// books its groups for the cycle a write is shown, the cycle after a read its next head is shown,
// and the cycle after one in which its head was seen shown (a head not taken is seen again).

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/raypipe/pipe_trace.h"
#include "sim/raypipe/wake_calendar.h"

namespace rtu {
namespace raypipe_timed {

// What a traced FIFO shows at its head (pipe_trace.h): the shader's free ray ids themselves.
inline uint64_t traceHead(uint32_t id, bool) { return id; }

template <class T>
class TimedQueue {
 public:
  TimedQueue(std::string name, int depth, int showDelay)
      : name_(std::move(name)), depth_(depth), delay_(showDelay) {
    size_t capacity = 1;
    while (capacity < static_cast<size_t>(depth) + 1) capacity *= 2;
    slots_.resize(capacity);
    mask_ = capacity - 1;
  }
  const std::string& name() const { return name_; }
  int depth() const { return depth_; }
  bool any() const { return count_ > 0; }  // holds an item, shown or not
  void bookOn(WakeCalendar& calendar, uint32_t groups) {
    calendar_ = &calendar;
    groups_ = groups;
  }
  // Reports every write and read to `trace` from now on (none: untraced, the default).
  void traceTo(FifoTrace* trace) { trace_ = trace; }
  // The head is shown in `now` and not yet read in it.
  bool shown(int64_t now) {
    const bool shown = count_ > 0 && lastPop_ != now && headShownFrom() <= now;
    if (shown) book(now + 1, now);
    return shown;
  }
  const T& front() const { return slots_[head_].item; }
  const T& back() const { return slots_[(head_ + static_cast<size_t>(count_) - 1) & mask_].item; }
  int countAtStart(int64_t now) const {
    return count_ - (lastPush_ == now ? 1 : 0) + (lastPop_ == now ? 1 : 0);
  }
  bool full(int64_t now) const { return countAtStart(now) >= depth_; }
  int numLeft(int64_t now) const { return depth_ - countAtStart(now); }
  T pop(int64_t now) {
    settle(now);
    T item = slots_[head_].item;
    head_ = (head_ + 1) & mask_;
    --count_;
    lastPop_ = now;
    if (count_ > 0) book(std::max(now + 1, headShownFrom()), now);
    if (trace_) traced(now);
    return item;
  }
  void push(int64_t now, const T& item) { write(now, item, now); }
  // An item written before the run's first cycle (the shader's ray ids).
  void preload(const T& item, int64_t written) { write(written, item, written); }
  int peak() const { return std::max(peak_, count_); }
  // The first cycle the head is shown in (with an item).
  int64_t headShownFrom() const { return slots_[head_].written + delay_; }

 private:
  void settle(int64_t now) {
    if (lastTouch_ < now) peak_ = std::max(peak_, count_);
    lastTouch_ = now;
  }
  void write(int64_t now, const T& item, int64_t written) {
    if (full(now) || lastPush_ == now)
      throw std::logic_error("raypipe timed model: write to the full FIFO " + name_);
    settle(now);
    Slot& slot = slots_[(head_ + static_cast<size_t>(count_)) & mask_];
    slot.item = item;
    slot.written = written;
    ++count_;
    lastPush_ = now;
    if (written == now) book(now + delay_, now);
    if (trace_) traced(now);
  }
  // The count and head from the cycle after a write or read in `now`; out of the untraced path
  // (cold, not inlined: a test and a branch are all an untraced write or read pays).
  [[gnu::noinline, gnu::cold]] void traced(int64_t now) {
    trace_->changed(now + 1, count_, count_ > 0 ? traceHead(front(), trace_->pixels()) : 0);
  }
  void book(int64_t cycle, int64_t now) {
    if (calendar_) calendar_->book(groups_, cycle, now);
  }
  struct Slot {
    T item{};
    int64_t written = 0;
  };
  std::string name_;
  int depth_, delay_;
  std::vector<Slot> slots_;
  size_t head_ = 0, mask_ = 0;
  int count_ = 0;
  int64_t lastPush_ = INT64_MIN, lastPop_ = INT64_MIN, lastTouch_ = INT64_MIN;
  int peak_ = 0;
  WakeCalendar* calendar_ = nullptr;
  uint32_t groups_ = 0;
  FifoTrace* trace_ = nullptr;
};

}  // namespace raypipe_timed
}  // namespace rtu
