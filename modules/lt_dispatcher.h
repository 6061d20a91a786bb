#pragma once
// The job manager and the scheduler of the loosely-timed model, at transaction level: a core
// that is idle asks for its next job (lt_transactions.h) and gets it with its dispatch cycle.
//
// The jobs are set up as the cycle-accurate job manager sets them up (golden/job_setup.h: the
// same float-to-fixed conversion, model headers and pipeline latencies), in host order:
//   accept  c_i = the input link's next slot after c_{i-1} (host_link.h), not inside a header
//                 fetch; pending A_i = max(c_i + L_i, A_{i-1} + 1).
// The core's dispatch cycle is the scheduling policy's choice (golden/scheduler_choice.h) among
// what the dispatcher knows: the asking core, idle from its cycle. Cores that have not asked are
// taken as busy, since within a quantum cores ask in the kernel's order, not in cycle order:
//   cfa  the first cycle t >= max(A_i, idle) with t mod N = the core (the select counter);
//   fa   the first cycle >= max(A_i, idle) in which no other job was dispatched;
//   rr   core k runs jobs k, k + N, ... (the policy's turns), dispatched as fa.
// The job manager's output register and its stalls (a job waiting for a core holds the pipeline
// and the host) are not modelled: jobs are pending as the input link brings them. Holding job i
// until D_{i-1} + 1 would serialise the cores, since a core that runs ahead in its quantum takes
// job i - 1 at a late cycle; so the scheduler statistics' waits (D - A) are longer than the
// cycle-accurate model's, and a run bound by the input link comes out a few percent short.

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "host_link.h"
#include "job_setup.h"
#include "lt_time.h"
#include "lt_transactions.h"
#include "scheduler_choice.h"
#include "slot_calendar.h"

namespace rtu {

struct LtDispatcherConfig {
  int cores = 16;
  SchedulerPolicy policy = SchedulerPolicy::CyclicFirstAvailable;
  JobManagerConfig jobManager;
  HostLinkConfig hostInput;
};

struct LtDispatchStatistics {
  uint64_t stallCycles = 0;                    // sum over jobs of dispatch - pending
  std::map<uint64_t, uint64_t> waitHistogram;  // dispatch - pending -> jobs
  uint64_t maxWait = 0;
  uint64_t maxWaitWithReadyCore = 0;  // over jobs whose core was idle when they became pending
};

class LtDispatcher : public sc_core::sc_module, public LtJobSourceIf {
 public:
  // `records` must outlive the dispatcher.
  LtDispatcher(sc_core::sc_module_name name, SvoMemory memory,
               const std::vector<HostRecord>& records, const LtDispatcherConfig& config,
               const LtTime& time);

  bool take(int core, uint64_t idleFrom, LtDispatch& dispatch) override;

  // Per job index, once dispatched.
  const std::vector<uint64_t>& dispatchCycles() const { return dispatchCycles_; }
  LtDispatchStatistics statistics() const;

 private:
  // The next job index for `core`, or records.size() when none is left.
  size_t nextJobFor(int core);
  uint64_t pendingCycle(size_t job);
  uint64_t dispatchCycle(int core, uint64_t pending, uint64_t idleFrom);
  void countWait(uint64_t pending, uint64_t dispatch, uint64_t idleFrom);

  const std::vector<HostRecord>& records_;
  LtDispatcherConfig config_;
  LtTime time_;
  JobSetup setup_;
  HostLinkPacer input_;
  SchedulerChoice choice_;
  SlotCalendar dispatches_;  // one dispatch per cycle (fa, rr)
  std::vector<TraversalJob> jobs_;                 // set up, by index, up to pending_.size()
  std::vector<uint64_t> pending_;
  uint64_t lastAccept_ = 0, fetchUntil_ = 0;
  size_t nextShared_ = 0;                  // cfa, fa: the next job in host order
  std::vector<size_t> nextOwn_;            // rr: each core's next job
  std::vector<uint64_t> dispatchCycles_;
  LtDispatchStatistics statistics_;  // its histogram holds the waits past shortWaits_
  std::array<uint64_t, 256> shortWaits_{};  // jobs by wait: no map look-up per job
};

}  // namespace rtu
