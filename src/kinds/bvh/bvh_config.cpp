#include "kinds/bvh/bvh_config.h"

#include <stdexcept>
#include <string>

namespace rtu {
namespace {

void checkRange(const char* key, uint64_t value, uint64_t low, uint64_t high) {
  if (value < low || value > high)
    throw std::invalid_argument(std::string(key) + " must be " + std::to_string(low) + " to " +
                                std::to_string(high) + ", got " + std::to_string(value));
}

}  // namespace

std::string toString(TriangleTest test) {
  return test == TriangleTest::Watertight ? WatertightIntersector::kName
                                          : MollerTrumboreIntersector::kName;
}

TriangleTest parseTriangleTest(const std::string& name) {
  if (name == WatertightIntersector::kName) return TriangleTest::Watertight;
  if (name == MollerTrumboreIntersector::kName) return TriangleTest::MollerTrumbore;
  throw std::invalid_argument("unknown triangle test '" + name +
                              "': give watertight or moller-trumbore");
}

std::string toString(ChildOrder order) { return order == ChildOrder::Entry ? "entry" : "axis"; }

ChildOrder parseChildOrder(const std::string& name) {
  if (name == "entry") return ChildOrder::Entry;
  if (name == "axis") return ChildOrder::Axis;
  throw std::invalid_argument("unknown child order '" + name + "': give entry or axis");
}

void BvhConfig::validate() const {
  if (stackDepth < 1 || stackDepth > kMaxBvhStackDepth)
    throw std::invalid_argument("core.stack_depth must be 1 to " +
                                std::to_string(kMaxBvhStackDepth) + " entries, got " +
                                std::to_string(stackDepth));
  checkRange("core.box.latency", cycles.boxLatency, 1, kMaxBvhUnitCycles);
  checkRange("core.triangle.latency", cycles.triangleLatency, 1, kMaxBvhUnitCycles);
  checkRange("core.triangle.interval", cycles.triangleInterval, 1, kMaxBvhUnitCycles);
  checkRange("core.transform.latency", cycles.transformLatency, 1, kMaxBvhUnitCycles);
  if (cycles.triangleInterval > cycles.triangleLatency)
    throw std::invalid_argument(
        "core.triangle.interval (" + std::to_string(cycles.triangleInterval) +
        ") exceeds core.triangle.latency (" + std::to_string(cycles.triangleLatency) +
        "): a unit takes its next test no later than it answers one");
}

}  // namespace rtu
