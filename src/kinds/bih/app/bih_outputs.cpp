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

KindOutputs<BihKind<>>::Tally::Tally(const RunConfig& settings, const FrameScene& scene)
    : unitInterval_(settings.rtu.coreConfig<BihKind<>>().cycles.triangleInterval),
      results_(scene) {}

// A BIH result's t is in grid units: its pixel takes the world `distance`.
void KindOutputs<BihKind<>>::Tally::add(const CoreKindResult& result, PixelSink* frame) {
  results_.add(result, frame, [](const BihResult& own) { return own.distance; });
}

// Hits, mean cost and the BIH's counters per ray, and the triangle unit's fill rate: its tests'
// issue cycles (the unit's interval each) over the rays' cycles (their costs).
std::string KindOutputs<BihKind<>>::Tally::describe() const {
  const TriangleTally<BihCounters>& tally = results_.tally();
  const BihCounters& counters = tally.counters;
  const size_t rays = tally.rays;
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
                100.0 * perRay(counters.bihTriangleTests * unitInterval_, tally.cost));
  return tally.describeHits() + text;
}

}  // namespace rtu
