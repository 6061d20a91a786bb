#include "kinds/svo/svo_resources.h"

namespace rtu {

CoreResources coreResources(const GoldenConfig& config) {
  const int width = config.format.totalBits;
  CoreResources resources;
  resources.core.memories.push_back({"svo stack", config.stackFrames, 32 + 9 * width + 3, 1});
  resources.core.units = {{"svo midpoints", ArithmeticKind::Adder, NumberKind::Fixed, width, 3},
                          {"svo child rules", ArithmeticKind::Comparator, NumberKind::Fixed, width,
                           8}};
  return resources;
}

}  // namespace rtu
