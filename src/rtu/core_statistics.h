#pragma once
// What a traversal core of any kind counts, in any model (the SystemC core, the recurrence's
// cores), and the declaration of it (base/statistics.h): per core its jobs and the cycles it spent
// busy, blocked on memory and handing over its result; for the run the rays whose traversal
// overflowed (the SVO kind's own counters, counted by SvoKind::count). A job's cost is its cycles
// outside IDLE, OUT and BLOCKED.

#include <cstdint>

#include "base/statistics.h"

namespace rtu {

struct CoreStatistics {
  uint64_t jobs = 0;
  uint64_t busyCycles = 0;     // the kind's working states (the jobs' cost)
  uint64_t blockedCycles = 0;  // BLOCKED
  uint64_t outCycles = 0;      // OUT: result waiting for the result manager
  uint64_t stackOverflows = 0;
  uint64_t tOverflows = 0;

  static const StatisticGroup<CoreStatistics>& declaration();
};

}  // namespace rtu
