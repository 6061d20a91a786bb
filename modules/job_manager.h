#pragma once
// The job manager (thesis 6.2.1, appendix C.2): host records in, fixed-point traversal jobs out,
// through a pipeline of `stages` registers for t-value records (the RTL), and `rayStages` more for
// ray records (ray transform into the model's space and the t-parameters of eq. 6.6; the thesis
// leaves them as placeholders, so their latency is configuration). Jobs leave in order: a
// t-value record behind a ray record waits for it. The first ray against a model fetches the
// model's header from memory (`headerFetchCycles`, during which no record is accepted) and keeps
// it for the rest of the run, as the thesis' animation stage would once per frame. Like the RTL it advances only when its output is taken
// or empty (pipeline_enable = out_ready || !out_valid), and it accepts an input exactly when it
// advances, so a job waiting for a core stalls the whole pipeline and the host.
//
// The pipeline is kept as the jobs in flight with the cycle each reaches the output if nothing
// stalls; a stall of k cycles at the output delays all of them by k. The module therefore runs
// only in cycles where a job enters, leaves or reaches the output.

#include <deque>
#include <map>

#include <systemc>

#include "cycle_clock.h"
#include "module_process.h"
#include "golden_model.h"
#include "job_setup.h"
#include "ready_valid.h"
#include "rtu_payloads.h"

namespace rtu {

struct JobManagerStatistics {
  uint64_t stallCycles = 0;  // cycles the output was valid and not taken
};

class JobManager : public sc_core::sc_module {
 public:
  sc_core::sc_port<ReadyValidIn<HostJob>> in;
  sc_core::sc_port<ReadyValidOut<CoreJob>> out;

  JobManager(sc_core::sc_module_name name, const CycleClock& clock, JobManagerConfig config,
             SvoMemory memory);

  const JobManagerStatistics& statistics() const { return statistics_; }

 private:
  struct InFlight {
    CoreJob job;
    uint64_t outputCycle;
  };

  void end_of_elaboration() override;
  void evaluate();
  void takeTransfers(uint64_t now);
  bool outputValid(uint64_t now) const;
  void accept(const HostJob& host, uint64_t edge);
  CoreJob convert(uint64_t sequence, const TraversalJob& job) const;

  const CycleClock& clock_;
  JobManagerConfig config_;
  JobSetup setup_;  // what it computes (golden/job_setup.h); this module adds when
  uint64_t fetchUntil_ = 0;                  // no record is accepted before this cycle
  std::deque<InFlight> pipeline_;
  bool offering_ = false;
  uint64_t handledCycle_ = ~0ull;
  CycleWake wake_;
  JobManagerStatistics statistics_;
};

}  // namespace rtu
