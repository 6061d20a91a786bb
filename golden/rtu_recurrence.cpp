#include "rtu_recurrence.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <set>
#include <stdexcept>
#include <utility>

namespace rtu {

void RecurrenceConfig::validate() const {
  if (cores < 1) throw std::invalid_argument("the recurrence needs at least one core");
  rtu::validate(hostInput, "host input");
  rtu::validate(hostOutput, "host output");
  if (hostInput.activeProbability < 1.0 || hostOutput.activeProbability < 1.0)
    throw std::invalid_argument("the recurrence cannot model randomly inactive host links");
}

namespace {

constexpr uint64_t kUnknown = std::numeric_limits<uint64_t>::max();
constexpr size_t kNoJob = std::numeric_limits<size_t>::max();

// The result buffers and the output link: drains are found in cycle order.
class Drains {
 public:
  Drains(int cores, HostLinkConfig output)
      : cores_(static_cast<uint64_t>(cores)), link_(output), bufferedFrom_(cores_, 0) {}

  // The buffer of `core` holds a result from cycle `from`.
  void add(int core, uint64_t from) {
    bufferedFrom_[static_cast<size_t>(core)] = from;
    if (from <= linkReadyFrom_)
      ready_.insert(core);
    else
      later_.insert({from, core});
  }
  bool empty() const { return ready_.empty() && later_.empty(); }

  // The next drain: its cycle and core (the buffer whose select cycle comes first once both the
  // result is buffered and the link is ready).
  std::pair<uint64_t, int> next() {
    while (!later_.empty() && later_.begin()->first <= linkReadyFrom_) {
      ready_.insert(later_.begin()->second);
      later_.erase(later_.begin());
    }
    std::pair<uint64_t, int> best{kUnknown, -1};
    if (!ready_.empty()) {
      const int selected = static_cast<int>(linkReadyFrom_ % cores_);
      auto it = ready_.lower_bound(selected);
      if (it == ready_.end()) it = ready_.begin();
      best = {firstSelect(linkReadyFrom_, *it), *it};
    }
    // Buffered later than the link is ready: each drains within N cycles of being buffered.
    for (const auto& [from, core] : later_) {
      if (from >= best.first) break;
      best = std::min(best, std::pair<uint64_t, int>{firstSelect(from, core), core});
    }
    return best;
  }

  void take(uint64_t cycle, int core) {
    ready_.erase(core);
    later_.erase({bufferedFrom_[static_cast<size_t>(core)], core});
    linkReadyFrom_ = link_.nextAllowed(cycle);
  }

 private:
  // The first cycle >= from in which the select counter shows `core`.
  uint64_t firstSelect(uint64_t from, int core) const {
    return from + (static_cast<uint64_t>(core) + cores_ - from % cores_) % cores_;
  }

  uint64_t cores_;
  HostLinkPacer link_;
  uint64_t linkReadyFrom_ = 0;
  std::vector<uint64_t> bufferedFrom_;        // per core with a buffered result
  std::set<int> ready_;                       // buffered by the time the link is ready
  std::set<std::pair<uint64_t, int>> later_;  // (buffered from, core)
};

class Recurrence {
 public:
  Recurrence(const std::vector<RecurrenceJob>& jobs, const RecurrenceConfig& config)
      : jobs_(jobs),
        config_(config),
        cores_(static_cast<uint64_t>(config.cores)),
        inputLink_(config.hostInput),
        drains_(config.cores, config.hostOutput),
        idleFrom_(cores_, 0),
        waiting_(cores_, kNoJob),
        buffered_(cores_, kNoJob),
        lastDrain_(cores_, kUnknown) {
    const size_t n = jobs.size();
    run_.acceptCycles.resize(n);
    run_.pendingCycles.resize(n);
    run_.dispatchCycles.resize(n);
    run_.cores.resize(n);
    run_.handoverCycles.resize(n);
    run_.drainCycles.resize(n);
  }

  RecurrenceRun run() {
    for (size_t i = 0; i < jobs_.size(); ++i) {
      enterPipeline(i);
      dispatch(i);
    }
    while (!drains_.empty()) drainNext();
    run_.hostOrder.resize(jobs_.size());
    std::iota(run_.hostOrder.begin(), run_.hostOrder.end(), size_t{0});
    std::sort(run_.hostOrder.begin(), run_.hostOrder.end(),
              [this](size_t a, size_t b) { return run_.drainCycles[a] < run_.drainCycles[b]; });
    run_.totalCycles = jobs_.empty() ? 0 : run_.drainCycles[run_.hostOrder.back()] + 1;
    return std::move(run_);
  }

