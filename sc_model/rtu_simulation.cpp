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

}  // namespace

RtuRun simulateRtu(const SvoMemory& memory, const std::vector<TraversalJob>& jobs,
                   const RtuConfig& config) {
  return simulateRtu(memory, std::vector<HostRecord>(jobs.begin(), jobs.end()), config);
}

RtuRun simulateRtu(const SvoMemory& memory, const std::vector<HostRecord>& records,
                   const RtuConfig& config) {
  validate(config);
  freshKernel();
  std::unique_ptr<CycleTrace> trace;
  if (config.trace) {
    TraceOptions options = *config.trace;
    options.periodPs = CycleClock::atMegahertz(config.clockMhz).period().value();
    trace = std::make_unique<CycleTrace>(options);
  }
  auto top = std::make_unique<RtuTop>("rtu", config, memory, records, trace.get());

  const auto start = std::chrono::steady_clock::now();
  sc_core::sc_start();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const HostSink& sink = top->sink();
  if (!sink.complete())
    throw std::runtime_error("simulation stalled after " + std::to_string(sink.results().size()) +
                             " of " + std::to_string(records.size()) + " results");
  RtuRun run;
  run.arrivalCycles = sink.arrivalCycles();
  run.totalCycles = run.arrivalCycles.empty() ? 0 : run.arrivalCycles.back() + 1;
  for (const CoreResult& result : sink.results()) {
    run.results.push_back(result.result);
    run.jobIndices.push_back(result.sequence);
  }
  run.statistics = collectStatistics(*top, config, run.totalCycles);
  run.statistics.hostSeconds = seconds;
  if (trace) trace->write();
  return run;
}

std::vector<TraversalResult> resultsInJobOrder(const RtuRun& run) {
  std::vector<TraversalResult> ordered(run.results.size());
  for (size_t i = 0; i < run.results.size(); ++i) ordered[run.jobIndices[i]] = run.results[i];
  return ordered;
}

}  // namespace rtu
