#include "sim/ca/scheduler.h"

#include <algorithm>

namespace rtu {

Scheduler::Scheduler(DecisionPump& pump, SchedulerPolicy policy, int cores)
    : Agent(pump), choice_(policy, cores) {}

void Scheduler::bind(TransferChannel<CoreJob>& in, std::vector<TransferChannel<CoreJob>*> cores) {
  in_ = &in;
  cores_ = std::move(cores);
}

void Scheduler::decide() {
  if (!in_->offering()) return;
  const uint64_t pending = in_->offerCycle();
  uint64_t cycle = std::max(pending, noDispatchBefore());
  CoreQuery query{*this};
  const int core = choice_.choose(query, cycle);
  if (core == SchedulerChoice::kWait) {
    awaited_ = query.awaited;
    raiseDispatchFloor(cycle);  // the cycles before are settled: no dispatch there
    return;
  }
  const uint64_t wait = cycle - pending;
  // Whether a core was ready at `pending` matters only to a wait that would raise the eq. 6.7
  // maximum and that the policy allows with a core idle; asking every core for every job would
  // make the cost follow the core count, and wake the scheduler at every core's news.
  if (wait > statistics_.maxWaitWithReadyCore && wait <= choice_.longestWaitWithIdleCore()) {
    const Idle readyAtPending = someCoreIdleIn(pending);
    if (readyAtPending == Idle::Unknown) {
      awaited_ = kAnyCore;
      raiseDispatchFloor(cycle);
      return;
    }
    if (readyAtPending == Idle::Yes) statistics_.maxWaitWithReadyCore = wait;
  }
  ++statistics_.jobs;
  countWait(wait);
  statistics_.maxWait = std::max(statistics_.maxWait, wait);
  dispatch(core, cycle);
}

void Scheduler::heard(int port) {
  if (port != kJobsPort && awaited_ != kAnyCore && port != awaited_) return;
  Agent::heard(port);
}

void Scheduler::countWait(uint64_t wait) {
  if (wait < shortWaits_.size())
    ++shortWaits_[wait];
  else
    ++statistics_.waitHistogram[wait];
}

SchedulerStatistics Scheduler::statistics() const {
  SchedulerStatistics all = statistics_;
  for (uint64_t wait = 0; wait < shortWaits_.size(); ++wait)
    if (shortWaits_[wait] > 0) all.waitHistogram[wait] += shortWaits_[wait];
  return all;
}

Idle Scheduler::idleIn(int core, uint64_t cycle) const {
  const TransferChannel<CoreJob>& channel = *cores_[static_cast<size_t>(core)];
  if (channel.readyCycle() <= cycle) return Idle::Yes;
  if (channel.readyBound() > cycle) return Idle::No;
  return Idle::Unknown;
}

Idle Scheduler::CoreQuery::in(int core, uint64_t cycle) {
  const Idle idle = scheduler.idleIn(core, cycle);
  if (idle == Idle::Unknown) await(core);
  return idle;
}

uint64_t Scheduler::CoreQuery::from(int core) {
  const uint64_t ready = scheduler.cores_[static_cast<size_t>(core)]->readyCycle();
  if (ready != kNeverCycle) return ready;
  await(core);
  return kIdleUnknown;
}

Idle Scheduler::someCoreIdleIn(uint64_t cycle) const {
  bool unknown = false;
  for (size_t core = 0; core < cores_.size(); ++core) {
    const Idle idle = idleIn(static_cast<int>(core), cycle);
    if (idle == Idle::Yes) return Idle::Yes;
    if (idle == Idle::Unknown) unknown = true;
  }
  return unknown ? Idle::Unknown : Idle::No;
}

void Scheduler::dispatch(int core, uint64_t cycle) {
  const CoreJob& job = in_->payload();  // take() leaves it in place until the next offer
  in_->take(cycle);
  cores_[static_cast<size_t>(core)]->deliver(job, cycle);
  awaited_ = kAnyCore;            // the next job's search has not started
  raiseDispatchFloor(cycle + 1);  // jobs are dispatched in increasing cycles
  choice_.dispatched(core);
}

}  // namespace rtu
