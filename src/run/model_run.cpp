#include "run/model_run.h"

#include <stdexcept>
#include <utility>

#include "run/analytic_run.h"
#include "run/lt_simulation.h"

namespace rtu {

ModelKind parseModelKind(const std::string& name) {
  if (name == "golden") return ModelKind::Golden;
  if (name == "lt") return ModelKind::LooselyTimed;
  if (name == "ca") return ModelKind::CycleAccurate;
  throw std::invalid_argument("unknown model '" + name + "' (golden, lt or ca)");
}

const char* toString(ModelKind model) {
  switch (model) {
    case ModelKind::Golden: return "golden";
    case ModelKind::LooselyTimed: return "lt";
    case ModelKind::CycleAccurate: return "ca";
  }
  return "?";
}

RtuRun runGoldenTimed(const WordMemory& memory, const std::vector<HostRecord>& records,
                      const RtuConfig& config) {
  RtuConfig ideal = config;
  ideal.memory.ideal = true;
  if (const auto why = whyNotAnalytic(ideal))
    throw std::invalid_argument("--model golden times rays by their golden costs in the "
                                "recurrence, which does not apply: " +
                                *why);
  RtuRun run = runAnalytic(memory, records, ideal);
  run.statistics.model = "golden";
  return run;
}

RtuRun runModel(ModelKind model, const WordMemory& memory, const std::vector<HostRecord>& records,
                const RtuConfig& config, const RunProgress& progress) {
  switch (model) {
    case ModelKind::Golden: return runGoldenTimed(memory, records, config);
    case ModelKind::LooselyTimed: return runLooselyTimed(memory, records, config, progress);
    case ModelKind::CycleAccurate: break;
  }
  return simulateRtu(memory, records, config, progress);
}

namespace {

// Hands a run's results to `take` in the host's order, then lets go of them and their columns.
RtuRun handedOver(RtuRun run, const ResultTaker& take) {
  for (size_t i = 0; i < run.results.size(); ++i) take(run.jobIndices[i], run.results[i]);
  RtuRun rest;
  rest.totalCycles = run.totalCycles;
  rest.statistics = std::move(run.statistics);
  rest.snapshots = std::move(run.snapshots);
  rest.traceBytes = run.traceBytes;
  rest.timelineBytes = run.timelineBytes;
  return rest;
}

}  // namespace

RtuRun runFrame(ModelKind model, const WordMemory& memory, const RecordSource& records,
                const RtuConfig& config, const ResultTaker& take, const RunProgress& progress) {
  switch (model) {
    case ModelKind::Golden: {
      if (const std::vector<HostRecord>* held = records.vector())
        return handedOver(runGoldenTimed(memory, *held, config), take);
      return handedOver(runGoldenTimed(memory, records.all(), config), take);
    }
    case ModelKind::LooselyTimed:
      return streamLooselyTimed(memory, records, config, take, progress);
    case ModelKind::CycleAccurate: break;
  }
  return streamRtu(memory, records, config, take, progress);
}

RtuRun runModel(ModelKind model, const WordMemory& memory, const std::vector<TValueRecord>& jobs,
                const RtuConfig& config, const RunProgress& progress) {
  return runModel(model, memory, std::vector<HostRecord>(jobs.begin(), jobs.end()), config,
                  progress);
}

}  // namespace rtu
