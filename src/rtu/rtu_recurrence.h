#pragma once
// The RTU's cycles as a recurrence over jobs, a third reference beside the naive per-cycle RTL
// transcription (rtl_cycle_model.h) and the event-driven SystemC model, for configurations whose
// memory is ideal: each ray's traversal then takes exactly its cost, and only the pipeline, the
// scheduler, the result buffers and the host links decide when things happen. Per job i, with
// cores N, job manager latency L_i and cost W_i (docs/cycle-semantics.md gives the rules):
//
//   accept   c_i = first cycle >= max(host offer h_i, header fetch end) outside every stall
//                  [A_k, D_k) of an earlier job (the pipeline takes input only when it moves);
//                  h_0 = 0, h_i = the input link's next slot after c_{i-1}
//   pending  A_i = max(c_i + L_i + S_i, D_{i-1} + 1), S_i = sum of D_k - A_k over earlier jobs k
//                  still in the pipeline when i entered (A_k > c_i): a stall holds all of them
//   dispatch D_i = cfa: first t >= A_i whose core t mod N is idle in t;
//                  fa: first t >= A_i with an idle core, the lowest one; rr: the next core in
//                  turn, at max(A_i, the cycle it is idle)
//   handover K_i = max(D_i + 1 + W_i, the cycle after the core's previous result drained), W_i
//                  the job's cost, or what a TraversalTimer says at its dispatch;
//                  the core is idle again from K_i + 1, the result is buffered from K_i + 1
//   drain    R_i = first t >= K_i + 1 with t mod N = its core and the output link ready in t;
//                  drains are resolved in cycle order, as the output link's pacing depends on it
//   total cycles = the last drain + 1.
//
// Cost follows the jobs: every step is a few operations per job, except the cycle-by-cycle
// search of cfa and fa while no core is idle. Memory follows the jobs in flight: the recurrence
// holds the jobs in the job manager's pipeline and a waiting and a buffered result per core, and
// tells each job's cycles when its result drains (streamRecurrence); a run's columns are the
// caller's to keep (runRecurrence keeps them).

#include <cstdint>
#include <functional>
#include <vector>

#include "rtu/host_link.h"
#include "rtu/scheduling_policy.h"

namespace rtu {

struct JobTiming {
  uint64_t cost = 0;            // traversal cycles W_i, INIT up to the last state before OUT
  uint64_t pipelineCycles = 6;  // job manager latency (L_i): stages, plus ray set-up and fetch
  uint64_t headerFetch = 0;     // cycles after its acceptance in which no record is accepted
};

struct RecurrenceConfig {
  int cores = 16;
  SchedulerPolicy policy = SchedulerPolicy::CyclicFirstAvailable;
  HostLinkConfig hostInput, hostOutput;  // activity must be 1: the recurrence draws no randomness

  // Throws std::invalid_argument naming what the recurrence cannot model.
  void validate() const;
};

// One job's cycles, told when its result drains (in the host's order).
struct JobCycles {
  size_t job = 0;
  uint64_t accept = 0, pending = 0, dispatch = 0;
  int core = 0;
  uint64_t handover = 0, drain = 0;
};
using DrainSink = std::function<void(const JobCycles&)>;

// What the recurrence finds over the whole run.
struct RecurrenceTotals {
  uint64_t totalCycles = 0;
  uint64_t resultBuffersMaxFull = 0;  // the most result buffers full at once (buffers_full.h)
};

struct RecurrenceRun {
  // Per job index.
  std::vector<uint64_t> acceptCycles;    // host -> job manager handshake
  std::vector<uint64_t> pendingCycles;   // first cycle at the job manager's output
  std::vector<uint64_t> dispatchCycles;  // scheduler -> core handshake
  std::vector<int> cores;                // the core that ran it
  std::vector<uint64_t> handoverCycles;  // core -> result manager handshake
  std::vector<uint64_t> drainCycles;     // result manager -> host handshake
  std::vector<size_t> hostOrder;         // job indices in the order the host received them
  uint64_t totalCycles = 0;
  uint64_t resultBuffersMaxFull = 0;
};

// The jobs, asked for in order, each once: a caller can set a job up when the recurrence reaches
// it rather than hold them all.
using JobSource = std::function<JobTiming(size_t job)>;

// Times a traversal when its job is dispatched: W_i of job `job` on `core`, INIT in `initCycle`
// (D_i + 1). The loosely-timed model's memory makes W_i depend on the core and the cycle. Jobs
// are dispatched in order, so the calls come in increasing initCycle, and each comes after its
// job was asked from the JobSource and before the next one is.
using TraversalTimer = std::function<uint64_t(size_t job, int core, uint64_t initCycle)>;

// With `timer`, W_i comes from it and the jobs' `cost` is not read. Each job's cycles go to
// `drained` as its result drains; nothing per job is kept.
RecurrenceTotals streamRecurrence(size_t jobs, const JobSource& jobAt,
                                  const RecurrenceConfig& config, const DrainSink& drained,
                                  const TraversalTimer& timer = {});
// The same, every job's cycles kept in columns.
RecurrenceRun runRecurrence(size_t jobs, const JobSource& jobAt, const RecurrenceConfig& config,
                            const TraversalTimer& timer = {});
RecurrenceRun runRecurrence(const std::vector<JobTiming>& jobs, const RecurrenceConfig& config,
                            const TraversalTimer& timer = {});

}  // namespace rtu
