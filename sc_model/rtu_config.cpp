#include "rtu_config.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rtu {

void validate(const RtuConfig& config) {
  if (config.cores < 1 || config.cores > kMaxCores)
    throw std::invalid_argument("the RTU needs 1 to " + std::to_string(kMaxCores) +
                                " cores, got " + std::to_string(config.cores));
  if (config.stackFrames < 1 || config.stackFrames > kMaxStackFrames)
    throw std::invalid_argument("stack depth must be 1 to " + std::to_string(kMaxStackFrames) +
                                " frames, got " + std::to_string(config.stackFrames));
  if (!(config.clockMhz > 0.0) || !std::isfinite(config.clockMhz) || config.clockMhz > 1e6)
    throw std::invalid_argument("clock must be a positive frequency up to 1 THz (in MHz)");
  if (config.reorderCapacity < 0)
    throw std::invalid_argument("reorder buffer capacity must not be negative");
  config.jobManager.format.validate();
  validate(config.memory);  // settings are checked even when ideal memory ignores them
  validate(config.hostInput, "host input");
  validate(config.hostOutput, "host output");
}

}  // namespace rtu
