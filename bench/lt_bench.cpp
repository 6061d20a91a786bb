// Loosely-timed model (issue 10 §2) against the cycle-accurate model and the golden model:
// 1280x720 primary rays of the default camera on depth-8 procedural scenes, 16 cores, cfa, with
// the `cached` preset's memory and with ideal memory. Per scene and quantum: host seconds, rays
// per host second as a share of the golden model's, total cycles and their error against the
// cycle-accurate model, L1/L2 hit rates. Targets (issue 10): LT at least a quarter of golden's
// rays per host second; total cycles within 5 % (cached) and 2 % (ideal). Not a test: run it and
// record the figures in docs/fidelity.md. Golden and LT each run --repeat times (default 3) and
// their fastest run counts, so that a busy moment of the machine weighs on neither side alone.
// The comparison with golden is in the thread's CPU seconds ("cpu s"), which other processes on
// a shared machine change far less than the wall seconds ("seconds", the model's host time).
//   build/bench/lt_bench [--quanta 100,1000,10000] [--repeat N] [scene ...]

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench_frame.h"
#include "config/configuration.h"
#include "kinds/svo/golden_model.h"
#include "run/lt_simulation.h"
#include "run/rtu_simulation.h"

using namespace rtu;

namespace {

double threadCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// The fastest of `repeat` runs of `run` in CPU seconds, and that run's result.
template <typename Run>
auto fastestOf(int repeat, const Run& run) {
  double best = 1e300;
  decltype(run()) kept{};
  for (int r = 0; r < repeat; ++r) {
    const double start = threadCpuSeconds();
    auto result = run();
    const double seconds = threadCpuSeconds() - start;
    if (seconds < best) {
      best = seconds;
      kept = std::move(result);
    }
  }
  return std::make_pair(best, std::move(kept));
}

std::vector<uint64_t> parseQuanta(const std::string& list) {
  std::vector<uint64_t> quanta;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) quanta.push_back(std::stoull(item));
  return quanta;
}

struct Memory {
  const char* name;
  RtuConfig config;
  double bound;  // the total-cycle error bound
};

}  // namespace

int main(int argc, char** argv) {
  std::vector<uint64_t> quanta{100, 1000, 10000};
  int repeat = 3;
  std::vector<std::string> names;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--quanta" && i + 1 < argc)
      quanta = parseQuanta(argv[++i]);
    else if (arg == "--repeat" && i + 1 < argc)
      repeat = std::max(1, std::atoi(argv[++i]));
    else
      names.push_back(arg);
  }
  if (names.empty()) names = proceduralSceneNames();
  Configuration preset;
  preset.applyPreset("cached");
  const RtuConfig cached = preset.values().rtu;
  RtuConfig ideal = cached;
  ideal.memory = RtuConfig::idealMemory();
  const std::vector<Memory> memories{{"cached", cached, 0.05}, {"ideal", ideal, 0.02}};

  std::printf(
      "LT against cycle-accurate, 1280x720, depth-8 scenes, 16 cores, cfa, cached preset\n");
  std::printf("%-8s %-6s %-9s %8s %8s %9s %9s %14s %9s %7s %7s %s\n", "scene", "memory", "model",
              "seconds", "cpu s", "Mrays/s", "x golden", "total cycles", "error", "L1 hit",
              "L2 hit", "targets");
  bool allMet = true;
  for (const std::string& name : names) {
    const BenchFrame frame = benchFrame(name);
    const WordMemory memory = frame.build.image.memory();
    const std::vector<HostRecord> records(frame.jobs.begin(), frame.jobs.end());
    const double rays = static_cast<double>(frame.jobs.size());
    const double goldenCpu =
        fastestOf(repeat, [&] {
          return GoldenModel(memory, cached.coreConfig<SvoKind>()).traceAll(frame.jobs);
        }).first;
    for (const Memory& mem : memories) {
      const auto [caCpu, ca] =
          fastestOf(1, [&] { return simulateRtu(memory, frame.jobs, mem.config); });
      const auto row = [&](const char* model, double cpu, const RtuRun& run,
                           const std::string& targets) {
        const RtuStatistics& s = run.statistics;
        const double error =
            static_cast<double>(run.totalCycles) / static_cast<double>(ca.totalCycles) - 1;
        std::printf("%-8s %-6s %-9s %8.3f %8.3f %9.2f %9.2f %14llu %+8.2f%% %7.4f %7.4f %s\n",
                    name.c_str(), mem.name, model, s.hostSeconds, cpu, rays / cpu / 1e6,
                    goldenCpu / cpu, static_cast<unsigned long long>(run.totalCycles), 100 * error,
                    hitRate(s.allL1()), hitRate(s.l2.cache), targets.c_str());
      };
      row("ca", caCpu, ca, "");
      for (uint64_t quantum : quanta) {
        RtuConfig config = mem.config;
        config.ltQuantum = quantum;
        const auto [ltCpu, lt] =
            fastestOf(repeat, [&] { return runLooselyTimed(memory, records, config); });
        const double error =
            std::abs(static_cast<double>(lt.totalCycles) / static_cast<double>(ca.totalCycles) - 1);
        const bool fast = goldenCpu / ltCpu >= 0.25;
        const bool close = error <= mem.bound;
        allMet &= fast && close;
        const std::string label = "lt q" + std::to_string(quantum);
        row(label.c_str(), ltCpu, lt,
            std::string(fast ? "speed met" : "speed MISSED") + ", " +
                (close ? "error met" : "error MISSED"));
      }
    }
    std::printf("%-8s golden %.2f M rays/s (cpu)\n", name.c_str(), rays / goldenCpu / 1e6);
  }
  return allMet ? 0 : 1;
}
