#include "explore/ray_passes.h"

#include <optional>
#include <stdexcept>

#include "explore/kind_scene.h"
#include "kind_explore_plugins.h"
#include "kinds/core_result.h"
#include "run/analytic_run.h"
#include "run/model_run.h"
#include "run/statistics_window.h"

namespace rtu {

namespace {

// Whether a result met something (an any-hit ray: occluded).
bool metSomething(const CoreKindResult& result) {
  return CoreKinds::visitResult(result, [](auto, const auto& own) { return own.hit; });
}

// The first `count` records of the frame's job stream, made as the run asks for them: the
// primary records, then each pass's rays in pass order.
RecordSource streamPrefix(const RecordSource& primaries, const std::vector<PassRun>& passes,
                          uint64_t count) {
  std::optional<HostRecord> sample;
  if (primaries.size() > 0) sample = primaries[0];
  for (const PassRun& pass : passes)
    if (!sample && !pass.rays.empty()) sample = pass.rays.front();
  if (!sample) throw std::logic_error("a frame's job stream without records");
  return RecordSource(
      count,
      [&primaries, &passes](uint64_t index) -> HostRecord {
        if (index < primaries.size()) return primaries[index];
        index -= primaries.size();
        for (const PassRun& pass : passes) {
          if (index < pass.rays.size()) return pass.rays[index];
          index -= pass.rays.size();
        }
        throw std::logic_error("a record beyond the frame's passes");
      },
      *sample);
}

// Marks each pass ray's hit as its result leaves a run of the stream (or of the passes alone,
// `primaryRays` 0); results are the same in every run, so a later run marks them again equally.
ResultTaker markHits(uint64_t primaryRays, std::vector<PassRun>& passes) {
  return [primaryRays, &passes](uint64_t job, const CoreKindResult& result) {
    if (job < primaryRays) return;
    job -= primaryRays;
    for (PassRun& pass : passes) {
      if (job < pass.hits.size()) {
        pass.hits[job] = metSomething(result);
        return;
      }
      job -= pass.hits.size();
    }
    throw std::logic_error("a result beyond the frame's passes");
  };
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

double passRays(const RunConfig& settings, size_t pixels) {
  RayWorkloadSpec spec = settings.workload;
  const std::vector<RayType> passes = parseRayPasses(settings.rayPasses, "--passes");
  double rays = 0;
  for (size_t i = 1; i < passes.size(); ++i) {
    spec.secondary.type = passes[i];
    rays += passes[i] == RayType::Random
                ? static_cast<double>(spec.randomRays == 0 ? pixels : spec.randomRays)
                : static_cast<double>(pixels) * spec.secondary.raysPerHit();
  }
  return rays;
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
  for (PassRun& pass : frame.passes) pass.hits.assign(pass.rays.size(), false);
  const ResultTaker take = markHits(0, frame.passes);
  if (settings.model == ModelKind::Golden) {
    const std::vector<HostRecord> noPrimaries;
    const RecordSource none(noPrimaries);
    uint64_t rays = 0;
    for (const PassRun& pass : frame.passes) rays += pass.rays.size();
    if (rays > 0) traceGolden(memory, streamPrefix(none, frame.passes, rays), settings.rtu, take);
    return frame;
  }
  if (!primary) throw std::logic_error("runFramePasses: a timed model's primary run missing");
  // The job stream: the primary records, then each pass's rays; run up to each pass's end. Records
  // are made as the run asks and results taken as they leave: nothing per ray of the frame is
  // held but the passes' rays and hits.
  const RecordSource primaries = frameRecordSource(scene, settings);
  const ResultTaker takeAfterPrimaries = markHits(primaries.size(), frame.passes);
  RtuStatistics before = *primary;
  uint64_t end = primaries.size();
  for (PassRun& pass : frame.passes) {
    end += pass.rays.size();
    const RtuRun run = runFrame(settings.model, memory, streamPrefix(primaries, frame.passes, end),
                                settings.rtu, takeAfterPrimaries);
    if (run.statistics.totalCycles < before.totalCycles)
      throw std::logic_error("a frame's run ended before the run of its first passes");
    pass.statistics = statisticsAfter(run.statistics, before, pass.rays.size(),
                                      run.statistics.totalCycles - before.totalCycles);
    before = run.statistics;
  }
  frame.frame = before;
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
