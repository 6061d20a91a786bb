#include "kinds/kd/kd_counters.h"

#include "rtu/any_hit_statistics.h"

namespace rtu {

void KdCounters::add(const KdRayCounts& counts) {
  constexpr uint64_t kAccessBytes = KdTraversal::kWordsPerRead * sizeof(uint32_t);
  kdNodesVisited += counts.nodes;
  kdTriangleTests += counts.triangleTests;
  kdRestarts += counts.restarts;
  kdShortStackDrops += counts.dropped;
  kdBytesFetched += uint64_t{counts.accesses} * kAccessBytes;
  kdAnyHitRays += counts.anyHit;
  kdAnyHitHits += counts.occluded;
}

const StatisticGroup<KdCounters>& KdCounters::declaration() {
  using C = KdCounters;
  static const StatisticGroup<KdCounters> group =
      StatisticGroup<KdCounters>("a k-d core's counters")
          .count(Statistic("kd_nodes_visited", "nodes", "k-d node records read, interior and leaf")
                     .runTotal(),
                 &C::kdNodesVisited)
          .count(Statistic("kd_triangle_tests", "tests", "unit-triangle tests (INT)").runTotal(),
                 &C::kdTriangleTests)
          .count(Statistic("kd_restarts", "restarts",
                           "restarts at the restart node after the short stack ran empty "
                           "(core.short_stack)")
                     .runTotal(),
                 &C::kdRestarts)
          .count(Statistic("kd_short_stack_drops", "entries",
                           "short-stack entries overwritten by a push onto the full stack (a "
                           "restart recovers them)")
                     .runTotal(),
                 &C::kdShortStackDrops)
          .count(Statistic("kd_bytes_fetched", "bytes",
                           "bytes the k-d traversals read, 16 a 4-word access (per ray: divided "
                           "by the jobs)")
                     .runTotal(),
                 &C::kdBytesFetched)
          .count(anyHitRaysStatistic("kd"), &C::kdAnyHitRays)
          .count(anyHitHitsStatistic("kd"), &C::kdAnyHitHits);
  return group;
}

}  // namespace rtu
