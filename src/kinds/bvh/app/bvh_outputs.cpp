#include "kinds/bvh/app/bvh_outputs.h"

#include <cstdio>

#include "app/triangle_render.h"
#include "kinds/bvh/bvh_counters.h"
#include "kinds/core_result.h"

namespace rtu {

std::string KindOutputs<BvhKind<>>::core(const RunConfig& settings) {
  const BvhConfig& core = settings.rtu.coreConfig<BvhKind<>>();
  return "bvh core, " + toString(core.triangleTest) + " test, " + std::to_string(core.stackDepth) +
         " stack entries";
}

// Hits, mean cost and the BVH's counters per ray.
std::string KindOutputs<BvhKind<>>::results(const RunConfig&,
                                            const std::vector<CoreKindResult>& kindResults) {
  const std::vector<BvhResult> results = resultsOfKind<BvhKind<>>(kindResults);
  const auto counters = countersOf<BvhCounters>(results);
  const size_t rays = results.size();
  char text[256];
  std::snprintf(text, sizeof text,
                "bvh         %.2f nodes, %.2f box tests, %.2f triangle tests, %.1f bytes per "
                "ray; %llu rays lost stack entries\n",
                perRay(counters.bvhNodesVisited, rays), perRay(counters.bvhBoxTests, rays),
                perRay(counters.bvhTriangleTests, rays), perRay(counters.bvhBytesFetched, rays),
                static_cast<unsigned long long>(counters.bvhStackOverflows));
  return describeTriangleHits(results) + text;
}

RenderedFrame KindOutputs<BvhKind<>>::pixels(const RunConfig& settings, const FrameScene& scene,
                                             const std::vector<CoreKindResult>& results) {
  return triangleFrame(settings.camera, scene, resultsOfKind<BvhKind<>>(results),
                       [](const BvhResult& result) { return result.t; });
}

}  // namespace rtu
