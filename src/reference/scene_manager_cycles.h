#pragma once
// A plain per-cycle model of the scene manager, written from its cycle rules
// (docs/cycle-semantics.md "Scene manager"), above the per-cycle RTL top level
// (src/reference/rtl_cycle_model.h): the reference the cycle-accurate module
// (src/sim/ca/scene_manager_module.h) is checked against, cycle for cycle. Speed is no concern.
//
// Every cycle it first takes the decisions of the cycle from the registers, in the rules' order
// (merge the result delivered in the cycle before, take a ray from the host, offer the oldest
// done ray to the host, offer a job to the job manager), then lets the RTU run the cycle with that
// offer, then updates every register with the cycle's handshakes, as the clock edge does.
//
// The host offers ray i from the cycle after ray i - 1 was taken (ray 0 from cycle 0) and is
// ready for a merged ray in every cycle. Below the manager the RTU is the RTL's: ideal memory,
// cyclic first-available scheduling, no reorder buffer.

#include <cstdint>
#include <vector>

#include "kinds/svo/ray_transform.h"
#include "reference/rtl_cycle_model.h"
#include "rtu/word_memory.h"
#include "scene/scene_manager.h"
#include "scene/scene_manager_timing.h"

namespace rtu {

struct SceneCyclesRun {
  // Per merged result, in the order the host received them:
  std::vector<uint64_t> rays;  // the ray's index in the input
  std::vector<CoreKindResult> results;
  std::vector<int> instances;  // the instance hit, -1 on a miss
  std::vector<uint64_t> arrivalCycles;
  std::vector<uint64_t> issueCycles;  // per job, in issue order: the cycle the job manager took it
  uint64_t totalCycles = 0;           // the cycle the host took the last ray, plus one
  SceneManagerStatistics statistics;
};

// Throws std::invalid_argument for an impossible configuration.
SceneCyclesRun runSceneCycles(const WordMemory& memory, const std::vector<RayRecord>& rays,
                              const std::vector<SceneInstance>& instances,
                              const SceneManagerConfig& scene, const RtlTopConfig& rtu);

}  // namespace rtu
