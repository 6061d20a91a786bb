// The k-d core's settings checked (KdTraversalConfig::validate, kd_traversal.h).
#include <stdexcept>
#include <string>

#include "kinds/kd/kd_traversal.h"

namespace rtu {
namespace {

void checkRange(const char* key, int64_t value, int64_t low, int64_t high, const char* unit) {
  if (value < low || value > high)
    throw std::invalid_argument(std::string(key) + " must be " + std::to_string(low) + " to " +
                                std::to_string(high) + " " + unit + ", got " +
                                std::to_string(value));
}

}  // namespace

void KdTraversalConfig::validate() const {
  checkRange("core.short_stack", stackDepth, 1, kMaxKdShortStack, "entries");
  checkRange("core.box.latency", cycles.boxLatency, 1, kMaxKdUnitCycles, "cycles");
  checkRange("core.triangle.latency", cycles.triangleLatency, 1, kMaxKdUnitCycles, "cycles");
  checkRange("core.triangle.interval", cycles.triangleInterval, 1, kMaxKdUnitCycles, "cycles");
  if (cycles.triangleInterval > cycles.triangleLatency)
    throw std::invalid_argument(
        "core.triangle.interval (" + std::to_string(cycles.triangleInterval) +
        ") exceeds core.triangle.latency (" + std::to_string(cycles.triangleLatency) +
        "): a unit takes its next test no later than it answers one");
}

}  // namespace rtu
