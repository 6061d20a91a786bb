#pragma once
// The SVO kind's own counters (rtu/core_kind.h: a kind's Counters), counted per job when a core
// offers its result, and their declaration (base/statistics.h): a core's statistics hold them
// (kinds/core_statistics.h), so they are reported, written to JSON and summed like the rest.

#include <cstdint>

#include "base/statistics.h"

namespace rtu {

struct SvoCounters {
  uint64_t stackOverflows = 0;
  uint64_t tOverflows = 0;
  uint64_t anyHitRays = 0;  // rays traced as any-hit (rtu/ray_span.h), among the run's rays
  uint64_t anyHitHits = 0;  // of them, the ones that hit

  static const StatisticGroup<SvoCounters>& declaration();
};

}  // namespace rtu
