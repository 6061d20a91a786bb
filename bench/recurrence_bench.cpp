// The exact answer without simulating (issue 9): the same 1280x720 frame of a procedural scene
// at depth 6 timed by the recurrence (src/rtu/rtu_recurrence.h) and by the SystemC model, with
// the golden traversal and the recurrence timed apart. Not a test: run it and record the figures
// in docs/performance.md.
//   build/bench/recurrence_bench [scene]

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_frame.h"
#include "kinds/svo/golden_model.h"
#include "rtu/rtu_recurrence.h"
#include "run/analytic_run.h"

using namespace rtu;

namespace {

template <typename Work>
double secondsOf(Work&& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  const std::string scene = argc > 1 ? argv[1] : "menger";
  const BenchFrame frame = benchFrame(scene, 6);
  const WordMemory memory = frame.build.image.memory();
  std::vector<JobTiming> timing;
  const double golden = secondsOf([&] {
    GoldenModel model(memory, GoldenConfig{});
    for (const TValueRecord& job : frame.jobs)
      timing.push_back(JobTiming{model.trace(job).cost, 6, 0});
  });
  std::printf("%s depth 6, %zu rays; golden traversal %.3f s\n", scene.c_str(), frame.jobs.size(),
              golden);
  std::printf("%6s %12s %11s %11s %11s %9s\n", "cores", "cycles", "recurrence", "analytic",
              "systemc", "equal");
  bool equal = true;
  for (const int cores : {1, 16, 1024}) {
    RecurrenceConfig recurrenceConfig;
    recurrenceConfig.cores = cores;
    RecurrenceRun recurrence;
    const double alone = secondsOf([&] { recurrence = runRecurrence(timing, recurrenceConfig); });
    RtuConfig config;
    config.cores = cores;
    RtuRun analytic;
    const double whole = secondsOf([&] { analytic = runAnalytic(memory, frame.jobs, config); });
    const RtuRun simulated = simulateRtu(memory, frame.jobs, config);
    const bool same = analytic.totalCycles == simulated.totalCycles &&
                      analytic.arrivalCycles == simulated.arrivalCycles &&
                      recurrence.totalCycles == simulated.totalCycles;
    equal = equal && same;
    std::printf("%6d %12llu %10.3fs %10.3fs %10.3fs %9s\n", cores,
                static_cast<unsigned long long>(simulated.totalCycles), alone, whole,
                simulated.statistics.hostSeconds, same ? "yes" : "NO");
  }
  return equal ? 0 : 1;
}
