#pragma once
// The SVO core's hardware (issue 30 §2; docs/comparison.md, "Resources"): the thesis' core of
// Revelles' traversal in its fixed-point format, with no multiplier and no divider (the thesis'
// Table 8.3 and appendix E.1: 0 DSP; the midpoints are a sum and a shift, the child rules
// comparisons).

#include "kinds/svo/golden_config.h"
#include "rtu/resource_estimate.h"

namespace rtu {

// The stack of `stackFrames` frames, each the node's entry word (32), t0, tm and t1 (9 values of
// the format's width) and the child index (3); 3 adders (the midpoints) and 8 comparators (2 for
// the entry's max of t0, 3 for the first child's tm against it, 2 for the exit's min of t1, 1 for
// the exit against zero) of the format's width. No triangle unit.
CoreResources coreResources(const GoldenConfig& config);

}  // namespace rtu
