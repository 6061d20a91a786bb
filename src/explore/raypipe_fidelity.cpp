#include "explore/raypipe_fidelity.h"

#include <chrono>
#include <cstring>

#include "explore/raypipe_frame.h"
#include "raypipe/raypipe_golden.h"

namespace rtu {
namespace {

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameCounts(const KdRayCounts& a, const KdRayCounts& b) {
  return a.nodes == b.nodes && a.leaves == b.leaves && a.triangleTests == b.triangleTests &&
         a.restarts == b.restarts && a.boxMisses == b.boxMisses && a.pushes == b.pushes &&
         a.dropped == b.dropped;
}

// A timed ray's result is the golden traversal's, bit for bit, with its counts.
bool sameResult(const RaypipeCycleResult& r, const RaypipePixel& p) {
  return r.pixelId == p.pixel.pixelId && r.hit == p.hit && r.boxMiss == p.boxMiss &&
         r.primitive == p.primitive && sameBits(r.t, p.t) && sameBits(r.u, p.u) &&
         sameBits(r.v, p.v) && sameCounts(r.counts, p.counts);
}

bool resultsEqual(const RaypipeCycleRun& run, const RaypipeGoldenFrame& golden) {
  if (run.results.size() != golden.pixels.size()) return false;
  for (size_t i = 0; i < run.results.size(); ++i)
    if (!sameResult(run.results[i], golden.pixels[i])) return false;
  return true;
}

// Each ray's cycles in the pipe, in issue order: from the PRG's accept to its exit.
std::vector<double> rayCycles(const RaypipeCycleRun& run) {
  std::vector<double> cycles;
  cycles.reserve(run.results.size());
  for (const RaypipeCycleResult& r : run.results)
    cycles.push_back(static_cast<double>(r.exitCycle - r.issueCycle));
  return cycles;
}

ModeFidelity mode(const std::string& name, double seconds, size_t rays, double referenceSeconds) {
  ModeFidelity m;
  m.mode = name;
  m.hostSeconds = seconds;
  m.raysPerHostSecond = seconds > 0 ? static_cast<double>(rays) / seconds : 0.0;
  m.speedUp = seconds > 0 ? referenceSeconds / seconds : 0.0;
  return m;
}

ModeFidelity timedMode(const std::string& name, const RaypipeCycleRun& run,
                       const RaypipeCycleRun& reference, const RaypipeGoldenFrame& golden) {
  ModeFidelity m = mode(name, run.hostSeconds, run.results.size(), reference.hostSeconds);
  m.totalCycles = static_cast<double>(run.frameCycles);
  m.totalCyclesError =
      static_cast<double>(run.frameCycles) / static_cast<double>(reference.frameCycles) - 1;
  const auto [mean, p99] = perRayErrors(rayCycles(run), rayCycles(reference));
  m.perRayErrorMean = mean;
  m.perRayErrorP99 = p99;
  m.resultsEqualGolden = resultsEqual(run, golden);
  return m;
}

}  // namespace

std::vector<ModeFidelity> measureRaypipeFidelity(const RunConfig& settings,
                                                 const FrameScene& scene) {
  const std::vector<PrimaryRay> rays = raypipeFrameRays(settings);
  const RaypipeCycleRun reference = runRaypipeReferenceFrame(settings.raypipe, scene.words, rays);
  const RaypipeCycleRun timed = runRaypipeFrame(settings.raypipe, scene.words, rays);
  const auto start = std::chrono::steady_clock::now();
  const RaypipeGoldenFrame golden = runGoldenFrame(scene.words, rays, settings.raypipe);
  const double goldenSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ModeFidelity untimed = mode("golden", goldenSeconds, rays.size(), reference.hostSeconds);
  untimed.resultsEqualGolden = true;
  return {timedMode("reference", reference, reference, golden),
          timedMode("raypipe", timed, reference, golden), untimed};
}

bool raypipeModesAgree(const std::vector<ModeFidelity>& modes) {
  for (const ModeFidelity& m : modes)
    if ((m.totalCyclesError && *m.totalCyclesError != 0) ||
        (m.perRayErrorMean && *m.perRayErrorMean != 0) || !m.resultsEqualGolden.value_or(true))
      return false;
  return true;
}

}  // namespace rtu
