#pragma once
// Runs one RTU simulation to completion: elaborates a fresh SystemC kernel, feeds the jobs from the
// first cycle after reset and returns what the host received. Several runs may follow each other
// in one process (tests, sweeps); they do not share any kernel state.

#include <cstdint>
#include <functional>
#include <vector>

#include "kinds/host_stream.h"
#include "kinds/svo/thesis_records.h"
#include "rtu/word_memory.h"
#include "run/rtu_statistics.h"
#include "sim/ca/rtu_payloads.h"
#include "sim/memory/cache_contents.h"
#include "sim/rtu_config.h"
#include "trace/trace_listener.h"

namespace rtu {

// The statistics of a run under way: at `cycle`, when `results` results had arrived.
struct RunSnapshot {
  uint64_t cycle = 0;
  uint64_t results = 0;
  RtuStatistics statistics;  // as collected at the end, with `cycle` as the total
};

// How sampled simulation (sampled_run.h) runs a block: from caches warmed functionally, with
// snapshots of the statistics on the way: one at the first multiple of `everyCycles` by which at
// least each count of results has arrived (counts ascending). With `stopAtLast` the run ends at
// the last snapshot and returns no results.
struct BlockRun {
  std::vector<uint64_t> afterResults;
  uint64_t everyCycles = 32;
  bool stopAtLast = false;
  const CacheContents* startCaches = nullptr;  // lines resident from cycle 0; null: empty caches
};

struct RtuRun {
  std::vector<CoreKindResult> results;   // in the order the host received them
  std::vector<uint64_t> jobIndices;      // the host record (ray) each result answers
  std::vector<uint64_t> arrivalCycles;   // the cycle of each result's handshake with the host
  std::vector<int> instances;            // a scene: the instance each result hit (-1: none)
  std::vector<uint32_t> blockedCycles;   // each result's cycles BLOCKED on memory (beside its cost)
  std::vector<uint64_t> jobIssueCycles;  // a scene: per job the scene manager issued, the cycle
                                         // the job manager took it
  // From the first cycle after reset up to and including the cycle the last result is taken.
  uint64_t totalCycles = 0;
  RtuStatistics statistics;
  std::vector<RunSnapshot> snapshots;
  // Bytes of the trace's VCD and of the timeline, of a run that only counts them (countOnly).
  // A run that only counts a windowed trace or timeline stops once the window (and for a
  // timeline the rays that started in it) has passed, with no results.
  uint64_t traceBytes = 0, timelineBytes = 0;
  // The kernel's simulated time when the run stopped, in cycles (the modules decide ahead of it:
  // a whole run's may end before totalCycles).
  uint64_t simulatedCycles = 0;
};

// Told now and then how many results the host has received of how many.
using RunProgress = std::function<void(size_t results, size_t total)>;

// Throws std::invalid_argument for impossible configurations and std::runtime_error when the
// simulation ends without every result (which would be a model defect). `listeners` see the
// trace's records (src/trace/trace_listener.h) and must outlive the call.
RtuRun simulateRtu(const WordMemory& memory, const std::vector<HostRecord>& records,
                   const RtuConfig& config, const RunProgress& progress = {},
                   std::vector<TraceListener*> listeners = {});
RtuRun simulateRtu(const WordMemory& memory, const std::vector<TValueRecord>& jobs,
                   const RtuConfig& config, const RunProgress& progress = {});
// A run that streams (kinds/host_stream.h): records made as the host source asks for them (or a
// vector's), each result handed to `take` as it reaches the host, none kept (the run's results
// and their columns are empty; its statistics count them all). The statistics equal simulateRtu's.
RtuRun streamRtu(const WordMemory& memory, const RecordSource& records, const RtuConfig& config,
                 const ResultTaker& take, const RunProgress& progress = {});
// A sampled block's run.
RtuRun simulateRtu(const WordMemory& memory, const std::vector<HostRecord>& records,
                   const RtuConfig& config, const BlockRun& block);

// A scene: each of `rays` (world space) is traced against `scene`'s instances by the scene
// manager (src/sim/ca/scene_manager_module.h); one merged result per ray.
RtuRun simulateScene(const WordMemory& memory, const std::vector<RayRecord>& rays,
                     const std::vector<SceneInstance>& scene, const RtuConfig& config,
                     const RunProgress& progress = {});

// Results ordered by job index, as the golden model returns them.
std::vector<CoreKindResult> resultsInJobOrder(const RtuRun& run);

}  // namespace rtu
