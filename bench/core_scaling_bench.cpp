// Cost follows the work, not the size of the simulated hardware (issue 9): the same 1280x720
// frame of menger at depth 6 on the cycle-accurate model with 1 to 1024 cores, ideal and cached
// memory. Target: 1024 cores within 1.5x the host time of 16 cores with ideal memory. Not a
// test: run it and record the figures in docs/performance.md.
//   build/bench/core_scaling_bench [scene]

#include <cstdio>
#include <string>
#include <vector>

#include "bench_frame.h"
#include "run/rtu_simulation.h"

using namespace rtu;

int main(int argc, char** argv) {
  const std::string scene = argc > 1 ? argv[1] : "menger";
  const BenchFrame frame = benchFrame(scene, 6);
  const std::vector<int> coreCounts = {1, 4, 16, 64, 256, 1024};
  std::printf("%s depth 6, %zu rays: simulation seconds by core count\n", scene.c_str(),
              frame.jobs.size());
  std::printf("%-7s %6s %12s %10s %12s\n", "memory", "cores", "cycles", "seconds", "vs 16 cores");
  bool met = true;
  for (const bool cached : {false, true}) {
    double at16 = 0.0;
    for (const int cores : coreCounts) {
      RtuConfig config;
      config.cores = cores;
      config.memory = cached ? MemoryConfig{} : RtuConfig::idealMemory();
      const RtuRun run = simulateRtu(frame.build.image.memory(), frame.jobs, config);
      const double seconds = run.statistics.hostSeconds;
      if (cores == 16) at16 = seconds;
      const double ratio = at16 > 0.0 ? seconds / at16 : 0.0;
      if (!cached && cores == 1024) met = ratio <= 1.5;
      std::printf("%-7s %6d %12llu %10.3f %12s\n", cached ? "cached" : "ideal", cores,
                  static_cast<unsigned long long>(run.totalCycles), seconds,
                  at16 > 0.0 ? std::to_string(ratio).substr(0, 4).c_str() : "-");
    }
  }
  std::printf("1024 cores within 1.5x of 16 (ideal): %s\n", met ? "met" : "MISSED");
  return met ? 0 : 1;
}
