#include "kinds/bvh/bvh_resources.h"

#include <vector>

namespace rtu {

CoreResources coreResources(const BvhConfig& config) {
  constexpr auto kFloat = NumberKind::Float;
  CoreResources resources;
  resources.core.memories.push_back({"bvh stack", config.stackDepth, 96, 1});
  resources.core.units = {{"bvh box unit", ArithmeticKind::Adder, kFloat, 32, 12},
                          {"bvh box unit", ArithmeticKind::Multiplier, kFloat, 32, 12},
                          {"bvh box unit", ArithmeticKind::Comparator, kFloat, 32, 22}};
  const bool watertight = config.triangleTest == TriangleTest::Watertight;
  resources.triangleUnit.units = {
      {"bvh triangle unit", ArithmeticKind::Adder, kFloat, 32, watertight ? 22 : 24},
      {"bvh triangle unit", ArithmeticKind::Multiplier, kFloat, 32, watertight ? 18 : 27},
      {"bvh triangle unit", ArithmeticKind::Divider, kFloat, 32, 1},
      {"bvh triangle unit", ArithmeticKind::Comparator, kFloat, 32, watertight ? 6 : 4}};
  return resources;
}

CoreResources twoLevelCoreResources(const BvhConfig& config) {
  constexpr auto kFloat = NumberKind::Float;
  CoreResources resources = coreResources(config);
  std::vector<ArithmeticUnits>& units = resources.core.units;
  units.push_back({"bvh transform unit", ArithmeticKind::Adder, kFloat, 32, 15});
  units.push_back({"bvh transform unit", ArithmeticKind::Multiplier, kFloat, 32, 24});
  units.push_back({"bvh transform unit", ArithmeticKind::Divider, kFloat, 32, 3});
  units.push_back({"bvh transform unit", ArithmeticKind::Comparator, kFloat, 32, 3});
  return resources;
}

}  // namespace rtu
