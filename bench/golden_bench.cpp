// Golden model throughput: single thread, 1280x720 primary rays of the default camera on
// depth-8 procedural scenes. Not a test: run it and record the figures in docs/performance.md.
//   build/bench/golden_bench [scene ...]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_frame.h"
#include "kinds/svo/golden_model.h"
#include "kinds/svo/result_summary.h"

using namespace rtu;

namespace {

constexpr int kRepetitions = 3;
constexpr double kTargetRaysPerSecond = 5e6;

double bestSecondsToTrace(GoldenModel& model, const std::vector<TValueRecord>& jobs,
                          std::vector<TraversalResult>& results) {
  double best = 1e30;
  for (int i = 0; i < kRepetitions; ++i) {
    const auto start = std::chrono::steady_clock::now();
    results = model.traceAll(jobs);
    best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const Camera camera = benchCamera();
  std::printf("golden model, 1 thread, %dx%d primary rays, depth-8 scenes, best of %d\n",
              camera.width, camera.height, kRepetitions);
  std::printf("%-10s %10s %10s %12s %8s\n", "scene", "hits %", "mean cost", "M rays/s", "target");
  bool allMet = true;
  for (const std::string& name : benchScenes(argc, argv)) {
    const BenchFrame frame = benchFrame(name);
    const SvoBuild& build = frame.build;
    const std::vector<TValueRecord>& jobs = frame.jobs;
    GoldenModel model(build.image.memory(), GoldenConfig{});
    std::vector<TraversalResult> results;
    const double seconds = bestSecondsToTrace(model, jobs, results);
    const ResultSummary summary = ResultSummary::of(results);
    const double raysPerSecond = jobs.size() / seconds;
    allMet &= raysPerSecond >= kTargetRaysPerSecond;
    std::printf("%-10s %10.1f %10.2f %12.2f %8s\n", name.c_str(), 100.0 * summary.hitShare(),
                summary.meanCost(), raysPerSecond / 1e6,
                raysPerSecond >= kTargetRaysPerSecond ? "met" : "MISSED");
  }
  return allMet ? 0 : 1;
}
