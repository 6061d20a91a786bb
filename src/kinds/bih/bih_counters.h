#pragma once
// The BIH kind's own counters (rtu/core_kind.h: a kind's Counters), counted per job when a core
// offers its result, and their declaration (base/statistics.h), as BvhCounters: a core's
// statistics hold them (kinds/core_statistics.h), so they are reported, written to JSON and summed
// like the rest. The triangle unit's fill rate (S4 §4.2 L672: "about 40 %") is bih_triangle_tests
// over the cores' busy cycles at an initiation interval of 1.

#include <cstdint>

#include "base/statistics.h"
#include "kinds/bih/bih_traversal.h"

namespace rtu {

struct BihCounters {
  uint64_t bihNodesVisited = 0;
  uint64_t bihTriangleTests = 0;
  uint64_t bihStackOverflows = 0;  // rays that lost a stack entry
  uint64_t bihDividerErrors = 0;   // tests ended by the VHDL divider's error bit
  uint64_t bihBytesFetched = 0;
  uint64_t bihAnyHitRays = 0;  // rays traced as any-hit (rtu/ray_span.h)
  uint64_t bihAnyHitHits = 0;  // of which hit (occluded)

  // One ray's counts added.
  void add(const BihRayCounts& counts);

  static const StatisticGroup<BihCounters>& declaration();
};

}  // namespace rtu
