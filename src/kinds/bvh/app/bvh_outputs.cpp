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

KindOutputs<BvhKind<>>::Tally::Tally(const RunConfig&, const FrameScene& scene) : results_(scene) {}

void KindOutputs<BvhKind<>>::Tally::add(const CoreKindResult& result, PixelSink* frame) {
  results_.add(result, frame, [](const BvhResult& own) { return own.t; });
}

// Hits, mean cost and the BVH's counters per ray.
std::string KindOutputs<BvhKind<>>::Tally::describe() const {
  const TriangleTally<BvhCounters>& tally = results_.tally();
  const BvhCounters& counters = tally.counters;
  const size_t rays = tally.rays;
  char text[256];
  std::snprintf(text, sizeof text,
                "bvh         %.2f nodes, %.2f box tests, %.2f triangle tests, %.1f bytes per "
                "ray; %llu rays lost stack entries\n",
                perRay(counters.bvhNodesVisited, rays), perRay(counters.bvhBoxTests, rays),
                perRay(counters.bvhTriangleTests, rays), perRay(counters.bvhBytesFetched, rays),
                static_cast<unsigned long long>(counters.bvhStackOverflows));
  return tally.describeHits() + text;
}

}  // namespace rtu
