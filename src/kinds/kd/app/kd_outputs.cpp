#include "kinds/kd/app/kd_outputs.h"

#include <cstdio>

#include "app/triangle_render.h"
#include "kinds/core_result.h"
#include "kinds/kd/kd_counters.h"

namespace rtu {

std::string KindOutputs<KdKind>::core(const RunConfig& settings) {
  const KdTraversalConfig& core = settings.rtu.coreConfig<KdKind>();
  return "kd core, " + std::to_string(core.stackDepth) + "-entry short stack, triangle unit " +
         std::to_string(core.cycles.triangleLatency) + " cycles";
}

// Hits, mean cost and the k-d core's counters per ray.
std::string KindOutputs<KdKind>::results(const RunConfig&,
                                         const std::vector<CoreKindResult>& kindResults) {
  const std::vector<KdResult> results = resultsOfKind<KdKind>(kindResults);
  const auto counters = countersOf<KdCounters>(results);
  const size_t rays = results.size();
  char text[256];
  std::snprintf(text, sizeof text,
                "kd          %.2f nodes, %.2f triangle tests, %.3f restarts, %.3f short-stack "
                "drops, %.1f bytes per ray\n",
                perRay(counters.kdNodesVisited, rays), perRay(counters.kdTriangleTests, rays),
                perRay(counters.kdRestarts, rays), perRay(counters.kdShortStackDrops, rays),
                perRay(counters.kdBytesFetched, rays));
  return describeTriangleHits(results) + text;
}

RenderedFrame KindOutputs<KdKind>::pixels(const RunConfig& settings, const FrameScene& scene,
                                          const std::vector<CoreKindResult>& results) {
  return triangleFrame(settings.camera, scene, resultsOfKind<KdKind>(results),
                       [](const KdResult& result) { return result.t; });
}

}  // namespace rtu
