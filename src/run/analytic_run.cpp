#include "run/analytic_run.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>

#include "kinds/core_result.h"
#include "kinds/registry.h"
#include "rtu/golden_shell.h"
#include "rtu/rtu_recurrence.h"
#include "run/recurrence_results.h"

namespace rtu {
namespace {

// Each record's result and its timing inputs.
struct Traced {
  std::vector<CoreKindResult> results;
  std::vector<JobTiming> timing;
};

// Traces records on a core of `Kind`: the kind's job set-up with the job manager's latencies,
// then the kind's behaviour in the untimed shell for the result and its cost.
template <class Kind>
class RecordTracer {
 public:
  RecordTracer(const WordMemory& memory, const RtuConfig& config)
      : setup_(memory, config.jobManager, config.coreConfig<Kind>()),
        shell_(memory, config.coreConfig<Kind>()) {}

  void trace(const HostRecord& record) {
    const JobSetUp<typename Kind::Job> set = setUpHostRecord<Kind>(setup_, record);
    typename Kind::Result& result = emplaceBackResult<Kind>(traced.results);
    shell_.run(set.idWord, set.job, result);
    traced.timing.push_back(JobTiming{Kind::resultCost(result), set.latency, set.headerFetch});
  }

  Traced traced;

 private:
  typename Kind::Setup setup_;
  GoldenShell<Kind> shell_;
};

template <class Kind, typename Record>
Traced traceRecords(const WordMemory& memory, const std::vector<Record>& records,
                    const RtuConfig& config) {
  RecordTracer<Kind> tracer(memory, config);
  tracer.traced.results.reserve(records.size());
  tracer.traced.timing.reserve(records.size());
  for (const Record& record : records) tracer.trace(record);
  return std::move(tracer.traced);
}

// Traces each record and hands its result on: the tracer's columns hold one record's at a time.
template <class Kind>
void streamRecords(const WordMemory& memory, const RecordSource& records, const RtuConfig& config,
                   const ResultTaker& take) {
  RecordTracer<Kind> tracer(memory, config);
  for (uint64_t i = 0; i < records.size(); ++i) {
    tracer.trace(records[i]);
    take(i, tracer.traced.results.back());
    tracer.traced.results.clear();
    tracer.traced.timing.clear();
  }
}

}  // namespace

void traceGolden(const WordMemory& memory, const RecordSource& records, const RtuConfig& config,
                 const ResultTaker& take) {
  checkCoreTakes(config.core, records);
  withCoreKind(config.core,
               [&](auto kind) { streamRecords<decltype(kind)>(memory, records, config, take); });
}

std::vector<CoreKindResult> traceGolden(const WordMemory& memory,
                                        const std::vector<HostRecord>& records,
                                        const RtuConfig& config) {
  return withCoreKind(config.core, [&](auto kind) {
    return traceRecords<decltype(kind)>(memory, records, config).results;
  });
}

std::optional<std::string> whyNotAnalytic(const RtuConfig& config) {
  if (!config.memory.ideal) return "the memory is cached";
  if (config.reorderCapacity > 0) return "results pass a reorder buffer";
  if (config.trianglesShared())
    return "cores share triangle units (core.triangle.shared_by): a test may wait for another "
           "core's";
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
  Traced traced = withCoreKind(config.core, [&](auto kind) {
    return traceRecords<decltype(kind)>(memory, records, config);
  });
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

RtuRun runAnalytic(const WordMemory& memory, const std::vector<TValueRecord>& jobs,
                   const RtuConfig& config) {
  return analyticRun(memory, jobs, config);
}

RtuRun runAnalytic(const WordMemory& memory, const std::vector<HostRecord>& records,
                   const RtuConfig& config) {
  checkCoreTakes(config.core, records);
  return analyticRun(memory, records, config);
}

}  // namespace rtu
