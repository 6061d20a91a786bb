#include "analytic_run.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <queue>
#include <stdexcept>
#include <utility>

#include "golden_model.h"
#include "job_setup.h"
#include "rtu_recurrence.h"

namespace rtu {
namespace {

// Each record's result and its timing inputs: the job manager's set-up and latencies
// (golden/job_setup.h), the golden model's result and cost.
class RecordTracer {
 public:
  RecordTracer(const SvoMemory& memory, const RtuConfig& config)
      : setup_(memory, config.jobManager), golden_(memory, config.golden()) {}

  void trace(const HostRecord& record) {
    const JobSetup::SetUp set = setup_.setUp(record);
    results.push_back(golden_.trace(set.job));
    timing.push_back(RecurrenceJob{results.back().cost, set.latency, set.headerFetch});
  }

  std::vector<TraversalResult> results;
  std::vector<RecurrenceJob> timing;

 private:
  JobSetup setup_;
  GoldenModel golden_;
};

// Per job: whether some core was idle in the cycle it became pending (eq. 6.7's case). A core is
// busy from the cycle after its dispatch to its handover; every earlier job was dispatched
// before that cycle and no later one, so the busy cores are the earlier jobs not yet handed over.
std::vector<bool> coreIdleWhenPending(const RecurrenceRun& run, int cores) {
  std::priority_queue<uint64_t, std::vector<uint64_t>, std::greater<>> handovers;  // earlier jobs
  std::vector<bool> idle(run.pendingCycles.size());
  for (size_t i = 0; i < idle.size(); ++i) {
    while (!handovers.empty() && handovers.top() < run.pendingCycles[i]) handovers.pop();
    idle[i] = handovers.size() < static_cast<size_t>(cores);
    handovers.push(run.handoverCycles[i]);
  }
  return idle;
}

// The most result buffers full at once, as the result manager counts them: a result counts from
// the cycle it is buffered to the cycle after it drained.
uint64_t maxBuffersFull(const RecurrenceRun& run) {
  std::vector<uint64_t> starts(run.handoverCycles.size()), ends(run.drainCycles.size());
  for (size_t j = 0; j < starts.size(); ++j) {
    starts[j] = run.handoverCycles[j] + 1;
    ends[j] = run.drainCycles[j] + 2;
  }
  std::sort(starts.begin(), starts.end());
  std::sort(ends.begin(), ends.end());
  uint64_t full = 0, most = 0;
  size_t ended = 0;
  for (uint64_t start : starts) {
    for (; ended < ends.size() && ends[ended] <= start; ++ended) --full;
    most = std::max(most, ++full);
  }
  return most;
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
  stats.hostOutRecordBytes = config.outputLink().recordBytes;
  const std::vector<bool> idleWhenPending = coreIdleWhenPending(run, config.cores);
  for (size_t j = 0; j < results.size(); ++j) {
    const TraversalResult& result = results[j];
    CoreStatistics& core = stats.coreTimes[static_cast<size_t>(run.cores[j])];
    ++core.jobs;
    core.busyCycles += result.cost;
    core.outCycles += run.handoverCycles[j] + 1 - (run.dispatchCycles[j] + 1 + result.cost);
    core.stackOverflows += result.stackOverflow;
    core.tOverflows += result.tOverflow;
    stats.belowResolution += result.belowResolution;
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
  if (config.timeline.wanted()) return "a timeline is recorded";
  if (config.hostInput.activeProbability < 1.0 || config.hostOutput.activeProbability < 1.0)
    return "a host link is randomly inactive";
  return std::nullopt;
}

namespace {

template <typename Record>
RtuRun analyticRun(const SvoMemory& memory, const std::vector<Record>& records, const RtuConfig& config) {
  validate(config);
  if (const auto why = whyNotAnalytic(config))
    throw std::invalid_argument("the analytic model does not apply: " + *why);
  const auto start = std::chrono::steady_clock::now();
  RecordTracer traced(memory, config);
  traced.results.reserve(records.size());
  traced.timing.reserve(records.size());
  for (const Record& record : records) traced.trace(record);
  const RecurrenceRun timing =
      runRecurrence(traced.timing, RecurrenceConfig{config.cores, config.scheduler,
                                                    config.hostInput, config.outputLink()});
  RtuRun run;
  run.totalCycles = timing.totalCycles;
  run.results.reserve(records.size());
  run.jobIndices = timing.hostOrder;
  run.arrivalCycles.reserve(records.size());
  for (size_t job : timing.hostOrder) {
    run.results.push_back(traced.results[job]);
    run.arrivalCycles.push_back(timing.drainCycles[job]);
  }
  run.blockedCycles.assign(records.size(), 0);
  run.statistics = statisticsOf(timing, traced.results, config);
  run.statistics.model = "recurrence";
  run.statistics.hostSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace

RtuRun runAnalytic(const SvoMemory& memory, const std::vector<TraversalJob>& jobs,
                   const RtuConfig& config) {
  return analyticRun(memory, jobs, config);
}

RtuRun runAnalytic(const SvoMemory& memory, const std::vector<HostRecord>& records,
                   const RtuConfig& config) {
  return analyticRun(memory, records, config);
}

}  // namespace rtu
