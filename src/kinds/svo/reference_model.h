#pragma once
// The float64 reference: the same traversal algorithm with double arithmetic and the ray set up in
// double, so its difference from the golden model is the cost of fixed point alone.

#include <cstdint>

#include "kinds/svo/ray_setup.h"
#include "kinds/svo/svo_memory.h"
#include "kinds/svo/traversal_core.h"

namespace rtu {

struct ReferenceResult {
  bool hit = false;
  double tHit = 0.0;
  int normalAxis = 0;
  uint32_t cost = 0;
  bool stackOverflow = false;
  uint64_t voxel = 0;  // on a hit: TraversalCore::hitVoxel()
};

class ReferenceModel {
 public:
  explicit ReferenceModel(WordMemory memory, double epsilon = kDefaultDirectionEpsilon,
                          int stackFrames = kMaxStackFrames);

  ReferenceResult trace(const Ray& ray, uint32_t root);

 private:
  WordMemory memory_;
  double epsilon_;
  TraversalCore<Float64Arith> core_;
};

}  // namespace rtu
