#include "kinds/bih/bih_resources.h"

#include "kinds/bih/bih_traversal.h"

namespace rtu {

CoreResources coreResources(const BihConfig& config) {
  constexpr auto kFixed = NumberKind::Fixed;
  const FixedTriangleFormat& f = config.format;
  CoreResources resources;
  resources.core.memories.push_back({"bih stack", kBihStackEntries, 96, 1});
  resources.core.units = {
      {"bih plane distances", ArithmeticKind::Adder, kFixed, f.n + 2, 2},
      {"bih plane distances", ArithmeticKind::Multiplier, kFixed, f.n + 2, 2, f.m + f.C},
      {"bih plane distances", ArithmeticKind::Comparator, kFixed, f.m + f.C, 4}};
  resources.triangleUnit.units = {
      {"bih triangle unit", ArithmeticKind::Adder, kFixed, f.m, 10},
      {"bih triangle unit", ArithmeticKind::Multiplier, kFixed, f.m, 10},
      {"bih triangle unit", ArithmeticKind::Divider, kFixed, f.m, 1},
      {"bih triangle unit", ArithmeticKind::Comparator, kFixed, f.m, 5}};
  return resources;
}

}  // namespace rtu
