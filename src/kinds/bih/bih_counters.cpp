#include "kinds/bih/bih_counters.h"

#include "rtu/any_hit_statistics.h"

namespace rtu {

void BihCounters::add(const BihRayCounts& counts) {
  constexpr uint64_t kAccessBytes = 4 * sizeof(uint32_t);  // BihTraversal::kWordsPerRead words
  bihNodesVisited += counts.nodes;
  bihTriangleTests += counts.triangleTests;
  bihStackOverflows += counts.dropped > 0;
  bihDividerErrors += counts.errBits;
  bihBytesFetched += uint64_t{counts.accesses} * kAccessBytes;
  bihAnyHitRays += counts.anyHit;
  bihAnyHitHits += counts.occluded;
}

const StatisticGroup<BihCounters>& BihCounters::declaration() {
  using C = BihCounters;
  static const StatisticGroup<BihCounters> group =
      StatisticGroup<BihCounters>("a BIH core's counters")
          .count(Statistic("bih_nodes_visited", "nodes", "BIH node triples read").runTotal(),
                 &C::bihNodesVisited)
          .count(Statistic("bih_triangle_tests", "tests",
                           "ray/triangle tests issued to the pipelined unit (its fill rate: "
                           "tests over busy cycles)")
                     .runTotal(),
                 &C::bihTriangleTests)
          .count(Statistic("bih_stack_overflows", "rays",
                           "rays that lost a stack entry to the full 32-entry stack (a tree "
                           "deeper than the builder's 31 levels); their result may miss a hit")
                     .runTotal()
                     .reportedWhenNotZero(),
                 &C::bihStackOverflows)
          .count(Statistic("bih_divider_errors", "tests",
                           "tests ended by the VHDL divider's error bit (t outside its range)")
                     .runTotal()
                     .reportedWhenNotZero(),
                 &C::bihDividerErrors)
          .count(Statistic("bih_bytes_fetched", "bytes",
                           "bytes the BIH traversals read, 16 a 4-word access (per ray: divided "
                           "by the jobs)")
                     .runTotal(),
                 &C::bihBytesFetched)
          .count(anyHitRaysStatistic("bih"), &C::bihAnyHitRays)
          .count(anyHitHitsStatistic("bih"), &C::bihAnyHitHits);
  return group;
}

}  // namespace rtu
