#include "run/rtu_simulation.h"

#include <chrono>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include <systemc>

#include "run/warm_frames.h"
#include "sim/ca/rtu_top.h"
#include "sim/kernel/sc_kernel.h"

namespace rtu {
namespace {

// Simulates until no event is left. With a progress callback it stops every 2^18 cycles to report;
// with a trace every TraceOptions::flushCycles to write the cycles that are final, which bounds
// the trace's memory; with snapshots every BlockRun::everyCycles until the last is taken.
// Stopping and resuming does not change what happens in any cycle.
class RunLoop {
 public:
  enum class End { Finished, LastSnapshot, CountedWindow };

  RunLoop(RtuTop& top, const RtuConfig& config, CycleTrace* trace, const RunProgress& progress,
          const BlockRun& plan, std::vector<RunSnapshot>& snapshots)
      : top_(top),
        config_(config),
        clock_(CycleClock::atMegahertz(config.clockMhz)),
        trace_(trace),
        progress_(progress),
        plan_(plan),
        snapshots_(snapshots) {}

  End run() {
    if (!progress_ && !trace_ && plan_.afterResults.empty()) {
      simulate();
      return End::Finished;
    }
    uint64_t nextProgress = kProgressCycles;
    do {
      simulateFor(clock_.period() * static_cast<double>(slice()));
      const uint64_t now = clock_.now();
      // Modules record no cycle before the current one any more (src/trace/cycle_trace.h).
      if (trace_) trace_->flush(now);
      if (countedAll(now)) return End::CountedWindow;
      if (progress_ && now >= nextProgress) {
        progress_(top_.sink().arrivedBefore(now), top_.sink().expected());
        nextProgress = (now / kProgressCycles + 1) * kProgressCycles;
      }
      if (takeSnapshots(now) && plan_.stopAtLast) return End::LastSnapshot;
      // The modules decide ahead of simulated time: go on until it has passed the last result.
    } while (sc_core::sc_pending_activity() || clock_.now() <= top_.sink().lastArrival());
    return End::Finished;
  }

 private:
  static constexpr uint64_t kProgressCycles = uint64_t{1} << 18;

  uint64_t slice() const {
    if (snapshots_.size() < plan_.afterResults.size())
      return std::max<uint64_t>(1, plan_.everyCycles);
    if (!trace_) return kProgressCycles;
    return config_.trace ? config_.trace->flushCycles : TraceOptions{}.flushCycles;
  }

  // A run that only counts a windowed trace's and timeline's bytes has counted them all once the
  // trace's window has passed (no record after it reaches the file) and the timeline has heard
  // its window and the rays that started in it.
  bool countedAll(uint64_t now) const {
    const bool traceCounted = !config_.trace ||
                              (config_.trace->countOnly && now >= config_.trace->toCycle);
    const bool timelineCounted = !config_.timeline.wanted() ||
                                 (config_.timeline.countOnly && trace_->listenersSatisfied());
    return (config_.trace || config_.timeline.wanted()) && traceCounted && timelineCounted;
  }

  // True once the last snapshot is taken.
  bool takeSnapshots(uint64_t now) {
    // Results arrive in their cycle, which the modules may have decided ahead of simulated time.
    const uint64_t results = top_.sink().arrivedBefore(now > 0 ? now - 1 : 0);
    while (snapshots_.size() < plan_.afterResults.size() &&
           results >= plan_.afterResults[snapshots_.size()])
      snapshots_.push_back({now, results, collectStatistics(top_, config_, now)});
    return !plan_.afterResults.empty() && snapshots_.size() == plan_.afterResults.size();
  }

  RtuTop& top_;
  const RtuConfig& config_;
  CycleClock clock_;
  CycleTrace* trace_;
  const RunProgress& progress_;
  const BlockRun& plan_;
  std::vector<RunSnapshot>& snapshots_;
};

// A trace when the run writes or counts one, a timeline, or has listeners: the file is optional.
std::unique_ptr<CycleTrace> openTrace(const RtuConfig& config,
                                      std::vector<TraceListener*> listeners) {
  if (!config.trace && listeners.empty()) return nullptr;
  TraceOptions options = config.trace.value_or(TraceOptions{});
  options.periodPs = CycleClock::atMegahertz(config.clockMhz).period().value();
  return std::make_unique<CycleTrace>(options, std::move(listeners));
}

// The caches of a whole frame's warm frames (none without them): the warmer walks a vector of
// records, so made records are made for it into one (warm frames hold the frame's records).
std::optional<CacheContents> warmFramesOf(const WordMemory& memory, const RecordSource& records,
                                          const RtuConfig& config) {
  if (config.warmFrames <= 0 || config.memory.ideal) return std::nullopt;
  if (const std::vector<HostRecord>* held = records.vector())
    return warmedCaches(memory, *held, config);
  return warmedCaches(memory, records.all(), config);
}

// What a streaming run counts of its results as they leave (the statistics of the rest come from
// the top, as collectStatistics takes them).
class CountingTaker {
 public:
  explicit CountingTaker(const ResultTaker& take) : take_(take) {}
  HostSink::Take sinkTake() {
    if (!take_) return {};
    return [this](uint64_t, const CoreResult& result) {
      counted_.count(result.result, result.blockedCycles);
      take_(result.ids.ray, result.result);
    };
  }
  const RtuStatistics& counted() const { return counted_; }

