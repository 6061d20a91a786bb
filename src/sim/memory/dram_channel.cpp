#include "sim/memory/dram_channel.h"

#include <cmath>

namespace rtu {

uint64_t DramChannel::transferCycles(uint32_t bytes) const {
  return static_cast<uint64_t>(std::ceil(bytes / config_.bytesPerCycle));
}

uint64_t DramChannel::read(uint32_t bytes, uint64_t issueCycle) {
  const uint64_t transfer = transferCycles(bytes);
  const uint64_t start = bus_.book(issueCycle + config_.latency, transfer);
  ++stats_.reads;
  stats_.bytes += bytes;
  stats_.busyCycles += transfer;
  return start + transfer;
}

}  // namespace rtu
