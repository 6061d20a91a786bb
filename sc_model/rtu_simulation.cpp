#include "rtu_simulation.h"

#include <chrono>
#include <memory>
#include <stdexcept>

#include <systemc>

#include "rtu_top.h"

namespace rtu {
namespace {

// SystemC cannot elaborate again once a simulation has started, so each run gets its own kernel.
// The previous kernel is left allocated: deleting it is not supported by SystemC 2.3.
void freshKernel() {
  sc_core::sc_curr_simcontext = new sc_core::sc_simcontext();
  sc_core::sc_default_global_context = sc_core::sc_curr_simcontext;
}

// Simulates until no event is left. With a progress callback it stops every 2^18 cycles to report;
// with a trace every TraceOptions::flushCycles to write the cycles that are final, which bounds
// the trace's memory. Stopping and resuming does not change what happens in any cycle.
void runToCompletion(const HostSink& sink, const CycleClock& clock, CycleTrace* trace,
                     uint64_t flushCycles, const RunProgress& progress) {
  if (!progress && !trace) return sc_core::sc_start();
  constexpr uint64_t kProgressCycles = uint64_t{1} << 18;
  const uint64_t slice = trace ? flushCycles : kProgressCycles;
  uint64_t simulated = 0, nextProgress = kProgressCycles;
  do {
    sc_core::sc_start(clock.period() * static_cast<double>(slice));
    simulated += slice;
    // Modules record no cycle before the current one any more (modules/cycle_trace.h).
    if (trace) trace->flush(clock.now());
    if (progress && simulated >= nextProgress) {
      progress(sink.results().size(), sink.expected());
      nextProgress = (simulated / kProgressCycles + 1) * kProgressCycles;
    }
  } while (sc_core::sc_pending_activity());
}

// A trace when the run writes or counts one, a timeline, or has listeners: the file is optional.
std::unique_ptr<CycleTrace> openTrace(const RtuConfig& config, std::vector<TraceListener*> listeners) {
  if (!config.trace && listeners.empty()) return nullptr;
  TraceOptions options = config.trace.value_or(TraceOptions{});
  options.periodPs = CycleClock::atMegahertz(config.clockMhz).period().value();
  return std::make_unique<CycleTrace>(options, std::move(listeners));
}

}  // namespace

RtuRun simulateRtu(const SvoMemory& memory, const std::vector<TraversalJob>& jobs,
                   const RtuConfig& config, const RunProgress& progress) {
  return simulateRtu(memory, std::vector<HostRecord>(jobs.begin(), jobs.end()), config, progress);
}

RtuRun simulateRtu(const SvoMemory& memory, const std::vector<HostRecord>& records,
                   const RtuConfig& config, const RunProgress& progress,
                   std::vector<TraceListener*> listeners) {
  validate(config);
  freshKernel();
  std::unique_ptr<TimelineWriter> timeline;
  if (config.timeline.wanted()) {
    timeline = std::make_unique<TimelineWriter>(
        config.timeline, CycleClock::atMegahertz(config.clockMhz).period().value());
    listeners.push_back(timeline.get());
  }
  std::unique_ptr<CycleTrace> trace = openTrace(config, std::move(listeners));
  auto top = std::make_unique<RtuTop>("rtu", config, memory, records, trace.get());
  if (trace) trace->checkScopesMatched();

  const auto start = std::chrono::steady_clock::now();
  runToCompletion(top->sink(), CycleClock::atMegahertz(config.clockMhz), trace.get(),
                  config.trace ? config.trace->flushCycles : TraceOptions{}.flushCycles, progress);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const HostSink& sink = top->sink();
  // Before the stall check: the trace of a stalled run shows why. The marker: the first result.
  if (trace) trace->finish(sink.arrivalCycles().empty() ? 0 : sink.arrivalCycles().front());
  if (!sink.complete())
    throw std::runtime_error("simulation stalled after " + std::to_string(sink.results().size()) +
                             " of " + std::to_string(records.size()) + " results");
  RtuRun run;
  run.arrivalCycles = sink.arrivalCycles();
  run.totalCycles = run.arrivalCycles.empty() ? 0 : run.arrivalCycles.back() + 1;
  for (const CoreResult& result : sink.results()) {
    run.results.push_back(result.result);
    run.jobIndices.push_back(result.sequence);
    run.blockedCycles.push_back(result.blockedCycles);
  }
  run.statistics = collectStatistics(*top, config, run.totalCycles);
  run.statistics.hostSeconds = seconds;
  if (trace) run.traceBytes = trace->countedBytes();
  if (timeline) run.timelineBytes = timeline->bytes();
  return run;
}

std::vector<TraversalResult> resultsInJobOrder(const RtuRun& run) {
  std::vector<TraversalResult> ordered(run.results.size());
  for (size_t i = 0; i < run.results.size(); ++i) ordered[run.jobIndices[i]] = run.results[i];
  return ordered;
}

}  // namespace rtu
