#include "kinds/kd/kd_resources.h"

namespace rtu {

CoreResources coreResources(const KdTraversalConfig& config) {
  constexpr auto kFloat = NumberKind::Float;
  CoreResources resources;
  resources.core.memories.push_back({"kd short stack", config.stackDepth + 1, 48, 1});
  resources.core.units = {{"kd SINT", ArithmeticKind::Adder, kFloat, 32, 2},
                          {"kd SINT", ArithmeticKind::Divider, kFloat, 32, 2},
                          {"kd SINT", ArithmeticKind::Comparator, kFloat, 32, 5},
                          {"kd TRAV", ArithmeticKind::Adder, kFloat, 32, 1},
                          {"kd TRAV", ArithmeticKind::Divider, kFloat, 32, 1},
                          {"kd TRAV", ArithmeticKind::Comparator, kFloat, 32, 3}};
  resources.triangleUnit.units = {{"kd INT", ArithmeticKind::Adder, kFloat, 32, 18},
                                  {"kd INT", ArithmeticKind::Multiplier, kFloat, 32, 20},
                                  {"kd INT", ArithmeticKind::Divider, kFloat, 32, 1},
                                  {"kd INT", ArithmeticKind::Comparator, kFloat, 32, 3}};
  return resources;
}

}  // namespace rtu
