#include "scheduler.h"

#include <algorithm>

namespace rtu {

Scheduler::Scheduler(DecisionPump& pump, SchedulerPolicy policy) : Agent(pump), policy_(policy) {}

void Scheduler::bind(TransferChannel<CoreJob>& in, std::vector<TransferChannel<CoreJob>*> cores) {
  in_ = &in;
  cores_ = std::move(cores);
}

void Scheduler::decide() {
  if (!in_->offering()) return;
  const uint64_t pending = in_->offerCycle();
  uint64_t cycle = std::max(pending, searchedFrom_);
  const int core = choose(cycle);
  if (core == kWait) {
    searchedFrom_ = cycle;  // the cycles before are settled: no dispatch there
    return;
  }
  const uint64_t wait = cycle - pending;
  // Whether a core was ready at `pending` matters only to a wait that would raise the eq. 6.7
  // maximum; asking every core for every job would make the cost follow the core count.
  if (wait > statistics_.maxWaitWithReadyCore) {
    const Idle readyAtPending = someCoreIdleIn(pending);
    if (readyAtPending == Idle::Unknown) {
      searchedFrom_ = cycle;
      return;
    }
    if (readyAtPending == Idle::Yes) statistics_.maxWaitWithReadyCore = wait;
  }
  ++statistics_.jobs;
  countWait(wait);
  statistics_.maxWait = std::max(statistics_.maxWait, wait);
  dispatch(core, cycle);
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

Scheduler::Idle Scheduler::idleIn(int core, uint64_t cycle) const {
  const TransferChannel<CoreJob>& channel = *cores_[static_cast<size_t>(core)];
  if (channel.readyCycle() <= cycle) return Idle::Yes;
  if (channel.readyBound() > cycle) return Idle::No;
  return Idle::Unknown;
}

int Scheduler::choose(uint64_t& cycle) {
  switch (policy_) {
    case SchedulerPolicy::CyclicFirstAvailable: return cyclicFirstAvailable(cycle);
    case SchedulerPolicy::FirstAvailable: return firstAvailable(cycle);
    case SchedulerPolicy::RoundRobin: return roundRobin(cycle);
  }
  return kWait;
}

// Core t mod N in cycle t, if it is idle then.
int Scheduler::cyclicFirstAvailable(uint64_t& cycle) const {
  const uint64_t n = cores_.size();
  for (;; ++cycle) {
    const int core = static_cast<int>(cycle % n);
    switch (idleIn(core, cycle)) {
      case Idle::Yes: return core;
      case Idle::Unknown: return kWait;
      case Idle::No: break;
    }
  }
}

// The lowest idle core, in the first cycle with one.
int Scheduler::firstAvailable(uint64_t& cycle) const {
  for (;; ++cycle) {
    bool unknown = false;
    for (size_t core = 0; core < cores_.size(); ++core) {
      const Idle idle = idleIn(static_cast<int>(core), cycle);
      if (idle == Idle::Unknown) unknown = true;
      if (idle == Idle::Yes) return unknown ? kWait : static_cast<int>(core);
    }
    if (unknown) return kWait;
  }
}

// The next core in turn, once it is idle.
int Scheduler::roundRobin(uint64_t& cycle) const {
  const TransferChannel<CoreJob>& channel = *cores_[static_cast<size_t>(nextInLine_)];
  if (channel.readyCycle() == kNeverCycle) return kWait;
  cycle = std::max(cycle, channel.readyCycle());
  return nextInLine_;
}

Scheduler::Idle Scheduler::someCoreIdleIn(uint64_t cycle) const {
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
  searchedFrom_ = cycle + 1;
  if (policy_ == SchedulerPolicy::RoundRobin) nextInLine_ = (core + 1) % static_cast<int>(cores_.size());
}

}  // namespace rtu
