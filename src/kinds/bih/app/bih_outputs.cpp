#include "kinds/bih/app/bih_outputs.h"

#include <cstdio>

#include "app/triangle_render.h"
#include "kinds/bih/bih_config.h"
#include "kinds/bih/bih_counters.h"
#include "kinds/core_result.h"

namespace rtu {

std::string KindOutputs<BihKind<>>::core(const RunConfig& settings) {
  const BihConfig& core = settings.rtu.coreConfig<BihKind<>>();
  return "bih core, " + bihFormatName(core.format) + " fixed-point formats, triangle unit " +
         std::to_string(core.cycles.triangleLatency) + " cycles";
}

// Hits, mean cost and the BIH's counters per ray, and the triangle unit's fill rate: its tests'
// issue cycles (the unit's interval each) over the rays' cycles (their costs).
std::string KindOutputs<BihKind<>>::results(const RunConfig& settings,
                                            const std::vector<CoreKindResult>& kindResults) {
  const std::vector<BihResult> results = resultsOfKind<BihKind<>>(kindResults);
  const uint32_t unitInterval = settings.rtu.coreConfig<BihKind<>>().cycles.triangleInterval;
  const auto counters = countersOf<BihCounters>(results);
  const size_t rays = results.size();
  uint64_t cycles = 0;
  for (const BihResult& result : results) cycles += result.cost;
  char text[512];
  std::snprintf(text, sizeof text,
                "bih         %.2f nodes, %.2f triangle tests, %.1f bytes per ray; %llu rays lost "
                "stack entries, %llu divider errors\n"
                "unit fill   %.1f %% (triangle tests x interval over the rays' cycles: seed 004 "
                "measured about 40 %%)\n",
                perRay(counters.bihNodesVisited, rays), perRay(counters.bihTriangleTests, rays),
                perRay(counters.bihBytesFetched, rays),
                static_cast<unsigned long long>(counters.bihStackOverflows),
                static_cast<unsigned long long>(counters.bihDividerErrors),
                100.0 * perRay(counters.bihTriangleTests * unitInterval, cycles));
  return describeTriangleHits(results) + text;
}

// A BIH result's t is in grid units: its pixel takes the world `distance`.
RenderedFrame KindOutputs<BihKind<>>::pixels(const RunConfig& settings, const FrameScene& scene,
                                             const std::vector<CoreKindResult>& results) {
  return triangleFrame(settings.camera, scene, resultsOfKind<BihKind<>>(results),
                       [](const BihResult& result) { return result.distance; });
}

}  // namespace rtu
