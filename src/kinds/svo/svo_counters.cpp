#include "kinds/svo/svo_counters.h"

namespace rtu {

const StatisticGroup<SvoCounters>& SvoCounters::declaration() {
  using C = SvoCounters;
  static const StatisticGroup<SvoCounters> group =
      StatisticGroup<SvoCounters>("an SVO core's counters")
          .count(Statistic("stack_overflows", "rays",
                           "rays that ran out of stack frames, reported as misses (result flag 1)")
                     .runTotal()
                     .reportedWhenNotZero(),
                 &C::stackOverflows)
          .count(Statistic("t_overflows", "rays",
                           "rays with t-values beyond the fixed-point range (result flag 2)")
                     .runTotal()
                     .reportedWhenNotZero("t-values beyond the fixed-point range; flag 2"),
                 &C::tOverflows)
          .count(Statistic("any_hit_rays", "rays",
                           "rays traced as any-hit (shadow and occlusion rays: the traversal "
                           "ends at the first hit within t in [0, 1]), among the rays")
                     .runTotal()
                     .reportedWhenNotZero(),
                 &C::anyHitRays)
          .count(Statistic("any_hit_hits", "rays",
                           "any-hit rays that hit something (occluded shadow rays)")
                     .runTotal()
                     .reportedWhenNotZero(),
                 &C::anyHitHits);
  return group;
}

}  // namespace rtu
