#pragma once
// The scheduler (thesis 6.2.2, appendix C.3): hands the job at the job manager's output to a
// ready core, by one of the policies of scheduling_policy.h. The RTL's scheduler is
// combinational: the job manager's handshake and the core's are the same cycle, the dispatch
// cycle D. For a job pending from A it finds D by the policy from what the cores have declared:
// a core ready from some cycle, or not ready before some cycle (still traversing). Where a core
// has declared neither for a cycle the policy needs, it waits for that core to declare more.

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "rtu/scheduler_choice.h"
#include "sim/ca/core_memory_if.h"
#include "sim/ca/rtu_payloads.h"
#include "sim/kernel/decision_pump.h"
#include "sim/kernel/transfer_channel.h"

namespace rtu {

struct SchedulerStatistics {
  uint64_t jobs = 0;
  std::map<uint64_t, uint64_t> waitHistogram;  // cycles from pending to dispatch -> jobs
  uint64_t maxWait = 0;
  // Over jobs that found at least one core ready when they became pending: the case of eq. 6.7.
  uint64_t maxWaitWithReadyCore = 0;
};

class Scheduler final : public Agent, public DispatchFloor {
 public:
  // The port of the job manager's channel; core i's channel is port i.
  static constexpr int kJobsPort = -1;

  Scheduler(DecisionPump& pump, SchedulerPolicy policy, int cores);

  void bind(TransferChannel<CoreJob>& in, std::vector<TransferChannel<CoreJob>*> cores);
  void decide() override;
  void heard(int port) override;

  SchedulerStatistics statistics() const;

 private:
  static constexpr int kAnyCore = -1;

  // What the cores' channels have declared, as the policy's query (scheduler_choice.h). It
  // notes the cores it could not answer for: the search waits for them.
  struct CoreQuery {
    const Scheduler& scheduler;
    int awaited = kNoCore;  // the core answered Unknown for, or kAnyCore for several
    Idle in(int core, uint64_t cycle);
    uint64_t from(int core);
    void await(int core) { awaited = awaited == kNoCore || awaited == core ? core : kAnyCore; }
    static constexpr int kNoCore = -2;
  };

  Idle idleIn(int core, uint64_t cycle) const;
  // Whether some core was ready when the job became pending (eq. 6.7), or Unknown.
  Idle someCoreIdleIn(uint64_t cycle) const;
  void dispatch(int core, uint64_t cycle);
  void countWait(uint64_t wait);

  SchedulerChoice choice_;
  TransferChannel<CoreJob>* in_ = nullptr;
  std::vector<TransferChannel<CoreJob>*> cores_;
  // The one core whose declaration the pending job's search waits for, or kAnyCore: the others'
  // news cannot move the search (a cached run's cores bound their readiness at every miss).
  int awaited_ = kAnyCore;
  SchedulerStatistics statistics_;          // its histogram holds the waits past shortWaits_
  std::array<uint64_t, 256> shortWaits_{};  // jobs by wait: an array, not a map lookup per job
};

}  // namespace rtu
