#pragma once
// Timing of the DRAM behind the L2: a fixed access latency, pipelined (reads overlap their
// latencies), in front of one data bus that transfers whole requests one after another in the
// order they are issued. A read issued at cycle I of B bytes:
//   start = max(I + latency, busFree),  end = start + ceil(B / bytesPerCycle),  busFree = end,
// and its data is complete at `end`. Addresses play no part (no banks or rows).

#include <cstdint>

#include "memory_config.h"

namespace rtu {

struct DramStats {
  uint64_t reads = 0;
  uint64_t bytes = 0;
  uint64_t busyCycles = 0;  // cycles the data bus spent transferring
};

class DramChannel {
 public:
  // `config` must have passed validate().
  explicit DramChannel(const DramConfig& config) : config_(config) {}

  // Returns the cycle the last byte of the read has arrived.
  uint64_t read(uint32_t bytes, uint64_t issueCycle);

  uint64_t transferCycles(uint32_t bytes) const;
  const DramStats& stats() const { return stats_; }

 private:
  DramConfig config_;
  uint64_t busFree_ = 0;
  DramStats stats_;
};

}  // namespace rtu
