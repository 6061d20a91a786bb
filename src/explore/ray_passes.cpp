#include "explore/ray_passes.h"

#include <stdexcept>

#include "explore/kind_scene.h"
#include "kind_explore_plugins.h"
#include "kinds/core_result.h"
#include "run/analytic_run.h"
#include "run/model_run.h"
#include "run/statistics_window.h"

namespace rtu {

namespace {

// Whether each result met something (an any-hit ray: occluded), from `first` on.
std::vector<bool> hitsOf(const std::vector<CoreKindResult>& results, size_t first, size_t count) {
  std::vector<bool> hits;
  hits.reserve(count);
  for (size_t i = first; i < first + count; ++i)
    hits.push_back(
        CoreKinds::visitResult(results[i], [](auto, const auto& own) { return own.hit; }));
  return hits;
}

// The passes' rays after the primary ones, spawned from the kind's golden hits of the frame.
std::vector<PassRun> spawnPasses(const PassSource& source, const RunConfig& settings,
                                 const std::vector<RayType>& passes) {
  RayWorkloadSpec spec = passSpec(settings);
  spec.secondary.selfOffset = source.selfOffset;
  spec.secondary.gridOffset = source.gridOffset;
  std::vector<PassRun> runs;
  for (size_t i = 1; i < passes.size(); ++i) {
    spec.secondary.type = passes[i];
    PassRun pass;
    pass.type = passes[i];
    pass.raysPerHit = spec.secondary.raysPerHit();
    pass.rays = spawnRayWorkload(source.hits, source.box, settings.camera.pixelCount(),
                                 source.modelAddress, spec)
                    .rays;
    runs.push_back(std::move(pass));
  }
  return runs;
}

}  // namespace

const StatisticGroup<FramePass>& FramePass::declaration() {
  using P = FramePass;
  static const StatisticGroup<FramePass> group =
      StatisticGroup<FramePass>("a pass of a frame")
          .derived(Statistic("rays", "rays", "the pass's rays"),
                   [](const P& p) { return p.statistics.rays; })
          .derived(Statistic("total_cycles", "cycles",
                             "the cycles of the pass's window of the frame's run"),
                   [](const P& p) { return p.statistics.totalCycles; })
          .derived(Statistic("cycles_per_ray", "cycles", "total_cycles / rays"),
                   [](const P& p) { return p.statistics.cyclesPerRay(); })
          .derived(Statistic("dram_utilisation", "",
                             "share of the pass's cycles the DRAM's data bus transfers"),
                   [](const P& p) { return p.statistics.utilisation().dramBandwidth; })
          .derived(Statistic("limit", "",
                             "the pass's limiting resource (docs/exploration.md, §2), or none"),
                   [](const P& p) { return p.statistics.limit(); });
  return group;
}

RayWorkloadSpec passSpec(const RunConfig& settings) {
  RayWorkloadSpec spec = settings.workload;
  spec.secondary.validate();
  return spec;
}

PassSource framePassSource(const FrameScene& scene, const RunConfig& settings) {
  if (scene.core == kRaypipeSceneCore)
    throw std::invalid_argument("secondary passes run on a core kind, not the ray pipe");
  return withCoreKind(scene.core, [&](auto kind) {
    return KindScene<decltype(kind)>::passSource(scene, settings);
  });
}

FramePassesRun runFramePasses(const FrameScene& scene, const RunConfig& settings,
                              const std::vector<RayType>& passes,
                              const std::optional<RtuStatistics>& primary) {
  const PassSource source = framePassSource(scene, settings);
  const WordMemory memory(source.words);
  FramePassesRun frame;
  frame.passes = spawnPasses(source, settings, passes);
  if (settings.model == ModelKind::Golden) {
    for (PassRun& pass : frame.passes) {
      const std::vector<HostRecord> records(pass.rays.begin(), pass.rays.end());
      pass.hits = hitsOf(traceGolden(memory, records, settings.rtu), 0, records.size());
    }
    return frame;
  }
  if (!primary) throw std::logic_error("runFramePasses: a timed model's primary run missing");
  // The job stream: the primary records, then each pass's rays; run up to each pass's end.
  std::vector<HostRecord> records = frameRecords(scene, settings);
  const size_t primaryRays = records.size();
  RtuStatistics before = *primary;
  RtuRun run;
  for (PassRun& pass : frame.passes) {
    records.insert(records.end(), pass.rays.begin(), pass.rays.end());
    run = runModel(settings.model, memory, records, settings.rtu);
    if (run.statistics.totalCycles < before.totalCycles)
      throw std::logic_error("a frame's run ended before the run of its first passes");
    pass.statistics = statisticsAfter(run.statistics, before, pass.rays.size(),
                                      run.statistics.totalCycles - before.totalCycles);
    before = run.statistics;
  }
  frame.frame = run.statistics;
  const std::vector<CoreKindResult> results = resultsInJobOrder(run);
  size_t first = primaryRays;
  for (PassRun& pass : frame.passes) {
    pass.hits = hitsOf(results, first, pass.rays.size());
    first += pass.rays.size();
  }
  return frame;
}

std::vector<double> openShare(const PassRun& pass, size_t pixels) {
  std::vector<double> open(pixels, 1.0);
  if (pass.type == RayType::Random) return open;
  std::vector<uint32_t> rays(pixels, 0), misses(pixels, 0);
  for (size_t i = 0; i < pass.rays.size(); ++i) {
    const size_t pixel = pass.rays[i].id / pass.raysPerHit;
    if (pixel >= pixels) throw std::logic_error("a pass's ray id beyond the frame");
    ++rays[pixel];
    misses[pixel] += !pass.hits[i];
  }
  for (size_t p = 0; p < pixels; ++p)
    if (rays[p] > 0 || pass.type == RayType::Shadow)
      open[p] = static_cast<double>(misses[p]) / pass.raysPerHit;
  return open;
}

}  // namespace rtu
