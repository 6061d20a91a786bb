#pragma once
// The k-d kind's own counters (rtu/core_kind.h: a kind's Counters), counted per job when a core
// offers its result, and their declaration (base/statistics.h), as BvhCounters: a core's
// statistics hold them (kinds/core_statistics.h), so they are reported, written to JSON and summed
// like the rest. The short stack's drops are entries, not rays: dropping is its design (S1
// §2.6.9), a restart recovers them, and the result never depends on them.

#include <cstdint>

#include "base/statistics.h"
#include "kinds/kd/kd_traversal.h"

namespace rtu {

struct KdCounters {
  uint64_t kdNodesVisited = 0;
  uint64_t kdTriangleTests = 0;
  uint64_t kdRestarts = 0;
  uint64_t kdShortStackDrops = 0;  // entries overwritten by a push onto the full short stack
  uint64_t kdBytesFetched = 0;
  uint64_t kdAnyHitRays = 0;  // rays traced as any-hit (rtu/ray_span.h)
  uint64_t kdAnyHitHits = 0;  // of which hit (occluded)

  // One ray's counts added.
  void add(const KdRayCounts& counts);

  static const StatisticGroup<KdCounters>& declaration();
};

}  // namespace rtu
