#include "rtu/rtu_recurrence.h"

#include <algorithm>
#include <deque>
#include <limits>
#include <optional>
#include <queue>
#include <stdexcept>
#include <utility>

#include "base/modulo.h"
#include "base/prefault.h"
#include "rtu/buffers_full.h"
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

// Room for `n` values, its pages mapped at once (prefault.h): a frame's columns are large.
template <typename T>
void reserveMapped(std::vector<T>& column, size_t n) {
  column.reserve(n);
  prefaultCapacity(column);
}

// `n` values, their pages mapped at once.
template <typename T>
void sizeMapped(std::vector<T>& column, size_t n) {
  reserveMapped(column, n);
  column.resize(n);
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
             const DrainSink& drained, const TraversalTimer& timer)
      : jobs_(jobs),
        jobAt_(jobAt),
        drained_(drained),
        timer_(timer),
        inputLink_(config.hostInput),
        drains_(config.cores, config.hostOutput),
        idleFrom_(static_cast<size_t>(config.cores), 0),
        waiting_(static_cast<size_t>(config.cores)),
        waitingFrom_(static_cast<size_t>(config.cores), 0),
        buffered_(static_cast<size_t>(config.cores)),
        lastDrain_(static_cast<size_t>(config.cores), kUnknown),
        choice_(config.policy, config.cores) {}

  RecurrenceTotals run() {
    for (size_t i = 0; i < jobs_; ++i) {
      const JobTiming job = jobAt_(i);
      JobCycles cycles = enterPipeline(i, job);
      dispatch(cycles, job.cost);
      // Now and then: the cycles settled cost a look at every core.
      if (i % kSettleEvery == kSettleEvery - 1) buffersFull_.settleBefore(settledBefore());
    }
    while (!drains_.empty()) drainNext();  // drains come in cycle order
    return RecurrenceTotals{jobs_ == 0 ? 0 : lastDrainCycle_ + 1, buffersFull_.most()};
  }

 private:
  static constexpr size_t kSettleEvery = 64;  // jobs

  // A job in the job manager's pipeline: entered, not yet dispatched when a later job entered.
  struct InPipeline {
    uint64_t pending, dispatch;
  };

  // c_i and A_i.
  JobCycles enterPipeline(size_t i, const JobTiming& job) {
    uint64_t accept = i == 0 ? 0 : inputLink_.nextAllowed(lastAccept_);
    accept = std::max(accept, fetchUntil_);
    while (!pipeline_.empty() && pipeline_.front().dispatch <= accept) pipeline_.pop_front();
    if (!pipeline_.empty() && pipeline_.front().pending <= accept) {
      accept = pipeline_.front().dispatch;  // the pipeline is held until that dispatch
      pipeline_.pop_front();
    }
    uint64_t stalls = 0;
    for (const InPipeline& k : pipeline_) stalls += k.dispatch - k.pending;
    uint64_t pending = accept + job.pipelineCycles + stalls;
    if (i > 0) pending = std::max(pending, lastDispatch_ + 1);
    if (job.headerFetch > 0) fetchUntil_ = accept + 1 + job.headerFetch;
    lastAccept_ = accept;
    JobCycles cycles;
    cycles.job = i;
    cycles.accept = accept;
    cycles.pending = pending;
    return cycles;
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
  void dispatch(JobCycles& cycles, uint64_t cost) {
    uint64_t cycle = cycles.pending;
    CoreQuery query{*this};
    const int core = choice_.choose(query, cycle);
    choice_.dispatched(core);
    cycles.dispatch = cycle;
    cycles.core = core;
    pipeline_.push_back(InPipeline{cycles.pending, cycle});
    lastDispatch_ = cycle;
    const uint64_t traversal = timer_ ? timer_(cycles.job, core, cycle + 1) : cost;  // W_i
    const size_t c = static_cast<size_t>(core);
    waiting_[c] = cycles;
    waitingFrom_[c] = cycle + 1 + traversal;
    idleFrom_[c] = kUnknown;
    if (!buffered_[c]) handOver(core);
  }

  // The waiting result of `core` moves into its (free) buffer.
  void handOver(int core) {
    const size_t c = static_cast<size_t>(core);
    JobCycles& job = *waiting_[c];
    const uint64_t out = waitingFrom_[c];
    job.handover = lastDrain_[c] == kUnknown ? out : std::max(out, lastDrain_[c] + 1);
    idleFrom_[c] = job.handover + 1;
    buffersFull_.started(job.handover);
    drains_.add(core, job.handover + 1);
    buffered_[c] = job;
    waiting_[c].reset();
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
    JobCycles job = *buffered_[c];
    buffered_[c].reset();
    job.drain = cycle;
    lastDrain_[c] = cycle;
    lastDrainCycle_ = cycle;
    buffersFull_.ended(cycle);
    drained_(job);
    if (waiting_[c]) handOver(core);
  }

  // No handover or drain still to come is before this cycle: later jobs hand over after their
  // dispatch, waiting results no earlier than they are out, and drains come in cycle order.
  uint64_t settledBefore() const {
    uint64_t before = lastDispatch_ + 1;
    if (lastDrainCycle_ != kUnknown) before = std::min(before, lastDrainCycle_ + 1);
    for (size_t c = 0; c < waiting_.size(); ++c)
      if (waiting_[c]) before = std::min(before, waitingFrom_[c]);
    return before;
  }

  const size_t jobs_;
  const JobSource& jobAt_;
  const DrainSink& drained_;
  const TraversalTimer& timer_;
  HostLinkPacer inputLink_;
  Drains drains_;
  std::vector<uint64_t> idleFrom_;  // per core: idle from this cycle on (kUnknown: not yet known)
  std::vector<std::optional<JobCycles>> waiting_;   // per core: the job whose result waits in it
  std::vector<uint64_t> waitingFrom_;               // ... from this cycle, D_i + 1 + W_i
  std::vector<std::optional<JobCycles>> buffered_;  // per core: the job in its result buffer
  std::vector<uint64_t> lastDrain_;
  std::deque<InPipeline> pipeline_;  // from the oldest job still undispatched when the last entered
  uint64_t lastAccept_ = 0, lastDispatch_ = 0, fetchUntil_ = 0, lastDrainCycle_ = kUnknown;
  SchedulerChoice choice_;
  BuffersFull buffersFull_;
};

}  // namespace

