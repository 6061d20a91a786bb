#pragma once
// The loosely-timed RTU (docs/fidelity.md, "The loosely-timed model"): thesis figure 6.1 with
// its memory at transaction level. N traversal cores are TLM-2.0 initiators; their memory is the
// ideal ROM (DMI) or, per core, an L1 target in front of the shared L2 target and the DRAM target.
//
// One thread drives them, temporally decoupled (tlm_utils::tlm_quantumkeeper, after the
// Accellera lt_td_initiator example): the job manager, scheduler and result manager are the
// recurrence of src/rtu/rtu_recurrence.h, the same rules as the cycle-accurate modules; at each
// dispatch the chosen core traverses its job through its memory at once, and the thread
// synchronises with the kernel whenever the dispatches run a quantum ahead of simulated time.
// Jobs are dispatched in cycle order, so the per-core L1s see their reads in cycle order; the
// shared L2 and DRAM see one traversal's reads after another's, out of cycle order by up to a
// traversal, and take them in their out-of-order form (src/sim/memory/resource_booking.h).

#include <memory>
#include <utility>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "kinds/svo/job_setup.h"
#include "rtu/rtu_recurrence.h"
#include "sim/lt/lt_dram.h"
#include "sim/lt/lt_l1_cache.h"
#include "sim/lt/lt_l2_cache.h"
#include "sim/lt/lt_rom.h"
#include "sim/lt/lt_core.h"
#include "sim/rtu_config.h"

namespace rtu {

class LtTop : public sc_core::sc_module {
 public:
  // `records` must outlive the top.
  LtTop(sc_core::sc_module_name name, const RtuConfig& config, WordMemory memory,
        const std::vector<HostRecord>& records);

  // After the simulation, taken once: the cycles, and each job's result and blocked cycles by
  // job index.
  RecurrenceRun takeTiming() { return std::move(timing_); }
  std::vector<TraversalResult> takeResults() { return std::move(results_); }
  std::vector<uint32_t> takeBlocked() { return std::move(blocked_); }
  bool idealMemory() const { return rom_ != nullptr; }
  std::vector<CacheStats> l1Statistics() const;
  L2Stats l2Statistics() const;  // the L2's counts with the DRAM target's

 private:
  void drive();
  RecurrenceJob setUp(size_t job);
  uint64_t traverse(size_t job, int core, uint64_t initCycle);
  void bindCachedMemory(const RtuConfig& config, WordMemory memory);

  const RtuConfig& config_;
  const std::vector<HostRecord>& records_;
  LtTime time_;
  JobSetup setup_;
  tlm_utils::tlm_quantumkeeper quantum_;
  // The cores' shared state machine: each runs a job to its end in one call (lt_core.h).
  TraversalCore<FixedArith> stateMachine_;
  std::vector<std::unique_ptr<LtTraversalCore>> cores_;
  std::unique_ptr<LtRom> rom_;
  std::vector<std::unique_ptr<LtL1Cache>> l1_;
  std::unique_ptr<LtL2Cache> l2_;
  std::unique_ptr<LtDram> dram_;
  TraversalJob current_;  // the job set up last, float t-values: converted at dispatch
  RecurrenceRun timing_;
  std::vector<TraversalResult> results_;
  std::vector<uint32_t> blocked_;
};

}  // namespace rtu
