#pragma once
// The BVH core's hardware (issue 30 §2; docs/comparison.md, "Resources"): seed 003's traversal in
// binary32 with a box unit testing a node's two children at once, and its ray/triangle unit.

#include "kinds/bvh/bvh_config.h"
#include "rtu/resource_estimate.h"

namespace rtu {

// The core: the stack of `stackDepth` entries of 3 words (the far child's two node words and its
// entry distance, bvh_traversal.h), and the box unit's two slab tests (a box: 6 subtractions, 6
// multiplications by the inverse direction, 11 comparisons: 6 to order each slab, 4 for the max of
// the entries and the min of the exits, 1 entry against exit), binary32.
// The triangle unit, binary32: watertight (Woop et al.) 22 adders, 18 multipliers, 1 divider, 6
// comparators; Moller-Trumbore 24 adders, 27 multipliers, 1 divider, 4 comparators.
CoreResources coreResources(const BvhConfig& config);

}  // namespace rtu
