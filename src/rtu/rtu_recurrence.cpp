#include "rtu/rtu_recurrence.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <queue>
#include <stdexcept>
#include <utility>

#include "base/modulo.h"
#include "base/prefault.h"
#include "rtu/scheduler_choice.h"

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

// Room for `n` values, its pages mapped at once (prefault.h): a frame's columns are large.
template <typename T>
void reserveMapped(std::vector<T>& column, size_t n) {
  column.reserve(n);
  prefaultCapacity(column);
}

// The result buffers and the output link: drains are found in cycle order. A buffer of core x
// filled from cycle f drains in the first cycle >= max(f, r) whose select counter shows x, with
// r the first cycle the link is ready. While r <= f that cycle is fixed, so such buffers wait in
// a heap by it; once r passes it, they all compete from r on, in the select counter's order.
class Drains {
 public:
  Drains(int cores, HostLinkConfig output)
      : cores_(static_cast<uint64_t>(cores)),
        select_(cores_),
        link_(output),
        compete_((cores_ + 63) / 64, 0) {}

  // The buffer of `core` holds a result from cycle `from`.
  void add(int core, uint64_t from) {
    byCycle_.emplace(firstSelect(from, core), core);
    next_.reset();
  }
  bool empty() const { return byCycle_.empty() && competing_ == 0; }

  // The next drain: its cycle and core.
  std::pair<uint64_t, int> next() {
    if (!next_) next_ = find();
    return *next_;
  }

  void take(const std::pair<uint64_t, int>& drain) {
    if (!byCycle_.empty() && byCycle_.top() == drain)
      byCycle_.pop();
    else
      setCompeting(drain.second, false);
    linkReadyFrom_ = link_.nextAllowed(drain.first);
    next_.reset();
  }

 private:
  using Candidate = std::pair<uint64_t, int>;  // (drain cycle, core)

  std::pair<uint64_t, int> find() {
    while (!byCycle_.empty() && byCycle_.top().first < linkReadyFrom_) {
      setCompeting(byCycle_.top().second, true);
      byCycle_.pop();
    }
    Candidate best{kUnknown, -1};
    if (!byCycle_.empty()) best = byCycle_.top();
    if (competing_ > 0) {
      const int core = firstCompetingFrom(static_cast<int>(select_.of(linkReadyFrom_)));
      best = std::min(best, Candidate{firstSelect(linkReadyFrom_, core), core});
    }
    return best;
  }

  // The first cycle >= from in which the select counter shows `core`.
  uint64_t firstSelect(uint64_t from, int core) const {
    const uint64_t shown = select_.of(from), wanted = static_cast<uint64_t>(core);
    return from + (wanted >= shown ? wanted - shown : wanted + cores_ - shown);
  }

  void setCompeting(int core, bool on) {
    uint64_t& word = compete_[static_cast<size_t>(core) / 64];
    const uint64_t bit = uint64_t{1} << (core % 64);
    competing_ += on ? 1 : -1;
    word = on ? word | bit : word & ~bit;
  }

  // The first competing core from `start` on, cyclically.
  int firstCompetingFrom(int start) const {
    const size_t words = compete_.size();
    const size_t first = static_cast<size_t>(start) / 64;
    for (size_t n = 0; n <= words; ++n) {
      const size_t w = first + n < words ? first + n : first + n - words;
      uint64_t word = compete_[w];
      if (n == 0) word &= ~uint64_t{0} << (start % 64);
      if (n == words) word &= (uint64_t{1} << (start % 64)) - 1;
      if (word != 0) return static_cast<int>(w * 64 + static_cast<size_t>(__builtin_ctzll(word)));
    }
    return -1;
  }

  uint64_t cores_;
  Modulo select_;  // the select counter's core in a cycle
  HostLinkPacer link_;
  uint64_t linkReadyFrom_ = 0;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<>> byCycle_;
  std::vector<uint64_t> compete_;  // bit per core: its buffer waits for the link
  int competing_ = 0;
  std::optional<Candidate> next_;
};

class Recurrence {
 public:
  Recurrence(size_t jobs, const JobSource& jobAt, const RecurrenceConfig& config,
             const TraversalTimer& timer)
      : jobs_(jobs),
        jobAt_(jobAt),
        config_(config),
        timer_(timer),
        cores_(static_cast<uint64_t>(config.cores)),
        inputLink_(config.hostInput),
        drains_(config.cores, config.hostOutput),
        idleFrom_(cores_, 0),
        waiting_(cores_, kNoJob),
        waitingFrom_(cores_, 0),
        buffered_(cores_, kNoJob),
        lastDrain_(cores_, kUnknown),
        choice_(config.policy, config.cores) {
    // Columns written in job order are appended; handovers and drains come out of order.
    for (auto* column : {&run_.acceptCycles, &run_.pendingCycles, &run_.dispatchCycles,
                         &run_.handoverCycles, &run_.drainCycles})
      reserveMapped(*column, jobs);
    reserveMapped(run_.cores, jobs);
    reserveMapped(run_.hostOrder, jobs);
    run_.handoverCycles.resize(jobs);
    run_.drainCycles.resize(jobs);
  }

