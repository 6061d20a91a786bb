#include "run/lt_simulation.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <utility>

#include "kinds/registry.h"
#include "run/analytic_run.h"
#include "run/recurrence_statistics.h"
#include "sim/kernel/sc_kernel.h"
#include "sim/lt/lt_top.h"

namespace rtu {

// The model is the recurrence with the memory's timing in the traversals: it runs what the
// recurrence runs, with any memory.
std::optional<std::string> whyNotLooselyTimed(const RtuConfig& config) {
  if (config.warmFrames > 0 && !config.memory.ideal)
    return "its caches start cold: warm_frames needs --model ca";
  RtuConfig anyMemory = config;
  anyMemory.memory.ideal = true;
  anyMemory.triangleSharedBy = 1;  // its cores book their shared units (lt_core.h)
  return whyNotAnalytic(anyMemory);
}

namespace {

// The memory's counts and the cores' stalls of a simulated top.
void addMemoryCounts(const LtTopBase& top, RtuStatistics& stats) {
  stats.idealMemory = top.idealMemory();
  // The recurrence took a test's wait for its shared unit as the core's handover (the cycles
  // from dispatch to hand-over beyond cost and blocked): moved to the stalls.
  for (size_t core = 0; core < stats.coreTimes.size(); ++core) {
    CoreStatistics& times = stats.coreTimes[core];
    times.unitStallCycles = top.unitStalls()[core];
    times.outCycles -= std::min(times.outCycles, times.unitStallCycles);
  }
  if (!stats.idealMemory) {
    stats.l1 = top.l1Statistics();
    stats.l2 = top.l2Statistics();
  }
}

// The run's cycles and statistics, each result handed to `arrived` as it reaches the host; the
// results are the caller's to keep.
RtuRun ltRun(const WordMemory& memory, const RecordSource& records, const RtuConfig& config,
             const LtArrival& arrived, const RunProgress& progress) {
  validate(config);
  checkCoreTakes(config.core, records);
  if (const auto why = whyNotLooselyTimed(config))
    throw std::invalid_argument("--model lt does not apply: " + *why);
  freshKernel();
  const auto start = std::chrono::steady_clock::now();
  RecurrenceStatistics statistics(config);
  const LtArrival counted = [&](const JobCycles& cycles, const CoreKindResult& result,
                                uint32_t blocked) {
    statistics.add(cycles, result, blocked);
    arrived(cycles, result, blocked);
  };
  RtuRun run;
  // The cores' kind, chosen once: the top is a template over it.
  withCoreKind(config.core, [&](auto kind) {
    auto top = std::make_unique<LtTop<decltype(kind)>>("rtu", config, memory, records, counted);
    simulate();
    run.totalCycles = top->totals().totalCycles;
    run.statistics = statistics.finish(top->totals());
    addMemoryCounts(*top, run.statistics);
  });
  run.statistics.model = "lt";
  if (progress) progress(records.size(), records.size());
  run.statistics.hostSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace

RtuRun runLooselyTimed(const WordMemory& memory, const RecordSource& records,
                       const RtuConfig& config, const RunProgress& progress) {
  std::vector<CoreKindResult> results;
  std::vector<uint64_t> jobIndices, arrivalCycles;
  std::vector<uint32_t> blockedCycles;
  RtuRun run = ltRun(
      memory, records, config,
      [&](const JobCycles& cycles, const CoreKindResult& result, uint32_t blocked) {
        results.push_back(result);
        jobIndices.push_back(cycles.job);
        arrivalCycles.push_back(cycles.drain);
        blockedCycles.push_back(blocked);
      },
      progress);
  run.results = std::move(results);
  run.jobIndices = std::move(jobIndices);
  run.arrivalCycles = std::move(arrivalCycles);
  run.blockedCycles = std::move(blockedCycles);
  return run;
}

RtuRun streamLooselyTimed(const WordMemory& memory, const RecordSource& records,
                          const RtuConfig& config, const ResultTaker& take,
                          const RunProgress& progress) {
  return ltRun(
      memory, records, config,
      [&take](const JobCycles& cycles, const CoreKindResult& result, uint32_t) {
        take(cycles.job, result);
      },
      progress);
}

RtuRun runLooselyTimed(const WordMemory& memory, const std::vector<TValueRecord>& jobs,
                       const RtuConfig& config, const RunProgress& progress) {
  const std::vector<HostRecord> records(jobs.begin(), jobs.end());
  return runLooselyTimed(memory, records, config, progress);
}

}  // namespace rtu
