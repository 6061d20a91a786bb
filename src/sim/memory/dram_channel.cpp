#include "sim/memory/dram_channel.h"

#include <cmath>

namespace rtu {

const StatisticGroup<DramStats>& DramStats::declaration() {
  static const StatisticGroup<DramStats> group =
      StatisticGroup<DramStats>("the DRAM channel")
          .count(Statistic("reads", "reads", "line reads from the L2"), &DramStats::reads)
          .count(Statistic("bytes", "bytes", "bytes read"), &DramStats::bytes)
          .count(Statistic("busy_cycles", "cycles", "cycles the data bus spent transferring"),
                 &DramStats::busyCycles);
  return group;
}

uint64_t DramChannel::transferCycles(uint32_t bytes) const {
  return static_cast<uint64_t>(std::ceil(bytes / config_.bytesPerCycle));
}

uint64_t DramChannel::read(uint32_t bytes, uint64_t issueCycle) {
  const uint64_t transfer = transferCycles(bytes);
  const uint64_t end = bus_.bookSpread(issueCycle + config_.latency, transfer);
  ++stats_.reads;
  stats_.bytes += bytes;
  stats_.busyCycles += transfer;
  return end;
}

}  // namespace rtu
