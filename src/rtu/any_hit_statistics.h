#pragma once
// The declarations of the any-hit counters every triangle kind keeps beside its own
// (rtu/ray_span.h: shadow and occlusion rays end at their first hit), named with the kind's prefix
// as its other counters are ("bvh_any_hit_rays"), so each kind's statistics count its any-hit rays
// apart.

#include <string>

#include "base/statistics.h"

namespace rtu {

inline Statistic anyHitRaysStatistic(const std::string& kind) {
  return Statistic(kind + "_any_hit_rays", "rays",
                   "rays traced as any-hit (shadow and occlusion rays: the traversal ends at the "
                   "first hit within t in [0, 1]), among the rays")
      .runTotal()
      .reportedWhenNotZero();
}

inline Statistic anyHitHitsStatistic(const std::string& kind) {
  return Statistic(kind + "_any_hit_hits", "rays",
                   "any-hit rays that hit something (occluded shadow rays)")
      .runTotal()
      .reportedWhenNotZero();
}

}  // namespace rtu