RecurrenceTotals streamRecurrence(size_t jobs, const JobSource& jobAt,
                                  const RecurrenceConfig& config, const DrainSink& drained,
                                  const TraversalTimer& timer) {
  config.validate();
  return Recurrence(jobs, jobAt, config, drained, timer).run();
}

RecurrenceRun runRecurrence(size_t jobs, const JobSource& jobAt, const RecurrenceConfig& config,
                            const TraversalTimer& timer) {
  RecurrenceRun run;
  for (auto* column : {&run.acceptCycles, &run.pendingCycles, &run.dispatchCycles,
                       &run.handoverCycles, &run.drainCycles})
    sizeMapped(*column, jobs);
  sizeMapped(run.cores, jobs);
  reserveMapped(run.hostOrder, jobs);
  const RecurrenceTotals totals = streamRecurrence(
      jobs, jobAt, config,
      [&run](const JobCycles& job) {
        run.acceptCycles[job.job] = job.accept;
        run.pendingCycles[job.job] = job.pending;
        run.dispatchCycles[job.job] = job.dispatch;
        run.cores[job.job] = job.core;
        run.handoverCycles[job.job] = job.handover;
        run.drainCycles[job.job] = job.drain;
        run.hostOrder.push_back(job.job);
      },
      timer);
  run.totalCycles = totals.totalCycles;
  run.resultBuffersMaxFull = totals.resultBuffersMaxFull;
  return run;
}

RecurrenceRun runRecurrence(const std::vector<JobTiming>& jobs, const RecurrenceConfig& config,
                            const TraversalTimer& timer) {
  return runRecurrence(
      jobs.size(), [&jobs](size_t i) { return jobs[i]; }, config, timer);
}

}  // namespace rtu
