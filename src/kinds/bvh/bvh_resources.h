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

// A core that also walks two-level jobs (bvh_traversal.h, "Two levels"; animate --core bvh):
// coreResources and, in the core, its transform unit for XFORM (one a core, pipelined), binary32:
// the world ray into the instance's mesh space as rtu/model_transform.h's toModelSpace computes
// it, the origin (o - T: 3 subtractions; a row of R^T times it: 3 multiplications and 2
// additions; times 1/S: 1 multiplication; three rows) 12 multiplications and 9 additions, the
// direction (no subtraction) 12 and 6, and the slab test's reciprocal direction (makeBvhRay,
// bvh_ray.h) 3 comparisons of |d| with 2^-64 and 3 divisions: 24 multipliers, 15 adders, 3
// dividers, 3 comparators. The one-level core has none of it: its job manager moves the ray
// (ray stages, not in the estimate). The instance record and the top level's registers are
// registers, as the rest of the core's, and not counted.
CoreResources twoLevelCoreResources(const BvhConfig& config);

}  // namespace rtu
