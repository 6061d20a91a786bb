#include "lt_simulation.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <numeric>
#include <stdexcept>

#include "lt_top.h"
#include "sc_kernel.h"

namespace rtu {

std::optional<std::string> whyNotLooselyTimed(const RtuConfig& config) {
  if (config.reorderCapacity > 0) return "results pass a reorder buffer (--reorder)";
  if (config.trace) return "a trace is recorded (waveforms are the cycle-accurate model's)";
  if (config.timeline.wanted()) return "a timeline is recorded (it is the cycle-accurate model's)";
  if (config.hostInput.activeProbability < 1.0 || config.hostOutput.activeProbability < 1.0)
    return "a host link is randomly inactive";
  return std::nullopt;
}

namespace {

RtuStatistics statisticsOf(const LtTop& top, const RtuConfig& config, const RtuRun& run) {
  RtuStatistics stats;
  stats.model = "lt";
  stats.rays = run.results.size();
  stats.totalCycles = run.totalCycles;
  stats.clockMhz = config.clockMhz;
  stats.cores = config.cores;
  stats.scheduler = toString(config.scheduler);
  stats.coreTimes = top.collector().coreStatistics();
  stats.stackOverflows = stats.allCores().stackOverflows;
  for (size_t i = 0; i < run.results.size(); ++i) {
    const TraversalResult& result = run.results[i];
    stats.totalCost += result.cost;
    stats.maxCost = std::max<uint64_t>(stats.maxCost, result.cost);
    stats.totalBlocked += run.blockedCycles[i];
    stats.maxBlocked = std::max<uint64_t>(stats.maxBlocked, run.blockedCycles[i]);
    stats.belowResolution += result.belowResolution;
  }
  stats.hostInBytesPerCycle = config.hostInput.bytesPerCycle;
  stats.hostOutBytesPerCycle = config.hostOutput.bytesPerCycle;
  stats.hostOutRecordBytes = config.outputLink().recordBytes;
  const LtDispatchStatistics dispatch = top.dispatcher().statistics();
  stats.jobManagerStallCycles = dispatch.stallCycles;
  stats.waitHistogram = dispatch.waitHistogram;
  stats.maxWait = dispatch.maxWait;
  stats.maxWaitWithReadyCore = dispatch.maxWaitWithReadyCore;
  stats.resultBuffersMaxFull = top.collector().maxBuffersFull();
  stats.idealMemory = top.idealMemory();
  if (!stats.idealMemory) {
    stats.l1 = top.l1Statistics();
    stats.l2 = top.l2Statistics();
  }
  return stats;
}

// The arrivals in the host's order: by drain cycle (one result a cycle leaves the RTU).
void collectResults(const LtTop& top, RtuRun& run) {
  const std::vector<LtArrival>& arrivals = top.collector().arrivals();
  std::vector<uint32_t> order(arrivals.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return arrivals[a].cycle != arrivals[b].cycle ? arrivals[a].cycle < arrivals[b].cycle
                                                  : arrivals[a].result.ids.job < arrivals[b].result.ids.job;
  });
  run.results.reserve(arrivals.size());
  run.jobIndices.reserve(arrivals.size());
  run.arrivalCycles.reserve(arrivals.size());
  run.blockedCycles.reserve(arrivals.size());
  for (uint32_t i : order) {
    const LtArrival& arrival = arrivals[i];
    run.results.push_back(arrival.result.result);
    run.jobIndices.push_back(arrival.result.ids.job);
    run.arrivalCycles.push_back(arrival.cycle);
    run.blockedCycles.push_back(arrival.result.blockedCycles);
  }
  run.instances.assign(arrivals.size(), -1);
  run.totalCycles = run.arrivalCycles.empty() ? 0 : run.arrivalCycles.back() + 1;
}

}  // namespace

RtuRun runLooselyTimed(const SvoMemory& memory, const std::vector<HostRecord>& records,
                       const RtuConfig& config, const RunProgress& progress) {
  validate(config);
  if (const auto why = whyNotLooselyTimed(config))
    throw std::invalid_argument("--model lt does not apply: " + *why);
  if (config.ltQuantum < 1) throw std::invalid_argument("lt.quantum must be at least 1 cycle");
  freshKernel();
  const auto start = std::chrono::steady_clock::now();
  auto top = std::make_unique<LtTop>("rtu", config, memory, records);
  sc_core::sc_start();
  RtuRun run;
  collectResults(*top, run);
  if (run.results.size() != records.size())
    throw std::runtime_error("loosely-timed run ended with " + std::to_string(run.results.size()) +
                             " of " + std::to_string(records.size()) + " results");
  if (progress) progress(records.size(), records.size());
  run.statistics = statisticsOf(*top, config, run);
  run.statistics.hostSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

RtuRun runLooselyTimed(const SvoMemory& memory, const std::vector<TraversalJob>& jobs,
                       const RtuConfig& config, const RunProgress& progress) {
  const std::vector<HostRecord> records(jobs.begin(), jobs.end());
  return runLooselyTimed(memory, records, config, progress);
}

}  // namespace rtu
