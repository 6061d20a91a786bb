#pragma once
// Timing of the DRAM behind the L2: a fixed access latency, pipelined (reads overlap their
// latencies), in front of one data bus that transfers whole requests one after another in the
// order they are issued. A read issued at cycle I of B bytes:
//   start = max(I + latency, busFree),  end = start + ceil(B / bytesPerCycle),  busFree = end,
// and its data is complete at `end`. Addresses play no part (no banks or rows). With
// RequestOrder::Any (the loosely-timed model) reads may be issued out of cycle order: each takes
// the bus's first ceil(B / bytesPerCycle) free cycles from issue + latency on, around the
// transfers booked already, and ends after the last (ResourceBooking::bookSpread). Waiting for a
// gap as long as the whole transfer instead lost the bus the shorter gaps that out-of-order
// bookings leave: the loosely-timed frames limited by DRAM bandwidth took 9-14 % more cycles than
// the cycle-accurate ones (docs/performance.md).

#include <cstdint>

#include "base/statistics.h"
#include "sim/memory/memory_config.h"
#include "sim/memory/resource_booking.h"

namespace rtu {

struct DramStats {
  uint64_t reads = 0;
  uint64_t bytes = 0;
  uint64_t busyCycles = 0;  // cycles the data bus spent transferring

  static const StatisticGroup<DramStats>& declaration();
};

class DramChannel {
 public:
  // `config` must have passed validate().
  explicit DramChannel(const DramConfig& config, RequestOrder order = RequestOrder::Cycle)
      : config_(config), bus_(order) {}

  // Returns the cycle the last byte of the read has arrived.
  uint64_t read(uint32_t bytes, uint64_t issueCycle);

  uint64_t transferCycles(uint32_t bytes) const;
  // No later read is issued before `cycle` (RequestOrder::Any keeps bookings until then).
  void forgetBefore(uint64_t cycle) { bus_.forgetBefore(cycle); }
  const DramStats& stats() const { return stats_; }

 private:
  DramConfig config_;
  ResourceBooking bus_;
  DramStats stats_;
};

}  // namespace rtu
