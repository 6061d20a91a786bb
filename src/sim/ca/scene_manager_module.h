#pragma once
// The scene manager (thesis 4.3.4, chapter 8), cycle-accurate: world-space rays from the host in,
// one job per instance the ray can hit out to the job manager (a ray record naming the
// instance's model header: the job manager's transform stage moves the ray into the model), the
// jobs' results back from the result manager (or the reorder buffer), and one merged result per
// ray (the nearest hit, the costs summed) out to the host. What it decides per ray is the golden
// scene manager's (src/scene/scene_manager.h: culling, front-to-back order, nearest hit, early
// termination); this module adds when.
//
// Cycle rules (docs/cycle-semantics.md "Scene manager"), all decided in cycle t from what
// happened in the cycles before t:
//   - results: a result the RTU delivers in cycle c is merged into its ray in c + 1;
//   - host out: the oldest ray with every job returned and nothing more to issue is offered to
//     the host from the cycle after its last result (its `latency` cycles after entry when
//     every instance is culled), one transfer per cycle, oldest first;
//   - host in: a ray offered from h is taken in the first cycle from h in which fewer than
//     `raysInFlight` rays are held (a ray leaves in the cycle after its transfer to the host);
//   - issue: from `latency` cycles after a ray entered (the sphere tests and the sort), its next
//     instance is offered to the job manager when no job of that ray is outstanding and fewer
//     than `jobsOutstanding` jobs are; oldest ray first, one offer at a time, the next from the
//     cycle after the previous transfer. A ray whose nearest hit so far lies before its next
//     sphere issues nothing more (early termination).
// One job per ray at a time keeps each ray's decisions exactly the golden manager's, so the
// image, the jobs per ray and the early terminations equal its; rays in flight are the
// parallelism. Jobs are numbered in issue order, the order they enter the job manager.
//
// The module decides cycle t at simulated time t (a wake-up per cycle with something to do):
// by then every transfer of the cycles before is decided (decision_pump.h).

#include <cstdint>
#include <deque>
#include <map>
#include <vector>

#include <systemc>

#include "kinds/core_result.h"
#include "scene/scene_manager.h"
#include "scene/scene_manager_timing.h"
#include "sim/ca/rtu_payloads.h"
#include "sim/kernel/cycle_clock.h"
#include "sim/kernel/decision_pump.h"
#include "sim/kernel/module_process.h"
#include "sim/kernel/transfer_channel.h"
#include "sim/rtu_config.h"

namespace rtu {

class SceneManagerModule : public sc_core::sc_module, public Agent {
 public:
  // Its ports on the transfer channels: rays from the host, jobs to the job manager, the RTU's
  // results, merged results to the host.
  static constexpr int kRaysInPort = 0, kJobsOutPort = 1, kResultsInPort = 2, kRaysOutPort = 3;

  // Of `config`: the scene manager's settings, the cores' kind (its miss) and the job manager's
  // (the distance of a hit).
  SceneManagerModule(sc_core::sc_module_name name, const CycleClock& clock, DecisionPump& pump,
                     std::vector<SceneInstance> instances, const RtuConfig& config);

  void bind(TransferChannel<HostPayload>& raysIn, TransferChannel<HostPayload>& jobsOut,
            TransferChannel<CoreResult>& resultsIn, TransferChannel<CoreResult>& raysOut);
  void decide() override;

  const SceneManagerStatistics& statistics() const { return statistics_; }
  // Per job, in issue order: the cycle it entered the job manager.
  const std::vector<uint64_t>& issueCycles() const { return issueCycles_; }

 private:
  struct Ray {
    uint64_t id = 0;  // the host record's index
    RayRecord record;
    std::vector<SceneCandidate> candidates;
    size_t next = 0;  // candidates issued
    uint64_t readyFrom = 0;
    bool outstanding = false;
    CoreResult merged;
    int nearest = -1;                 // the instance hit, -1 on a miss so far
    uint64_t doneFrom = kNeverCycle;  // the cycle it may be offered to the host from
  };

  void end_of_elaboration() override;
  void mergeResults(uint64_t now);
  void merge(const CoreResult& result, uint64_t cycle);
  void offerToHost(uint64_t now);
  void takeRay(uint64_t now);
  void issue(uint64_t now);
  // Whether `ray` has a job to issue now: none outstanding and not ended.
  bool wantsJob(const Ray& ray) const;
  void finish(Ray& ray, uint64_t cycle);
  Ray& rayWithId(uint64_t id);
  // Rays held in `cycle` (not before now).
  uint64_t heldIn(uint64_t cycle) const;
  void wakeForNext(uint64_t now);

  const CycleClock& clock_;
  CycleWake wake_;
  std::vector<SceneInstance> instances_;
  SceneManagerConfig config_;
  CoreKindConfigs coreConfigs_;  // how the cores' kind set their jobs up: the hits' distances
  CoreKindMiss miss_;            // the cores' kind's
  TransferChannel<HostPayload>* raysIn_ = nullptr;
  TransferChannel<HostPayload>* jobsOut_ = nullptr;
  TransferChannel<CoreResult>* resultsIn_ = nullptr;
  TransferChannel<CoreResult>* raysOut_ = nullptr;
  std::deque<Ray> rays_;                          // held, oldest first
  std::multimap<uint64_t, CoreResult> arriving_;  // delivered, by cycle, not yet merged
  uint64_t jobsOutstanding_ = 0;
  uint64_t nextJob_ = 0;
  uint64_t issueFrom_ = 0;        // the cycle after the last transfer to the job manager
  uint64_t hostFrom_ = 0;         // the cycle after the last transfer to the host
  uint64_t takeFrom_ = 0;         // the cycle after the last ray taken
  uint64_t offeredRay_ = 0;       // the ray offered to the host
  std::deque<uint64_t> leaving_;  // cycles rays left in, not yet past
  std::vector<uint64_t> issueCycles_;
  SceneManagerStatistics statistics_;
};

}  // namespace rtu
