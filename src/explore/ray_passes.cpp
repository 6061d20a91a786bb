#include "explore/ray_passes.h"

#include <cmath>
#include <stdexcept>

#include "kinds/core_result.h"
#include "run/analytic_run.h"
#include "run/model_run.h"

namespace rtu {

namespace {

PassRun runPass(const WordMemory& memory, const RunConfig& settings, PassRun pass) {
  const std::vector<HostRecord> records(pass.rays.begin(), pass.rays.end());
  if (settings.model == ModelKind::Golden) {
    pass.results = svoResults(traceGolden(memory, records, settings.rtu));
    return pass;
  }
  pass.run = runModel(settings.model, memory, records, settings.rtu);
  pass.results = svoResults(resultsInJobOrder(*pass.run));
  return pass;
}

}  // namespace

const StatisticGroup<FramePass>& FramePass::declaration() {
  using P = FramePass;
  static const StatisticGroup<FramePass> group =
      StatisticGroup<FramePass>("a pass of a frame")
          .derived(Statistic("rays", "rays", "the pass's rays"),
                   [](const P& p) { return p.statistics.rays; })
          .derived(Statistic("total_cycles", "cycles", "the pass's run, its cycles"),
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
  const GoldenConfig& golden = settings.rtu.coreConfig<SvoKind>();
  golden.validate();
  spec.secondary.selfOffset = std::ldexp(16.0, -golden.format.fractionBits);
  spec.secondary.validate();
  return spec;
}

std::vector<PassRun> runSecondaryPasses(const FrameScene& scene, const RunConfig& settings,
                                        const std::vector<RayType>& passes) {
  const RayWorkloadSpec spec = passSpec(settings);
  if (scene.core != SvoKind::kName)
    throw std::invalid_argument("secondary passes run on the svo core only, not " + scene.core);
  std::vector<uint32_t> words = scene.words;
  const ModelHeader header = makeModelHeader(ModelPlacement{}, scene.entry);
  const ModelHeaderWords headerWords = encodeModelHeader(header);
  const uint32_t address = static_cast<uint32_t>(words.size());
  words.insert(words.end(), headerWords.begin(), headerWords.end());
  const WordMemory memory(words);
  std::vector<PassRun> runs;
  for (size_t i = 1; i < passes.size(); ++i) {
    RayWorkloadSpec passSpec = spec;
    passSpec.secondary.type = passes[i];
    PassRun pass;
    pass.type = passes[i];
    pass.raysPerHit = passSpec.secondary.raysPerHit();
    pass.rays = makeRayWorkload(memory, address, settings.camera,
                                settings.rtu.coreConfig<SvoKind>(), passSpec)
                    .rays;
    runs.push_back(runPass(memory, settings, std::move(pass)));
  }
  return runs;
}

std::vector<double> openShare(const PassRun& pass, size_t pixels) {
  std::vector<double> open(pixels, 1.0);
  if (pass.type == RayType::Random) return open;
  std::vector<uint32_t> rays(pixels, 0), misses(pixels, 0);
  for (size_t i = 0; i < pass.rays.size(); ++i) {
    const size_t pixel = pass.rays[i].id / pass.raysPerHit;
    if (pixel >= pixels) throw std::logic_error("a pass's ray id beyond the frame");
    ++rays[pixel];
    misses[pixel] += !pass.results[i].hit;
  }
  for (size_t p = 0; p < pixels; ++p)
    if (rays[p] > 0 || pass.type == RayType::Shadow)
      open[p] = static_cast<double>(misses[p]) / pass.raysPerHit;
  return open;
}

}  // namespace rtu
