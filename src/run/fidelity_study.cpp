#include "run/fidelity_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "kinds/core_result.h"
#include "run/analytic_run.h"
#include "run/lt_simulation.h"

namespace rtu {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Each ray's cycles in job order: its traversal states and its cycles blocked on memory.
std::vector<double> rayCycles(const RtuRun& run) {
  std::vector<double> cycles(run.results.size());
  for (size_t i = 0; i < run.results.size(); ++i)
    cycles[run.jobIndices[i]] =
        static_cast<double>(resultCost(run.results[i])) + run.blockedCycles[i];
  return cycles;
}

class Study {
 public:
  Study(const WordMemory& memory, const std::vector<HostRecord>& jobs, const RtuConfig& config)
      : memory_(memory), jobs_(jobs), config_(config) {
    const auto start = std::chrono::steady_clock::now();
    golden_ = traceGolden(memory, jobs, config);
    goldenSeconds_ = secondsSince(start);
  }

  ModeFidelity exact(const std::string& mode, const RtuRun& run, double seconds) {
    ModeFidelity m = timed(mode, seconds, static_cast<double>(run.totalCycles), run.statistics);
    const auto [mean, p99] = perRayErrors(rayCycles(run), referenceCycles_);
    m.perRayErrorMean = mean;
    m.perRayErrorP99 = p99;
    m.resultsEqualGolden = resultsInJobOrder(run) == golden_;
    return m;
  }

  ModeFidelity systemc() {
    const auto start = std::chrono::steady_clock::now();
    const RtuRun run = simulateRtu(memory_, jobs_, config_);
    const double seconds = secondsSince(start);
    reference_ = run.statistics;
    referenceSeconds_ = seconds;
    referenceCycles_ = rayCycles(run);
    return exact("systemc", run, seconds);
  }

  std::optional<ModeFidelity> recurrence() {
    if (whyNotAnalytic(config_)) return std::nullopt;
    const auto start = std::chrono::steady_clock::now();
    const RtuRun run = runAnalytic(memory_, jobs_, config_);
    return exact("recurrence", run, secondsSince(start));
  }

  ModeFidelity looselyTimed(uint64_t quantum) {
    RtuConfig config = config_;
    config.ltQuantum = quantum;
    const RtuRun run = runLooselyTimed(memory_, jobs_, config);
    return exact("lt q" + std::to_string(quantum), run, run.statistics.hostSeconds);
  }

  ModeFidelity sampled(double fraction, SampleSpec spec) {
    spec.fraction = fraction;
    const SampledRun run = runSampled(memory_, jobs_, config_, spec);
    char name[32];
    std::snprintf(name, sizeof name, "sampled %g", fraction);
    ModeFidelity m = timed(name, run.hostSeconds, run.totalCycles.estimate, run.counted);
    m.totalCyclesInterval = run.totalCycles;
    if (!config_.memory.ideal) setHitRates(m, run.l1HitRate.estimate, run.l2HitRate.estimate);
    return m;
  }

  ModeFidelity golden() {
    ModeFidelity m = base("golden", goldenSeconds_);
    std::vector<double> costs(golden_.size());
    for (size_t i = 0; i < golden_.size(); ++i) costs[i] = resultCost(golden_[i]);
    const auto [mean, p99] = perRayErrors(costs, referenceCycles_);
    m.perRayErrorMean = mean;
    m.perRayErrorP99 = p99;
    m.resultsEqualGolden = true;
    return m;
  }

 private:
  ModeFidelity base(const std::string& mode, double seconds) const {
    ModeFidelity m;
    m.mode = mode;
    m.hostSeconds = seconds;
    m.raysPerHostSecond = seconds > 0 ? static_cast<double>(jobs_.size()) / seconds : 0.0;
    m.speedUp = seconds > 0 ? referenceSeconds_ / seconds : 0.0;
    return m;
  }

  ModeFidelity timed(const std::string& mode, double seconds, double cycles,
                     const RtuStatistics& statistics) const {
    ModeFidelity m = base(mode, seconds);
    m.totalCycles = cycles;
    m.totalCyclesError = cycles / static_cast<double>(reference_.totalCycles) - 1;
    if (!config_.memory.ideal)
      setHitRates(m, hitRate(statistics.allL1()), hitRate(statistics.l2.cache));
    return m;
  }

  void setHitRates(ModeFidelity& m, double l1, double l2) const {
    m.l1HitRate = l1;
    m.l2HitRate = l2;
    m.l1Error = 100 * (l1 - hitRate(reference_.allL1()));
    m.l2Error = 100 * (l2 - hitRate(reference_.l2.cache));
  }

  const WordMemory& memory_;
  const std::vector<HostRecord>& jobs_;
  const RtuConfig& config_;
  std::vector<CoreKindResult> golden_;
  double goldenSeconds_ = 0, referenceSeconds_ = 0;
  RtuStatistics reference_;
  std::vector<double> referenceCycles_;
};

}  // namespace

std::pair<double, double> perRayErrors(const std::vector<double>& mode,
                                       const std::vector<double>& reference) {
  std::vector<double> errors(mode.size());
  double sum = 0;
  for (size_t i = 0; i < mode.size(); ++i) {
    errors[i] = reference[i] > 0 ? std::abs(mode[i] - reference[i]) / reference[i] : 0.0;
    sum += errors[i];
  }
  if (errors.empty()) return {0, 0};
  const size_t p99 = std::min(errors.size() - 1, errors.size() * 99 / 100);
  std::nth_element(errors.begin(), errors.begin() + static_cast<ptrdiff_t>(p99), errors.end());
  return {sum / static_cast<double>(errors.size()), errors[p99]};
}

std::vector<ModeFidelity> measureFidelity(const WordMemory& memory,
                                          const std::vector<HostRecord>& jobs,
                                          const RtuConfig& config,
                                          const std::vector<uint64_t>& quanta,
                                          const std::vector<double>& fractions, SampleSpec sample) {
  Study study(memory, jobs, config);
  std::vector<ModeFidelity> modes{study.systemc()};
  if (auto recurrence = study.recurrence()) modes.push_back(*recurrence);
  for (uint64_t quantum : quanta) modes.push_back(study.looselyTimed(quantum));
  for (double fraction : fractions) modes.push_back(study.sampled(fraction, sample));
  modes.push_back(study.golden());
  return modes;
}

}  // namespace rtu
