#include "run/analytic_run.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>

#include "kinds/svo/golden_model.h"
#include "kinds/svo/job_setup.h"
#include "rtu/rtu_recurrence.h"
#include "run/recurrence_results.h"

namespace rtu {
namespace {

// Each record's result and its timing inputs: the job manager's set-up and latencies
// (src/kinds/svo/job_setup.h), the golden model's result and cost.
class RecordTracer {
 public:
  RecordTracer(const WordMemory& memory, const RtuConfig& config)
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
RtuRun analyticRun(const WordMemory& memory, const std::vector<Record>& records,
                   const RtuConfig& config) {
  validate(config);
  if (const auto why = whyNotAnalytic(config))
    throw std::invalid_argument("the analytic model does not apply: " + *why);
  const auto start = std::chrono::steady_clock::now();
  RecordTracer traced(memory, config);
  traced.results.reserve(records.size());
  traced.timing.reserve(records.size());
  for (const Record& record : records) traced.trace(record);
  RecurrenceRun timing =
      runRecurrence(traced.timing, RecurrenceConfig{config.cores, config.scheduler,
                                                    config.hostInput, config.outputLink()});
  RtuRun run = recurrenceResults(std::move(timing), std::move(traced.results), {}, config);
  run.statistics.model = "recurrence";
  run.statistics.hostSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace

RtuRun runAnalytic(const WordMemory& memory, const std::vector<TraversalJob>& jobs,
                   const RtuConfig& config) {
  return analyticRun(memory, jobs, config);
}

RtuRun runAnalytic(const WordMemory& memory, const std::vector<HostRecord>& records,
                   const RtuConfig& config) {
  return analyticRun(memory, records, config);
}

}  // namespace rtu
