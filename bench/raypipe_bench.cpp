// Seed 001's ray pipe (issue 29 §4): host seconds of the timed model (sim/raypipe/raypipe_timed.h)
// against the per-cycle reference (reference/raypipe_cycles.h) on R1's primary rays at a
// resolution level (default 5: 640x480) over the sphere-like mesh of 80 triangles the reference's
// "[.raypipe_figures]" test renders (R1's bunny is not in the repository). The two run alternately
// --repeat times (default 3), each run's host seconds (wall, and the thread's CPU seconds, which
// other processes on the shared machine change far less) printed and the fastest of each compared,
// so a busy moment of the shared machine weighs on neither side alone; the frame cycles must agree.
// Not a test: run it and record the figures in docs/performance.md, "Ray pipe".
// --rays-in-flight N gives the shader fewer ray ids (R1: 512), a pipe mostly idle, where the
// model's cost follows the rays and the reference's the cycles.
//   build/bench/raypipe_bench [--level 0-5] [--repeat N] [--rays-in-flight N]

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "raypipe_scenes.h"
#include "reference/raypipe_cycles.h"
#include "sim/raypipe/raypipe_timed.h"

using namespace rtu;

namespace {

double threadCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  int level = 5, repeat = 3;
  RaypipeConfig config;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--level")
      level = std::atoi(argv[i + 1]);
    else if (flag == "--repeat")
      repeat = std::atoi(argv[i + 1]);
    else if (flag == "--rays-in-flight")
      config.raysInFlight = std::atoi(argv[i + 1]);
  }
  const KdImage image = frameScene();
  const std::vector<RaypipeCycleRay> rays = prgRays(level);
  double bestTimed = 1e30, bestReference = 1e30, cpuTimed = 1e30, cpuReference = 1e30;
  for (int r = 0; r < repeat; ++r) {
    const double t0 = threadCpuSeconds();
    const RaypipeCycleRun timed = runRaypipeTimed(config, image, rays);
    const double t1 = threadCpuSeconds();
    const RaypipeCycleRun reference = runRaypipeCycles(config, image, rays);
    const double t2 = threadCpuSeconds();
    cpuTimed = std::min(cpuTimed, t1 - t0);
    cpuReference = std::min(cpuReference, t2 - t1);
    if (timed.frameCycles != reference.frameCycles) {
      std::fprintf(stderr, "frame cycles differ: timed %lld, reference %lld\n",
                   static_cast<long long>(timed.frameCycles),
                   static_cast<long long>(reference.frameCycles));
      return 1;
    }
    std::printf(
        "round %d: %dx%d, %zu rays, %lld cycles: timed %.3f s (cpu %.3f), reference %.3f s (cpu "
        "%.3f)\n",
        r + 1, 20 << level, 15 << level, rays.size(), static_cast<long long>(timed.frameCycles),
        timed.hostSeconds, t1 - t0, reference.hostSeconds, t2 - t1);
    bestTimed = std::min(bestTimed, timed.hostSeconds);
    bestReference = std::min(bestReference, reference.hostSeconds);
  }
  std::printf("fastest: timed %.3f s (cpu %.3f), reference %.3f s (cpu %.3f): %.1fx (cpu %.1fx)\n",
              bestTimed, cpuTimed, bestReference, cpuReference, bestReference / bestTimed,
              cpuReference / cpuTimed);
  return 0;
}
