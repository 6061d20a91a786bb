#pragma once
// The BVH kind's own counters (rtu/core_kind.h: a kind's Counters), counted per job when a core
// offers its result, and their declaration (base/statistics.h), as SvoCounters: a core's
// statistics hold them (kinds/core_statistics.h), so they are reported, written to JSON and summed
// like the rest.

#include <cstdint>

#include "base/statistics.h"
#include "kinds/bvh/bvh_traversal.h"

namespace rtu {

struct BvhCounters {
  uint64_t bvhNodesVisited = 0;
  uint64_t bvhBoxTests = 0;
  uint64_t bvhTriangleTests = 0;
  uint64_t bvhStackOverflows = 0;  // rays that lost a stack entry
  uint64_t bvhBytesFetched = 0;
  uint64_t bvhAnyHitRays = 0;  // rays traced as any-hit (rtu/ray_span.h)
  uint64_t bvhAnyHitHits = 0;  // of which hit (occluded)
  uint64_t bvhInstances = 0;   // instances a two-level BVH's rays entered (XFORM states)

  // One ray's counts added.
  void add(const BvhRayCounts& counts);

  static const StatisticGroup<BvhCounters>& declaration();
};

}  // namespace rtu
