#pragma once
// The scheduler (thesis 6.2.2, appendix C.3): hands the job at the job manager's output to a
// ready core, by one of the policies of scheduling_policy.h.
// The RTL's scheduler is combinational: the job manager's handshake and the core's are the same
// cycle. Here it is a process that runs only when the job, a core's readiness or the selected core
// changes; for cyclic first-available it computes the cycle the counter reaches a ready core.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <systemc>

#include "core_set.h"
#include "cycle_clock.h"
#include "module_process.h"
#include "ready_valid.h"
#include "rtu_payloads.h"
#include "scheduling_policy.h"

namespace rtu {

struct SchedulerStatistics {
  uint64_t jobs = 0;
  std::map<uint64_t, uint64_t> waitHistogram;  // cycles from pending to dispatch -> jobs
  uint64_t maxWait = 0;
  // Over jobs that found at least one core ready when they became pending: the case of eq. 6.7.
  uint64_t maxWaitWithReadyCore = 0;
};

class Scheduler : public sc_core::sc_module {
 public:
  sc_core::sc_port<ReadyValidIn<CoreJob>> in;
  sc_core::sc_port<ReadyValidOut<CoreJob>, 0> cores;

  Scheduler(sc_core::sc_module_name name, const CycleClock& clock, SchedulerPolicy policy);

  const SchedulerStatistics& statistics() const { return statistics_; }

 private:
  static constexpr int kNone = -1;

  void end_of_elaboration() override;
  void evaluate();
  void takeTransfer(uint64_t now);
  void notePending(uint64_t now);
  // The core the job goes to in cycle `now`, or kNone; `wakeCycle` is set when only a later cycle
  // of the cyclic counter can find a ready core.
  int choose(uint64_t now, uint64_t& wakeCycle) const;
  void dispatch(int core);

  const CycleClock& clock_;
  SchedulerPolicy policy_;
  int coreCount_ = 0;
  // The cores' channels, taken from the port once: indexing an sc_port checks bounds every time.
  std::vector<ReadyValidOut<CoreJob>*> core_;
  CoreSet readyCores_;
  int target_ = kNone;           // core currently offered the job
  uint64_t offeredSequence_ = 0;
  int nextInLine_ = 0;           // round-robin
  uint64_t handledCycle_ = ~0ull;
  uint64_t dispatchedSequence_ = ~0ull;
  uint64_t notedSequence_ = ~0ull;
  bool readyAtPending_ = false;
  CycleWake wake_;
  SchedulerStatistics statistics_;
};

}  // namespace rtu