  RecurrenceRun run() {
    for (size_t i = 0; i < jobs_; ++i) {
      const JobTiming job = jobAt_(i);
      enterPipeline(i, job);
      dispatch(i, job.cost);
    }
    while (!drains_.empty()) drainNext();  // drains come in cycle order
    run_.totalCycles = jobs_ == 0 ? 0 : run_.drainCycles[run_.hostOrder.back()] + 1;
    return std::move(run_);
  }

 private:
  // c_i and A_i.
  void enterPipeline(size_t i, const JobTiming& job) {
    uint64_t accept = i == 0 ? 0 : inputLink_.nextAllowed(run_.acceptCycles[i - 1]);
    accept = std::max(accept, fetchUntil_);
    while (inPipeline_ < i && run_.dispatchCycles[inPipeline_] <= accept) ++inPipeline_;
    if (inPipeline_ < i && run_.pendingCycles[inPipeline_] <= accept)
      accept = run_.dispatchCycles[inPipeline_++];  // the pipeline is held until that dispatch
    uint64_t stalls = 0;
    for (size_t k = inPipeline_; k < i; ++k)
      stalls += run_.dispatchCycles[k] - run_.pendingCycles[k];
    uint64_t pending = accept + job.pipelineCycles + stalls;
    if (i > 0) pending = std::max(pending, run_.dispatchCycles[i - 1] + 1);
    if (job.headerFetch > 0) fetchUntil_ = accept + 1 + job.headerFetch;
    run_.acceptCycles.push_back(accept);
    run_.pendingCycles.push_back(pending);
  }

  // What the recurrence knows of the cores, as the policy's query (scheduler_choice.h): every
  // drain before a cycle decides which cores are idle by then; a busy core's idle cycle is known
  // once its result drained.
  struct CoreQuery {
    Recurrence& r;
    Idle in(int core, uint64_t cycle) {
      r.drainBefore(cycle);
      return r.idleFrom_[static_cast<size_t>(core)] <= cycle ? Idle::Yes : Idle::No;
    }
    uint64_t from(int core) {
      while (r.idleFrom_[static_cast<size_t>(core)] == kUnknown) r.drainNext();
      return r.idleFrom_[static_cast<size_t>(core)];
    }
  };

  // D_i and the core, then the core's handover if its result buffer is free.
  void dispatch(size_t i, uint64_t cost) {
    uint64_t cycle = run_.pendingCycles[i];
    CoreQuery query{*this};
    const int core = choice_.choose(query, cycle);
    choice_.dispatched(core);
    run_.dispatchCycles.push_back(cycle);
    run_.cores.push_back(core);
    const uint64_t traversal = timer_ ? timer_(i, core, cycle + 1) : cost;  // W_i
    const size_t c = static_cast<size_t>(core);
    waiting_[c] = i;
    waitingFrom_[c] = cycle + 1 + traversal;
    idleFrom_[c] = kUnknown;
    if (buffered_[c] == kNoJob) handOver(core);
  }

  // The waiting result of `core` moves into its (free) buffer.
  void handOver(int core) {
    const size_t c = static_cast<size_t>(core);
    const size_t job = waiting_[c];
    const uint64_t out = waitingFrom_[c];
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
    const auto drain = drains_.next();
    const auto [cycle, core] = drain;
    const size_t c = static_cast<size_t>(core);
    drains_.take(drain);
    run_.drainCycles[buffered_[c]] = cycle;
    run_.hostOrder.push_back(buffered_[c]);
    buffered_[c] = kNoJob;
    lastDrain_[c] = cycle;
    if (waiting_[c] != kNoJob) handOver(core);
  }

  const size_t jobs_;
  const JobSource& jobAt_;
  const RecurrenceConfig& config_;
  const TraversalTimer& timer_;
  const uint64_t cores_;
  HostLinkPacer inputLink_;
  Drains drains_;
  std::vector<uint64_t> idleFrom_;  // per core: idle from this cycle on (kUnknown: not yet known)
  std::vector<size_t> waiting_;     // per core: job whose result waits in the core (kNoJob: none)
  std::vector<uint64_t> waitingFrom_;  // ... from this cycle, D_i + 1 + W_i
  std::vector<size_t> buffered_;       // per core: job whose result is in the result buffer
  std::vector<uint64_t> lastDrain_;
  uint64_t fetchUntil_ = 0;
  size_t inPipeline_ = 0;  // the oldest job not yet dispatched when the current one entered
  SchedulerChoice choice_;
  RecurrenceRun run_;
};

}  // namespace

RecurrenceRun runRecurrence(size_t jobs, const JobSource& jobAt, const RecurrenceConfig& config,
                            const TraversalTimer& timer) {
  config.validate();
  return Recurrence(jobs, jobAt, config, timer).run();
}

RecurrenceRun runRecurrence(const std::vector<JobTiming>& jobs, const RecurrenceConfig& config,
                            const TraversalTimer& timer) {
  return runRecurrence(
      jobs.size(), [&jobs](size_t i) { return jobs[i]; }, config, timer);
}

}  // namespace rtu