 private:
  // c_i and A_i.
  void enterPipeline(size_t i) {
    uint64_t accept = i == 0 ? 0 : inputLink_.nextAllowed(run_.acceptCycles[i - 1]);
    accept = std::max(accept, fetchUntil_);
    while (inPipeline_ < i && run_.dispatchCycles[inPipeline_] <= accept) ++inPipeline_;
    if (inPipeline_ < i && run_.pendingCycles[inPipeline_] <= accept)
      accept = run_.dispatchCycles[inPipeline_++];  // the pipeline is held until that dispatch
    uint64_t stalls = 0;
    for (size_t k = inPipeline_; k < i; ++k) stalls += run_.dispatchCycles[k] - run_.pendingCycles[k];
    uint64_t pending = accept + jobs_[i].pipelineCycles + stalls;
    if (i > 0) pending = std::max(pending, run_.dispatchCycles[i - 1] + 1);
    if (jobs_[i].headerFetch > 0) fetchUntil_ = accept + 1 + jobs_[i].headerFetch;
    run_.acceptCycles[i] = accept;
    run_.pendingCycles[i] = pending;
  }

  // D_i and the core, then the core's handover if its result buffer is free.
  void dispatch(size_t i) {
    uint64_t cycle = run_.pendingCycles[i];
    int core = -1;
    switch (config_.policy) {
      case SchedulerPolicy::CyclicFirstAvailable:
        for (;; ++cycle) {
          drainBefore(cycle);
          core = static_cast<int>(cycle % cores_);
          if (idleFrom_[static_cast<size_t>(core)] <= cycle) break;
        }
        break;
      case SchedulerPolicy::FirstAvailable:
        for (;; ++cycle) {
          drainBefore(cycle);
          core = lowestIdle(cycle);
          if (core >= 0) break;
        }
        break;
      case SchedulerPolicy::RoundRobin:
        core = nextInTurn_;
        while (idleFrom_[static_cast<size_t>(core)] == kUnknown) drainNext();
        cycle = std::max(cycle, idleFrom_[static_cast<size_t>(core)]);
        nextInTurn_ = (core + 1) % config_.cores;
        break;
    }
    run_.dispatchCycles[i] = cycle;
    run_.cores[i] = core;
    const size_t c = static_cast<size_t>(core);
    waiting_[c] = i;
    idleFrom_[c] = kUnknown;
    if (buffered_[c] == kNoJob) handOver(core);
  }

  int lowestIdle(uint64_t cycle) const {
    for (size_t core = 0; core < cores_; ++core)
      if (idleFrom_[core] <= cycle) return static_cast<int>(core);
    return -1;
  }

  // The waiting result of `core` moves into its (free) buffer.
  void handOver(int core) {
    const size_t c = static_cast<size_t>(core);
    const size_t job = waiting_[c];
    const uint64_t out = run_.dispatchCycles[job] + 1 + jobs_[job].cost;
    const uint64_t handover = lastDrain_[c] == kUnknown ? out : std::max(out, lastDrain_[c] + 1);
    run_.handoverCycles[job] = handover;
    idleFrom_[c] = handover + 1;
    waiting_[c] = kNoJob;
    buffered_[c] = job;
    drains_.add(core, handover + 1);
  }

  // Every drain before `cycle`: those decide which cores are idle by then. Later jobs cannot add
  // one, as their results are buffered after their dispatch.
  void drainBefore(uint64_t cycle) {
    while (!drains_.empty() && drains_.next().first < cycle) drainNext();
  }

  void drainNext() {
    const auto [cycle, core] = drains_.next();
    const size_t c = static_cast<size_t>(core);
    drains_.take(cycle, core);
    run_.drainCycles[buffered_[c]] = cycle;
    buffered_[c] = kNoJob;
    lastDrain_[c] = cycle;
    if (waiting_[c] != kNoJob) handOver(core);
  }

  const std::vector<RecurrenceJob>& jobs_;
  const RecurrenceConfig& config_;
  const uint64_t cores_;
  HostLinkPacer inputLink_;
  Drains drains_;
  std::vector<uint64_t> idleFrom_;  // per core: idle from this cycle on (kUnknown: not yet known)
  std::vector<size_t> waiting_;     // per core: job whose result waits in the core (kNoJob: none)
  std::vector<size_t> buffered_;    // per core: job whose result is in the result buffer
  std::vector<uint64_t> lastDrain_;
  uint64_t fetchUntil_ = 0;
  size_t inPipeline_ = 0;  // the oldest job not yet dispatched when the current one entered
  int nextInTurn_ = 0;
  RecurrenceRun run_;
};

}  // namespace

RecurrenceRun runRecurrence(const std::vector<RecurrenceJob>& jobs, const RecurrenceConfig& config) {
  config.validate();
  return Recurrence(jobs, config).run();
}

}  // namespace rtu
