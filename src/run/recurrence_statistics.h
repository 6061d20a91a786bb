#pragma once
// A run's statistics from the recurrence's cycles (src/rtu/rtu_recurrence.h) and each job's
// result, counted as the results drain: core times, scheduler waits, the counts of results and
// the result buffers. What depends on the jobs' order (whether some core was idle when a job
// became pending) waits for the jobs before it, so what is held is the jobs in flight, not the
// frame (the loosely-timed model streams its results through it: lt_simulation.h).

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "kinds/core_result.h"
#include "rtu/rtu_recurrence.h"
#include "run/rtu_statistics.h"
#include "sim/rtu_config.h"

namespace rtu {

class RecurrenceStatistics {
 public:
  explicit RecurrenceStatistics(const RtuConfig& config);

  // A job's cycles, result and cycles BLOCKED on memory (W_i = cost + blocked), in any order.
  void add(const JobCycles& cycles, const CoreKindResult& result, uint64_t blocked);
  // Once every job was added: the statistics, with the run's totals. The model, memory counts and
  // host seconds are the caller's to fill.
  RtuStatistics finish(const RecurrenceTotals& totals);

 private:
  // What the job-ordered part reads of a job.
  struct Ordered {
    uint64_t pending, wait, handover;
    int core;
  };
  void inJobOrder(const Ordered& job);

  RtuStatistics stats_;
  std::array<uint64_t, 256> shortWaits_{};    // jobs by wait: no map look-up per job
  std::vector<uint64_t> busyUntil_;           // per core: its last job's handover + 1 in job order
  std::deque<std::optional<Ordered>> ahead_;  // jobs from nextInOrder_ on, added out of order
  size_t nextInOrder_ = 0;
};

}  // namespace rtu
