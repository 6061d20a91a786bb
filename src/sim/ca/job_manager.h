#pragma once
// The job manager (thesis 6.2.1, appendix C.2): host records in, fixed-point traversal jobs out,
// through a pipeline of `stages` registers for t-value records (the RTL), and `rayStages` more for
// ray records (ray transform into the model's space and the t-parameters of eq. 6.6; the thesis
// leaves them as placeholders, so their latency is configuration). Jobs leave in order: a
// t-value record behind a ray record waits for it. The first ray against a model fetches the
// model's header from memory (`headerFetchCycles`, during which no record is accepted) and keeps
// it for the rest of the run, as the thesis' animation stage would once per frame. Like the RTL
// it advances only when its output is taken or empty (pipeline_enable = out_ready || !out_valid),
// and it accepts an input exactly when it advances, so a job waiting for a core stalls the whole
// pipeline and the host.
//
// The pipeline is kept as the jobs in flight with the cycle each reaches the output if nothing
// stalls; the job at the output from A until the scheduler takes it in D stalls all of them by
// D - A. A record offered from h is taken in the first cycle from max(h, end of a header fetch)
// outside every stall [A, D), so while the job at the output is not yet taken, a record offered
// from A on waits for D.

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "base/ring_queue.h"
#include "kinds/registry.h"
#include "sim/ca/rtu_payloads.h"
#include "sim/kernel/cycle_clock.h"
#include "sim/kernel/decision_pump.h"
#include "sim/kernel/transfer_channel.h"

namespace rtu {

struct JobManagerStatistics {
  uint64_t stallCycles = 0;  // cycles the output was valid and not taken
};

class JobManager final : public Agent {
 public:
  // Its ports on the transfer channels (TransferChannel::connect).
  static constexpr int kInPort = 0, kOutPort = 0;

  // `setup` is the cores' kind's (kinds/registry.h, makeCoreJobSetup), with the latencies of
  // `timing`, which is checked here.
  JobManager(DecisionPump& pump, const CycleClock& clock, const JobManagerTiming& timing,
             CoreJobSetup setup);

  void bind(TransferChannel<HostPayload>& in, TransferChannel<CoreJob>& out);
  void decide() override;

  const JobManagerStatistics& statistics() const { return statistics_; }

 private:
  struct InFlight {
    CoreJob job;
    uint64_t unstalledOutput;  // its output cycle less the stalls before it entered: outputOf()
  };
  struct Window {  // cycles [from, to) in which no record is accepted
    uint64_t from, to;
  };

  // The cycle `job` reaches the output if nothing stalls from now on. A stall holds every job in
  // flight, so their output cycles are kept less the stalls so far and the stall adds to all
  // of them at once.
  uint64_t outputOf(const InFlight& job) const { return job.unstalledOutput + stallShift_; }
  void takeDispatch();
  void acceptOffered();
  uint64_t acceptanceCycle(uint64_t offered) const;
  void accept(const HostPayload& host, uint64_t cycle);
  // The trace of in_ready, recomputed at the cycles where it may change.
  bool readyIn(uint64_t cycle) const;
  void traceReadyAt(uint64_t cycle);
  void retraceReady();

  const CycleClock& clock_;
  CoreJobSetup setup_;  // what it computes (the kind's Setup); this module adds when
  TransferChannel<HostPayload>* in_ = nullptr;
  TransferChannel<CoreJob>* out_ = nullptr;
  RingQueue<InFlight> pipeline_;
  uint64_t stallShift_ = 0;  // the stalls so far (modulo 2^64: only outputOf() is a cycle)
  bool frontOffered_ = false;
  std::optional<uint64_t> lastDispatch_;  // of the job that left the output last
  std::deque<Window> stalls_;             // decided stalls a later acceptance may fall into
  std::deque<Window> fetches_;            // header fetches
  bool accepted_ = false;
  uint64_t lastAccepted_ = 0;
  std::vector<uint64_t> readyPoints_;  // traced cycles whose level a later window may change
  JobManagerStatistics statistics_;
};

}  // namespace rtu
