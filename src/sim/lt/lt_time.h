#pragma once
// Time in the loosely-timed model (docs/fidelity.md, "The loosely-timed model"): TLM-2.0's
// annotated delays, counted in whole clock cycles. A component's cycle is simulated time plus its
// delay; every delay is a whole number of cycles, as every wait is.

#include <cstdint>
#include <vector>

#include <systemc>
#include <tlm>

#include "sim/kernel/cycle_clock.h"

namespace rtu {

class LtTime {
 public:
  explicit LtTime(const CycleClock& clock)
      : clock_(clock),
        period_(clock.period()),
        periodPs_(period_.value()),
        cyclesPerPs_(1.0 / static_cast<double>(periodPs_)),
        exactCycles_(kExactPs / periodPs_) {}

  // The cycle `delay` after simulated time. Delays are whole cycles, so a multiplication by the
  // reciprocal, rounded, gives the quotient exactly (below 2^53 ps) without a division per read.
  uint64_t cycleAt(const sc_core::sc_time& delay) const {
    if (delay.value() >= kExactPs) return clock_.now() + delay.value() / periodPs_;
    // Through int64_t: x86-64 converts signed integers and doubles in one instruction each.
    const double ps = static_cast<double>(static_cast<int64_t>(delay.value()));
    return clock_.now() + static_cast<uint64_t>(static_cast<int64_t>(ps * cyclesPerPs_ + 0.5));
  }
  // The delay from simulated time to `cycle` (not before it). Scaled in line, exactly while the
  // picoseconds fit a double's 53 bits: the library's sc_time::from_value is a call per read.
  sc_core::sc_time delayTo(uint64_t cycle) const {
    if (cycle > kMaxCycles) CycleClock::pastLastCycle(cycle);  // throws std::overflow_error
    return cycles(cycle - clock_.now());
  }
  // `count` cycles as a delay.
  sc_core::sc_time cycles(uint64_t count) const {
    if (count >= exactCycles_) return sc_core::sc_time::from_value(count * periodPs_);
    sc_core::sc_time delay = period_;
    delay *= static_cast<double>(count);
    return delay;
  }
  uint64_t now() const { return clock_.now(); }
  // Picoseconds since the start: the time of `delay` as a target that counts in picoseconds sees
  // it is now + delay.value(), with no conversion.
  uint64_t nowPicoseconds() const { return clock_.nowPicoseconds(); }
  // The delay from simulated time to `picoseconds` (a whole cycle, not before now).
  sc_core::sc_time delayToPicoseconds(uint64_t picoseconds) const {
    return cycles((picoseconds - clock_.nowPicoseconds()) / periodPs_);
  }
  uint64_t periodPicoseconds() const { return periodPs_; }
  // Whether simulated time has moved since `seen` was last set here (it moves only at the
  // initiator's quantum synchronisations): a target then forgets the bookings behind it.
  bool movedSince(uint64_t& seen) const {
    const uint64_t cycle = clock_.now();
    if (cycle == seen) return false;
    seen = cycle;
    return true;
  }
  sc_core::sc_time period() const { return period_; }

 private:
  static constexpr uint64_t kExactPs = uint64_t{1} << 53;  // a double holds them exactly

  CycleClock clock_;
  sc_core::sc_time period_;
  uint64_t periodPs_;
  double cyclesPerPs_;
  uint64_t exactCycles_;  // fewer cycles than this scale exactly through a double
};

// A read of a cache line through a socket, for its timing: the caches hold tags only (the image
// is read-only, cache_array.h), so the target fills no data. Returns the cycle the line is there.
class LineRead {
 public:
  explicit LineRead(uint32_t maxBytes) : buffer_(maxBytes) {
    payload_.set_read();
    payload_.set_data_ptr(buffer_.data());
  }

  // Requested at `delay` after simulated time; returns the delay to the line's arrival.
  template <typename Socket>
  sc_core::sc_time operator()(Socket& socket, uint64_t address, uint32_t bytes,
                              sc_core::sc_time delay) {
    payload_.set_address(address);
    payload_.set_data_length(bytes);
    payload_.set_streaming_width(bytes);
    payload_.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    socket->b_transport(payload_, delay);
    return delay;
  }
  // Requested in `cycle`; returns the cycle of the line's arrival.
  template <typename Socket>
  uint64_t operator()(Socket& socket, const LtTime& time, uint64_t address, uint32_t bytes,
                      uint64_t cycle) {
    return time.cycleAt((*this)(socket, address, bytes, time.delayTo(cycle)));
  }

 private:
  std::vector<unsigned char> buffer_;
  tlm::tlm_generic_payload payload_;
};

}  // namespace rtu
