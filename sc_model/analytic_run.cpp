#include "analytic_run.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <stdexcept>
#include <utility>

#include "golden_model.h"
#include "model_header.h"
#include "rtu_recurrence.h"

namespace rtu {
namespace {

// Each record's result and its timing inputs, with the job manager's latencies (job_manager.h):
// a ray record adds the ray stages, and the first ray of a model its header fetch.
struct TracedRecords {
  std::vector<TraversalResult> results;
  std::vector<RecurrenceJob> timing;
};

TracedRecords traceRecords(const SvoMemory& memory, const std::vector<HostRecord>& records,
                           const RtuConfig& config) {
  const JobManagerConfig& manager = config.jobManager;
  GoldenModel golden(memory, config.golden());
  std::map<uint32_t, ModelHeader> headers;
  TracedRecords traced;
  traced.results.reserve(records.size());
  traced.timing.reserve(records.size());
  for (const HostRecord& record : records) {
    RecurrenceJob timing;
    timing.pipelineCycles = static_cast<uint64_t>(manager.stages);
    TraversalJob job;
    if (const auto* ray = std::get_if<RayRecord>(&record)) {
      auto header = headers.find(ray->modelAddress);
      if (header == headers.end()) {
        header = headers.emplace(ray->modelAddress, readModelHeader(memory, ray->modelAddress)).first;
        timing.headerFetch = static_cast<uint64_t>(manager.headerFetchCycles);
      }
      job = rayRecordToJob(*ray, header->second, manager.epsilon);
      timing.pipelineCycles += static_cast<uint64_t>(manager.rayStages) + timing.headerFetch;
    } else {
      job = std::get<TraversalJob>(record);
    }
    traced.results.push_back(golden.trace(job));
    timing.cost = traced.results.back().cost;
    traced.timing.push_back(timing);
  }
  return traced;
}

// Per job: whether some core was idle in the cycle it became pending (eq. 6.7's case). A core is
// busy from the cycle after its dispatch to its handover.
std::vector<bool> coreIdleWhenPending(const RecurrenceRun& run, int cores) {
  std::vector<std::pair<uint64_t, int>> changes;  // (cycle, +1 busy / -1 idle again)
  for (size_t j = 0; j < run.dispatchCycles.size(); ++j) {
    changes.push_back({run.dispatchCycles[j] + 1, +1});
    changes.push_back({run.handoverCycles[j] + 1, -1});
  }
  std::sort(changes.begin(), changes.end());
  std::vector<bool> idle(run.pendingCycles.size());
  size_t next = 0;
  int busy = 0;
  for (size_t i = 0; i < idle.size(); ++i) {  // pending cycles rise with the job index
    for (; next < changes.size() && changes[next].first <= run.pendingCycles[i]; ++next)
      busy += changes[next].second;
    idle[i] = busy < cores;
  }
  return idle;
}

// The most result buffers full at once, as the result manager counts them: a result counts from
// the cycle it is buffered to the cycle after it drained.
uint64_t maxBuffersFull(const RecurrenceRun& run) {
  std::vector<std::pair<uint64_t, int>> changes;  // at equal cycles, ends (-1) before starts
  for (size_t j = 0; j < run.handoverCycles.size(); ++j) {
    changes.push_back({run.handoverCycles[j] + 1, +1});
    changes.push_back({run.drainCycles[j] + 2, -1});
  }
  std::sort(changes.begin(), changes.end());
  int64_t full = 0, most = 0;
  for (const auto& change : changes) {
    full += change.second;
    most = std::max(most, full);
  }
  return static_cast<uint64_t>(most);
}

RtuStatistics statisticsOf(const RecurrenceRun& run, const std::vector<TraversalResult>& results,
                           const RtuConfig& config) {
  RtuStatistics stats;
  stats.rays = results.size();
  stats.totalCycles = run.totalCycles;
  stats.clockMhz = config.clockMhz;
  stats.cores = config.cores;
  stats.scheduler = toString(config.scheduler);
  stats.coreTimes.resize(static_cast<size_t>(config.cores));
  stats.hostInBytesPerCycle = config.hostInput.bytesPerCycle;
  stats.hostOutBytesPerCycle = config.hostOutput.bytesPerCycle;
  const std::vector<bool> idleWhenPending = coreIdleWhenPending(run, config.cores);
  for (size_t j = 0; j < results.size(); ++j) {
    const TraversalResult& result = results[j];
    CoreStatistics& core = stats.coreTimes[static_cast<size_t>(run.cores[j])];
    ++core.jobs;
    core.busyCycles += result.cost;
    core.outCycles += run.handoverCycles[j] + 1 - (run.dispatchCycles[j] + 1 + result.cost);
    core.stackOverflows += result.stackOverflow;
    stats.totalCost += result.cost;
    stats.maxCost = std::max<uint64_t>(stats.maxCost, result.cost);
    const uint64_t wait = run.dispatchCycles[j] - run.pendingCycles[j];
    stats.jobManagerStallCycles += wait;
    ++stats.waitHistogram[wait];
    stats.maxWait = std::max(stats.maxWait, wait);
    if (idleWhenPending[j]) stats.maxWaitWithReadyCore = std::max(stats.maxWaitWithReadyCore, wait);
  }
  stats.stackOverflows = stats.allCores().stackOverflows;
  stats.resultBuffersMaxFull = maxBuffersFull(run);
  return stats;
}

}  // namespace

std::optional<std::string> whyNotAnalytic(const RtuConfig& config) {
  if (!config.memory.ideal) return "the memory is cached";
  if (config.reorderCapacity > 0) return "results pass a reorder buffer";
  if (config.trace) return "a trace is recorded";
  if (config.hostInput.activeProbability < 1.0 || config.hostOutput.activeProbability < 1.0)
    return "a host link is randomly inactive";
  return std::nullopt;
}

RtuRun runAnalytic(const SvoMemory& memory, const std::vector<TraversalJob>& jobs,
                   const RtuConfig& config) {
  return runAnalytic(memory, std::vector<HostRecord>(jobs.begin(), jobs.end()), config);
}

RtuRun runAnalytic(const SvoMemory& memory, const std::vector<HostRecord>& records,
                   const RtuConfig& config) {
  validate(config);
  if (const auto why = whyNotAnalytic(config))
    throw std::invalid_argument("the analytic model does not apply: " + *why);
  const auto start = std::chrono::steady_clock::now();
  const TracedRecords traced = traceRecords(memory, records, config);
  const RecurrenceRun timing =
      runRecurrence(traced.timing, RecurrenceConfig{config.cores, config.scheduler,
                                                    config.hostInput, config.hostOutput});
  RtuRun run;
  run.totalCycles = timing.totalCycles;
  for (size_t job : timing.hostOrder) {
    run.results.push_back(traced.results[job]);
    run.jobIndices.push_back(job);
    run.arrivalCycles.push_back(timing.drainCycles[job]);
    run.blockedCycles.push_back(0);
  }
  run.statistics = statisticsOf(timing, traced.results, config);
  run.statistics.hostSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace rtu
