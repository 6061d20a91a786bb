#include "host_link.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rtu {

HostLinkPacer::HostLinkPacer(HostLinkConfig config) : config_(config), generator_(config.seed) {}

uint64_t HostLinkPacer::nextAllowed(uint64_t cycle) {
  if (config_.bytesPerCycle <= 0.0) return cycle + 1;
  earliest_ = std::max(earliest_, static_cast<double>(cycle)) +
              static_cast<double>(kHostRecordBytes) / config_.bytesPerCycle;
  return std::max(cycle + 1, static_cast<uint64_t>(std::ceil(earliest_)));
}

bool HostLinkPacer::drawActive() {
  return std::uniform_real_distribution<double>(0.0, 1.0)(generator_) < config_.activeProbability;
}

void validate(const HostLinkConfig& config, const char* which) {
  if (!(config.bytesPerCycle >= 0.0) || !std::isfinite(config.bytesPerCycle))
    throw std::invalid_argument(std::string(which) + " bytes per cycle must be 0 (unlimited) or positive");
  if (!(config.activeProbability > 0.0 && config.activeProbability <= 1.0))
    throw std::invalid_argument(std::string(which) + " activity must be in (0, 1]");
}

}  // namespace rtu
