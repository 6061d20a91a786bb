#include "lt_dispatcher.h"

#include <algorithm>

#include "job_manager.h"

namespace rtu {

LtDispatcher::LtDispatcher(sc_core::sc_module_name name, SvoMemory memory,
                           const std::vector<HostRecord>& records, const LtDispatcherConfig& config,
                           const LtTime& time)
    : sc_core::sc_module(name),
      records_(records),
      config_(config),
      time_(time),
      setup_(memory, config.jobManager),
      input_(config.hostInput),
      choice_(config.policy, config.cores),
      dispatchCycles_(records.size(), 0) {
  for (int core = 0; core < config.cores; ++core) nextOwn_.push_back(static_cast<size_t>(core));
  jobs_.reserve(records.size());
  pending_.reserve(records.size());
}

bool LtDispatcher::take(int core, uint64_t idleFrom, LtDispatch& dispatch) {
  const size_t job = nextJobFor(core);
  if (job >= records_.size()) return false;
  const uint64_t pending = pendingCycle(job);
  const uint64_t cycle = dispatchCycle(core, pending, idleFrom);
  countWait(pending, cycle, idleFrom);
  dispatchCycles_[job] = cycle;
  dispatch.job = coreJobOf(PayloadIds::plain(job), jobs_[job], config_.jobManager);
  dispatch.job.pendingSince = pending;
  dispatch.cycle = cycle;
  return true;
}

size_t LtDispatcher::nextJobFor(int core) {
  if (config_.policy != SchedulerPolicy::RoundRobin) return nextShared_++;
  size_t& own = nextOwn_[static_cast<size_t>(core)];
  const size_t job = own;
  own += static_cast<size_t>(config_.cores);
  return job;
}

// A_job; the jobs before it are set up first, in host order (headers are read by the first).
uint64_t LtDispatcher::pendingCycle(size_t job) {
  while (pending_.size() <= job) {
    const size_t i = pending_.size();
    const JobSetup::SetUp set = setup_.setUp(records_[i]);
    uint64_t accept = i == 0 ? 0 : input_.nextAllowed(lastAccept_);
    accept = std::max(accept, fetchUntil_);
    if (set.headerFetch > 0) fetchUntil_ = accept + 1 + set.headerFetch;
    lastAccept_ = accept;
    uint64_t pending = accept + set.latency;
    if (i > 0) pending = std::max(pending, pending_.back() + 1);
    jobs_.push_back(set.job);
    pending_.push_back(pending);
  }
  return pending_[job];
}

uint64_t LtDispatcher::dispatchCycle(int core, uint64_t pending, uint64_t idleFrom) {
  const uint64_t cycle = choice_.firstCycleFor(core, std::max(pending, idleFrom));
  // The select counter gives each cycle to one core; otherwise one dispatch a cycle is booked.
  if (config_.policy == SchedulerPolicy::CyclicFirstAvailable) return cycle;
  dispatches_.forgetBefore(time_.now());  // no core asks behind simulated time
  return dispatches_.takeFirstFree(cycle);
}

void LtDispatcher::countWait(uint64_t pending, uint64_t dispatch, uint64_t idleFrom) {
  const uint64_t wait = dispatch - pending;
  statistics_.stallCycles += wait;
  if (wait < shortWaits_.size())
    ++shortWaits_[wait];
  else
    ++statistics_.waitHistogram[wait];
  statistics_.maxWait = std::max(statistics_.maxWait, wait);
  if (idleFrom <= pending)
    statistics_.maxWaitWithReadyCore = std::max(statistics_.maxWaitWithReadyCore, wait);
}

LtDispatchStatistics LtDispatcher::statistics() const {
  LtDispatchStatistics all = statistics_;
  for (uint64_t wait = 0; wait < shortWaits_.size(); ++wait)
    if (shortWaits_[wait] > 0) all.waitHistogram[wait] += shortWaits_[wait];
  return all;
}

}  // namespace rtu
