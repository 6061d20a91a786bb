#pragma once
// The BIH core's hardware (issue 30 §2; docs/comparison.md, "Resources"): seed 004's traversal
// (Listing A.3) and its fixed-point ray/triangle unit (Listing A.2), sized by the formats n, m
// and C.

#include "kinds/bih/bih_config.h"
#include "rtu/resource_estimate.h"

namespace rtu {

// The core: the 32-entry stack of node triples (kBihStackEntries x 96 bits, A.3's RAM 992-1023),
// two plane distances ((plane - pos) idir: 2 adders of n + 2 bits, 2 multipliers of n + 2 by
// m + C bits) and 4 comparators of m + C bits (each distance against tmin and tmax).
// The triangle unit (A.2): 10 multipliers of m bits (t's numerator terms 2, denominator terms 2,
// the hit point's 2, the barycentrics' 4), 10 adders of m bits, the divider t_div of m bits and 5
// comparators of m bits.
CoreResources coreResources(const BihConfig& config);

}  // namespace rtu
