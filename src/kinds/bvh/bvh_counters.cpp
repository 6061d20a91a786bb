#include "kinds/bvh/bvh_counters.h"

#include "kinds/bvh/bvh_intersectors.h"
#include "kinds/bvh/langr_node.h"
#include "rtu/any_hit_statistics.h"

namespace rtu {

void BvhCounters::add(const BvhRayCounts& counts) {
  using Traversal = BvhTraversal<LangrNode, SelectedIntersector>;
  bvhNodesVisited += counts.nodes;
  bvhBoxTests += counts.boxTests;
  bvhTriangleTests += counts.triangleTests;
  bvhStackOverflows += counts.dropped > 0;
  bvhBytesFetched += uint64_t{counts.accesses} * Traversal::kWordsPerRead * sizeof(uint32_t);
  bvhAnyHitRays += counts.anyHit;
  bvhAnyHitHits += counts.occluded;
  bvhInstances += counts.instances;
}

const StatisticGroup<BvhCounters>& BvhCounters::declaration() {
  using C = BvhCounters;
  static const StatisticGroup<BvhCounters> group =
      StatisticGroup<BvhCounters>("a BVH core's counters")
          .count(Statistic("bvh_nodes_visited", "nodes", "BVH node records fetched").runTotal(),
                 &C::bvhNodesVisited)
          .count(Statistic("bvh_box_tests", "tests", "ray/box tests").runTotal(), &C::bvhBoxTests)
          .count(Statistic("bvh_triangle_tests", "tests", "ray/triangle tests").runTotal(),
                 &C::bvhTriangleTests)
          .count(Statistic("bvh_stack_overflows", "rays",
                           "rays that lost a stack entry to a full stack (core.stack_depth); "
                           "their result may miss a nearer hit")
                     .runTotal()
                     .reportedWhenNotZero(),
                 &C::bvhStackOverflows)
          .count(Statistic("bvh_bytes_fetched", "bytes",
                           "bytes the BVH traversals read, 16 a 4-word access (per ray: divided "
                           "by the jobs)")
                     .runTotal(),
                 &C::bvhBytesFetched)
          .count(anyHitRaysStatistic("bvh"), &C::bvhAnyHitRays)
          .count(anyHitHitsStatistic("bvh"), &C::bvhAnyHitHits)
          .count(Statistic("bvh_instances", "instances",
                           "instances a two-level BVH's rays entered, an XFORM state each "
                           "(animate --core bvh; per ray: divided by the jobs)")
                     .runTotal()
                     .reportedWhenNotZero(),
                 &C::bvhInstances);
  return group;
}

}  // namespace rtu