 private:
  const ResultTaker& take_;
  RtuStatistics counted_;
};

RtuRun simulate(const WordMemory& memory, const RecordSource& records, const RtuConfig& config,
                const RunProgress& progress, std::vector<TraceListener*> listeners,
                const BlockRun& plan, const std::vector<SceneInstance>* scene = nullptr,
                const ResultTaker& take = {}) {
  validate(config);
  checkCoreTakes(config.core, records);
  if (scene && config.warmFrames > 0)
    throw std::invalid_argument("warm_frames: a scene's frames (animate) run back to back already; "
                                "set warm_frames to 0");
  // A sampled block brings its own caches; a whole frame, those of its warm frames.
  const std::optional<CacheContents> warmed =
      plan.startCaches ? std::nullopt : warmFramesOf(memory, records, config);
  const CacheContents* startCaches = warmed ? &*warmed : plan.startCaches;
  freshKernel();
  std::unique_ptr<TimelineWriter> timeline;
  if (config.timeline.wanted()) {
    timeline = std::make_unique<TimelineWriter>(
        config.timeline, CycleClock::atMegahertz(config.clockMhz).period().value(),
        withCoreKind(config.core, [](auto kind) { return decltype(kind)::vocabulary(); }));
    listeners.push_back(timeline.get());
  }
  std::unique_ptr<CycleTrace> trace = openTrace(config, std::move(listeners));
  CountingTaker counting(take);
  auto top = std::make_unique<RtuTop>("rtu", config, memory, records, trace.get(), startCaches,
                                      scene, counting.sinkTake());
  if (trace) trace->checkScopesMatched();

  RtuRun run;
  const auto start = std::chrono::steady_clock::now();
  const RunLoop::End end = RunLoop(*top, config, trace.get(), progress, plan, run.snapshots).run();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (end == RunLoop::End::LastSnapshot) return run;
  run.simulatedCycles = CycleClock::atMegahertz(config.clockMhz).now();
  if (end == RunLoop::End::CountedWindow) {
    trace->finish(0);
    run.traceBytes = trace->countedBytes();
    if (timeline) run.timelineBytes = timeline->bytes();
    return run;
  }

  HostSink& sink = top->sink();
  sink.arrange();
  // Before the stall check: the trace of a stalled run shows why. The marker: the first result.
  if (trace) trace->finish(sink.firstArrival());
  if (!sink.complete())
    throw std::runtime_error("simulation stalled after " + std::to_string(sink.received()) +
                             " of " + std::to_string(records.size()) + " results");
  run.totalCycles = sink.received() == 0 ? 0 : sink.lastArrival() + 1;
  if (top->sceneManager()) run.jobIssueCycles = top->sceneManager()->issueCycles();
  run.statistics = collectStatistics(*top, config, run.totalCycles);
  run.statistics.addCounts(counting.counted());
  run.statistics.hostSeconds = seconds;
  HostSink::Arrivals arrivals = sink.takeArrivals();
  run.arrivalCycles = std::move(arrivals.cycles);
  run.results = std::move(arrivals.results);
  run.jobIndices = std::move(arrivals.rays);
  run.blockedCycles = std::move(arrivals.blockedCycles);
  run.instances = std::move(arrivals.instances);
  if (trace) run.traceBytes = trace->countedBytes();
  if (timeline) run.timelineBytes = timeline->bytes();
  return run;
}

}  // namespace

RtuRun simulateRtu(const WordMemory& memory, const std::vector<TValueRecord>& jobs,
                   const RtuConfig& config, const RunProgress& progress) {
  return simulateRtu(memory, std::vector<HostRecord>(jobs.begin(), jobs.end()), config, progress);
}

RtuRun simulateRtu(const WordMemory& memory, const std::vector<HostRecord>& records,
                   const RtuConfig& config, const RunProgress& progress,
                   std::vector<TraceListener*> listeners) {
  return simulate(memory, records, config, progress, std::move(listeners), BlockRun{});
}

RtuRun streamRtu(const WordMemory& memory, const RecordSource& records, const RtuConfig& config,
                 const ResultTaker& take, const RunProgress& progress) {
  return simulate(memory, records, config, progress, {}, BlockRun{}, nullptr, take);
}

RtuRun simulateRtu(const WordMemory& memory, const std::vector<HostRecord>& records,
                   const RtuConfig& config, const BlockRun& block) {
  return simulate(memory, records, config, {}, {}, block);
}

RtuRun simulateScene(const WordMemory& memory, const std::vector<RayRecord>& rays,
                     const std::vector<SceneInstance>& scene, const RtuConfig& config,
                     const RunProgress& progress) {
  return simulate(memory, std::vector<HostRecord>(rays.begin(), rays.end()), config, progress, {},
                  BlockRun{}, &scene);
}

std::vector<CoreKindResult> resultsInJobOrder(const RtuRun& run) {
  std::vector<CoreKindResult> ordered(run.results.size());
  for (size_t i = 0; i < run.results.size(); ++i) ordered[run.jobIndices[i]] = run.results[i];
  return ordered;
}

}  // namespace rtu
