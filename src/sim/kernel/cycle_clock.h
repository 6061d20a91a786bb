#pragma once
// Simulated time as whole clock cycles. rtusim's modules have no clock signal: a module wakes only
// in the cycles where it has work and converts between cycles and SystemC time here.

#include <cstdint>
#include <stdexcept>
#include <string>

#include <systemc>

#include "base/timing_limits.h"

namespace rtu {

// now() reads the simulated time of the kernel that was current when the clock was made (each
// run makes a fresh kernel first). The channels check it on every transfer while simulated time
// moves only every few thousand cycles, so it reads the time directly rather than through the
// library call sc_time_stamp(), and divides only when the time has moved.
class CycleClock {
 public:
  explicit CycleClock(sc_core::sc_time period)
      : period_(period), time_(&sc_core::sc_get_curr_simcontext()->time_stamp()) {}

  // Period of a clock at `megahertz`, rounded to the 1 ps time resolution.
  static CycleClock atMegahertz(double megahertz) {
    return CycleClock(sc_core::sc_time(1e6 / megahertz, sc_core::SC_PS));
  }

  sc_core::sc_time period() const { return period_; }
  uint64_t now() const {
    if (time_->value() != nowStamp_) {
      nowStamp_ = time_->value();
      nowCycle_ = nowStamp_ / period_.value();
    }
    return nowCycle_;
  }
  // Simulated time in picoseconds (the time resolution): no conversion at all.
  uint64_t nowPicoseconds() const { return time_->value(); }
  // The delay from now to the start of `cycle` (a later cycle). Throws std::overflow_error past
  // kMaxCycles rather than let the picosecond count wrap.
  sc_core::sc_time until(uint64_t cycle) const {
    if (cycle > kMaxCycles) pastLastCycle(cycle);
    return sc_core::sc_time::from_value(period_.value() * (cycle - now()));
  }
  // Out of line and cold: callers that convert a cycle per access (LtTime::delayTo) stay small
  // enough to be inlined.
  [[noreturn, gnu::noinline, gnu::cold]] static void pastLastCycle(uint64_t cycle) {
    throw std::overflow_error("the run reached cycle " + std::to_string(cycle) +
                              ", past the last simulated cycle " + std::to_string(kMaxCycles));
  }

 private:
  sc_core::sc_time period_;
  const sc_core::sc_time* time_;
  mutable uint64_t nowStamp_ = 0, nowCycle_ = 0;  // the last time read and its cycle
};

}  // namespace rtu
