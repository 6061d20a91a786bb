#pragma once
// What a simulated run measured: the readable report and the JSON of `--stats`. Every statistic
// is declared once (declaration(), base/statistics.h): the JSON, the report's lines for flagged
// rays, sums over parts and windows (statistics_window.h) and `rtusim stats --list` come from it.

#include <cstdint>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/statistics.h"
#include "kinds/core_statistics.h"
#include "kinds/registry.h"
#include "scene/scene_manager_timing.h"
#include "sim/memory/l2_cache_timing.h"
#include "sim/rtu_config.h"

namespace rtu {

class RtuTop;

struct RtuStatistics {
  uint64_t rays = 0;
  uint64_t totalCycles = 0;
  double clockMhz = 100.0;
  int cores = 0;
  std::string scheduler;
  std::vector<CoreStatistics> coreTimes;
  uint64_t jobManagerStallCycles = 0;
  std::map<uint64_t, uint64_t> waitHistogram;
  uint64_t maxWait = 0, maxWaitWithReadyCore = 0;
  uint64_t resultBuffersMaxFull = 0;
  uint64_t reorderMaxOccupancy = 0;
  std::optional<SceneManagerStatistics> scene;  // a run through the scene manager
  bool idealMemory = true;
  int warmFrames = 0;  // frames run through the caches before this one (warm_frames)
  std::vector<CacheStats> l1;
  L2Stats l2;
  uint64_t belowResolution = 0;  // rays flagged for nodes narrower than a step (result flag 4)
  uint64_t totalCost = 0, maxCost = 0;  // traversal states per ray, as the golden model counts
  uint64_t totalBlocked = 0, maxBlocked = 0;  // cycles BLOCKED on memory per ray, beside the cost
  double hostInBytesPerCycle = 0.0, hostOutBytesPerCycle = 0.0;  // 0: a record a cycle
  uint64_t hostOutRecordBytes = kHostRecordBytes;                // 48 for formats over 32 bits
  double hostSeconds = 0.0;
  std::string model = "systemc";  // what answered: the SystemC simulation or the "recurrence"
  // The cores' kind (RtuConfig::core): its counters, and no other kind's, are written. Not a
  // statistic of its own: the configuration beside the statistics names it.
  std::string core = SvoKind::kName;

  // The settings of a run of `config` (clock, cores, policy, host links), nothing counted yet.
  static RtuStatistics of(const RtuConfig& config);
  // Counts one result: its cost, cycles blocked on memory and flags.
  void count(const CoreKindResult& result, uint64_t blocked);
  // Adds what count() counted in `other` (results counted as they left a run that keeps none).
  void addCounts(const RtuStatistics& other);

  // Shares of the cores' time (cores x total cycles); they add up to 1.
  struct CoreTimeShares {
    double busy = 0, blocked = 0, handover = 0, idle = 0, unitStall = 0;
    static const StatisticGroup<CoreTimeShares>& declaration();
  };
  CoreTimeShares coreTimeShares() const;
  // Utilisation of each resource that can bound the frame rate, and the one that does (the
  // first of the highest, when it reaches kSaturated); the rule is in docs/exploration.md, §2.
  struct Utilisation {
    double cores = 0, memoryLatency = 0, dramBandwidth = 0, l2Port = 0, hostIn = 0, hostOut = 0,
           jobManager = 0;
    static const StatisticGroup<Utilisation>& declaration();
  };
  static constexpr double kSaturated = 0.8;
  Utilisation utilisation() const;
  // The highest utilisation's resource, or "none" below kSaturated.
  std::string limit() const;
  double limitUtilisation() const;  // the highest utilisation, saturated or not
  // "limited by cores (96.1 %)", "limited by cores (96.1 %; memory_latency 94.0 % close
  // behind)" or "nothing saturated (highest: cores 45.2 %)".
  std::string describeLimit() const;
  // How the run's caches started: "cold", or "warm after N frames" (warm_frames).
  std::string cacheStart() const;
  double frameMilliseconds() const;

  double cyclesPerRay() const;
  double raysPerSecond() const;    // at the simulated clock
  double framesPerSecond() const;  // the run's rays as one frame
  double dramBytesPerCycle() const;
  double simulatedRaysPerHostSecond() const;
  uint64_t idleCycles(const CoreStatistics& core) const;
  CoreStatistics allCores() const;  // the cores' times summed
  CacheStats allL1() const;         // the L1s' counts summed
  // The thesis' worst-case wait of eq. 6.7 for the policy, or -1 when it depends on the jobs (rr).
  int64_t waitBound() const;

  nlohmann::ordered_json toJson() const;
  void writeReport(std::ostream& out) const;

  static const StatisticGroup<RtuStatistics>& declaration();
};

RtuStatistics collectStatistics(const RtuTop& top, const RtuConfig& config, uint64_t totalCycles);

}  // namespace rtu
