#include "rtu/host_link.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "base/timing_limits.h"

namespace rtu {

HostLinkPacer::HostLinkPacer(HostLinkConfig config)
    : config_(config),
      slot_(config.bytesPerCycle > 0.0
                ? static_cast<double>(config.recordBytes) / config.bytesPerCycle
                : 0.0),
      generator_(config.seed) {}

// Slot boundaries are computed from the last restart, not accumulated, so rounding cannot drift
// them across a cycle boundary over millions of records. The ceiling is taken by hand: std::ceil
// is a library call on x86-64's baseline, and this runs for every record.
// Signed conversions: x86-64 converts unsigned 64-bit integers to and from double in several
// instructions. Record counts and cycles stay far below 2^63.
uint64_t HostLinkPacer::slotStart(uint64_t records) const {
  const double cycles = static_cast<double>(static_cast<int64_t>(records)) * slot_ - 1e-6;  // > -1
  const auto whole = static_cast<int64_t>(std::max(cycles, 0.0));
  return restartCycle_ +
         static_cast<uint64_t>(static_cast<double>(whole) < cycles ? whole + 1 : whole);
}

uint64_t HostLinkPacer::nextAllowed(uint64_t cycle) {
  if (config_.bytesPerCycle <= 0.0) return cycle + 1;
  // A record that crossed as early as allowed keeps the fraction of its slot; one held back
  // (an idle producer or consumer) restarts the pacing from its own cycle.
  if (cycle > lastSlotStart_) {
    restartCycle_ = cycle;
    recordsSinceRestart_ = 0;
  }
  ++recordsSinceRestart_;
  lastSlotStart_ = slotStart(recordsSinceRestart_);
  return std::max(cycle + 1, lastSlotStart_);
}

bool HostLinkPacer::drawActive() {
  return std::uniform_real_distribution<double>(0.0, 1.0)(generator_) < config_.activeProbability;
}

void validate(const HostLinkConfig& config, const char* which) {
  const double rate = config.bytesPerCycle;
  if (rate != 0.0 && !(rate >= kMinBytesPerCycle && rate <= kMaxBytesPerCycle))  // NaN fails too
    throw std::invalid_argument(std::string(which) +
                                " bytes per cycle must be 0 (unlimited) or in " + rateRange() +
                                ", not " + std::to_string(rate));
  if (!(config.activeProbability > 0.0 && config.activeProbability <= 1.0))
    throw std::invalid_argument(std::string(which) + " activity must be in (0, 1]");
}

}  // namespace rtu
