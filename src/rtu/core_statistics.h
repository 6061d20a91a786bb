#pragma once
// What a traversal core of any kind counts over a run: its jobs and where its cycles went. The
// cost of a job is its cycles outside IDLE, OUT and BLOCKED.

#include <cstdint>

namespace rtu {

struct CoreStatistics {
  uint64_t jobs = 0;
  uint64_t busyCycles = 0;     // the kind's working states (the jobs' cost)
  uint64_t blockedCycles = 0;  // BLOCKED
  uint64_t outCycles = 0;      // OUT: result waiting for the result manager
  uint64_t stackOverflows = 0;
  uint64_t tOverflows = 0;
};

}  // namespace rtu
