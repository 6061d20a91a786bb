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

KindOutputs<KdKind>::Tally::Tally(const RunConfig&, const FrameScene& scene) : results_(scene) {}

void KindOutputs<KdKind>::Tally::add(const CoreKindResult& result, PixelSink* frame) {
  results_.add(result, frame, [](const KdResult& own) { return own.t; });
}

// Hits, mean cost and the k-d core's counters per ray.
std::string KindOutputs<KdKind>::Tally::describe() const {
  const TriangleTally<KdCounters>& tally = results_.tally();
  const KdCounters& counters = tally.counters;
  const size_t rays = tally.rays;
  char text[256];
  std::snprintf(text, sizeof text,
                "kd          %.2f nodes, %.2f triangle tests, %.3f restarts, %.3f short-stack "
                "drops, %.1f bytes per ray\n",
                perRay(counters.kdNodesVisited, rays), perRay(counters.kdTriangleTests, rays),
                perRay(counters.kdRestarts, rays), perRay(counters.kdShortStackDrops, rays),
                perRay(counters.kdBytesFetched, rays));
  return tally.describeHits() + text;
}

}  // namespace rtu
