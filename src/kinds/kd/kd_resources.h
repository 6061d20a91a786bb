#pragma once
// The k-d core's hardware (issue 30 §2; docs/comparison.md, "Resources"): seed 001's units as one
// core (specs/001 §2.2), binary32: SINT's 2 adders, 2 dividers and 5 comparators (the slabs'
// order, max and min, entry against exit), TRAV's adder, divider and 3 comparators, and the short
// stack with its restart node; the triangle unit is INT: 20 multipliers, 18 adders, 1 divider, 3
// comparators (the RTL's, spec 001 §2.2 "Resources").

#include "kinds/kd/kd_traversal.h"
#include "rtu/resource_estimate.h"

namespace rtu {

// The short stack: `stackDepth` entries and the restart node, each a node (16) and a t (32).
CoreResources coreResources(const KdTraversalConfig& config);

}  // namespace rtu
