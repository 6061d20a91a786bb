#pragma once
// The BVH core's own settings (RtuConfig::coreConfig<BvhKind<>>(); the schema's keys in
// src/config/config_schema.cpp, "addBvhSettings"): its stack, child order, triangle test and the
// cycles of its box and triangle units (bvh_timing.h).

#include <cstdint>
#include <string>

#include "kinds/bvh/bvh_intersectors.h"
#include "kinds/bvh/bvh_timing.h"
#include "kinds/bvh/bvh_traversal.h"

namespace rtu {

constexpr int kMaxBvhStackDepth = 1024;
constexpr uint32_t kMaxBvhUnitCycles = 1024;

struct BvhConfig {
  // Entries: the seed's build stack has 64 (Alg. 3), its traversal's depth is unstated.
  int stackDepth = 64;
  ChildOrder childOrder = ChildOrder::Entry;
  TriangleTest triangleTest = TriangleTest::Watertight;
  BvhCycles cycles;

  // Throws std::invalid_argument naming the setting (core.stack_depth, core.box.latency,
  // core.triangle.latency, core.triangle.interval) for a value the core cannot have: a stack of
  // 1 to kMaxBvhStackDepth entries, units of 1 to kMaxBvhUnitCycles cycles, and an interval no
  // longer than the latency (a unit takes its next test no later than it answers one).
  void validate() const;
};

// The settings' names: "watertight", "moller-trumbore"; "entry", "axis". The parsers throw
// std::invalid_argument for another name.
std::string toString(TriangleTest test);
TriangleTest parseTriangleTest(const std::string& name);
std::string toString(ChildOrder order);
ChildOrder parseChildOrder(const std::string& name);

}  // namespace rtu
