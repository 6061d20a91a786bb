#pragma once
// A unit's registered output for the timed model (TRAV's requests to the shortstack, tarb and
// larb, its leaf_max to the list unit, the list unit's miss to the shortstack), lazy in time:
// timing rule: a value set in cycle t is read from t + 1; in t every reader sees the old one. A
// register nobody sets keeps its value and costs nothing. It books its readers on the wake calendar
// for the cycle after one it is set valid in or read valid in.

#include <cstdint>

#include "sim/raypipe/wake_calendar.h"

namespace rtu {
namespace raypipe_timed {

template <class T>
class StagedRegister {
 public:
  void bookOn(WakeCalendar& calendar, uint32_t groups) {
    calendar_ = &calendar;
    groups_ = groups;
  }
  bool valid(int64_t now) {
    commit(now);
    if (valid_ && calendar_) calendar_->book(groups_, now + 1, now);
    return valid_;
  }
  const T& value(int64_t now) {
    commit(now);
    return value_;
  }
  // The value from the next cycle on (only `valid` when invalid).
  void set(int64_t now, bool valid, const T* value) {
    commit(now);
    pending_ = true;
    nextValid_ = valid;
    if (value) next_ = *value;
    setAt_ = now;
    if (valid && calendar_) calendar_->book(groups_, now + 1, now);
  }

 private:
  void commit(int64_t now) {
    if (!pending_ || setAt_ >= now) return;
    valid_ = nextValid_;
    value_ = next_;
    pending_ = false;
  }
  bool valid_ = false, nextValid_ = false, pending_ = false;
  T value_{}, next_{};
  int64_t setAt_ = 0;
  WakeCalendar* calendar_ = nullptr;
  uint32_t groups_ = 0;
};

}  // namespace raypipe_timed
}  // namespace rtu
