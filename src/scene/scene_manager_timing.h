#pragma once
// The scene manager's timing settings and the statistics of a run through it, shared by the
// cycle-accurate module (src/sim/ca/scene_manager_module.h) and its per-cycle reference
// (src/reference/scene_manager_cycles.h). The cycle rules are in docs/cycle-semantics.md.

#include <cstdint>
#include <map>

#include "base/statistics.h"
#include "scene/scene_manager.h"

namespace rtu {

struct SceneManagerConfig {
  int raysInFlight = 32;
  int jobsOutstanding = 32;
  int latency = 2;  // cycles from taking a ray to its first job
  SceneManagerOptions options;

  // Throws std::invalid_argument naming the setting.
  void validate() const;
};

struct SceneManagerStatistics {
  uint64_t rays = 0;
  uint64_t jobs = 0;
  uint64_t culled = 0;                      // instances whose sphere a ray missed
  uint64_t earlyTerminations = 0;           // rays that ended with instances left to trace
  uint64_t skipped = 0;                     // instances those rays did not trace
  std::map<uint64_t, uint64_t> jobsPerRay;  // jobs -> rays

  bool operator==(const SceneManagerStatistics& other) const {
    return rays == other.rays && jobs == other.jobs && culled == other.culled &&
           earlyTerminations == other.earlyTerminations && skipped == other.skipped &&
           jobsPerRay == other.jobsPerRay;
  }
  static const StatisticGroup<SceneManagerStatistics>& declaration();
};

}  // namespace rtu
