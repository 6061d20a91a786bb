// Cycle-accurate SystemC model throughput: simulated rays per host second for 1280x720 primary
// rays of the default camera on depth-8 procedural scenes with 16 cores, ideal memory and the
// default cached hierarchy; for scale, the naive per-cycle RTL transcription on the same frame.
// Not a test: run it and record the figures in docs/performance.md.
//   build/bench/rtu_bench [scene ...]

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_frame.h"
#include "reference/rtl_cycle_model.h"
#include "run/rtu_simulation.h"

using namespace rtu;

namespace {

struct Mode {
  const char* name;
  MemoryConfig memory;
  double target;
};

}  // namespace

int main(int argc, char** argv) {
  const Camera camera = benchCamera();
  const std::vector<Mode> modes = {{"ideal", RtuConfig::idealMemory(), 1e6},
                                   {"cached", MemoryConfig{}, 3e5}};
  std::printf("SystemC RTU model, 16 cores, cfa, %dx%d primary rays, depth-8 scenes\n",
              camera.width, camera.height);
  std::printf("%-10s %-7s %12s %10s %10s %12s %8s\n", "scene", "memory", "cycles", "cyc/ray",
              "seconds", "M rays/s", "target");
  bool allMet = true;
  for (const std::string& name : benchScenes(argc, argv)) {
    const BenchFrame frame = benchFrame(name);
    const SvoBuild& build = frame.build;
    const std::vector<TValueRecord>& jobs = frame.jobs;
    for (const Mode& mode : modes) {
      RtuConfig config;
      config.memory = mode.memory;
      const RtuRun run = simulateRtu(build.image.memory(), jobs, config);
      const RtuStatistics& s = run.statistics;
      const double raysPerSecond = s.simulatedRaysPerHostSecond();
      allMet &= raysPerSecond >= mode.target;
      std::printf("%-10s %-7s %12llu %10.2f %10.3f %12.3f %8s\n", name.c_str(), mode.name,
                  static_cast<unsigned long long>(run.totalCycles), s.cyclesPerRay(), s.hostSeconds,
                  raysPerSecond / 1e6, raysPerSecond >= mode.target ? "met" : "MISSED");
    }
    const auto start = std::chrono::steady_clock::now();
    const RtlTopRun rtl = runRtlTop(build.image.memory(), jobs, RtlTopConfig{});
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-10s %-7s %12llu %10.2f %10.3f %12.3f %8s\n", name.c_str(), "RTL ref",
                static_cast<unsigned long long>(rtl.totalCycles),
                static_cast<double>(rtl.totalCycles) / jobs.size(), seconds,
                jobs.size() / seconds / 1e6, "-");
  }
  return allMet ? 0 : 1;
}
