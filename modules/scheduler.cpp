#include "scheduler.h"

#include <stdexcept>

namespace rtu {

Scheduler::Scheduler(sc_core::sc_module_name name, const CycleClock& clock, SchedulerPolicy policy)
    : sc_core::sc_module(name), clock_(clock), policy_(policy), wake_(clock) {}

void Scheduler::end_of_elaboration() {
  coreCount_ = cores.size();
  readyCores_ = CoreSet(coreCount_);
  std::vector<const sc_core::sc_event*> coreReadiness;
  for (int i = 0; i < coreCount_; ++i) {
    core_.push_back(cores[i]);
    coreReadiness.push_back(&core_.back()->readyChanged());
    core_.back()->watchReady([this, i](bool ready) { readyCores_.assign(i, ready); });
  }
  spawnMethod("evaluate", [this] { evaluate(); },
              {&in->edge(), &in->offerChanged(), &wake_.event()}, coreReadiness);
}

void Scheduler::evaluate() {
  const uint64_t now = clock_.now();
  takeTransfer(now);
  // Until the job manager writes again in this cycle, its levels still show the job just taken.
  const bool pending = in->valid() && in->payload().sequence != dispatchedSequence_;
  uint64_t wakeCycle = 0;
  const int core = pending ? choose(now, wakeCycle) : kNone;
  if (pending) notePending(now);
  dispatch(core);
  if (core == kNone && wakeCycle > now) wake_.at(wakeCycle);
}

void Scheduler::takeTransfer(uint64_t now) {
  if (handledCycle_ == now) return;
  handledCycle_ = now;
  if (now == 0 || !in->transferredIn(now - 1)) return;
  const CoreJob& job = in->transferred();
  const uint64_t wait = now - 1 - job.pendingSince;
  ++statistics_.jobs;
  ++statistics_.waitHistogram[wait];
  statistics_.maxWait = std::max(statistics_.maxWait, wait);
  if (readyAtPending_)
    statistics_.maxWaitWithReadyCore = std::max(statistics_.maxWaitWithReadyCore, wait);
  if (policy_ == SchedulerPolicy::RoundRobin) nextInLine_ = (target_ + 1) % coreCount_;
  dispatchedSequence_ = job.sequence;
  dispatch(kNone);
}

// Pending since this cycle: record whether some core was ready, the condition of eq. 6.7. Core
// levels can still settle in later deltas of the cycle, so the note is revised within it.
void Scheduler::notePending(uint64_t now) {
  const CoreJob& job = in->payload();
  if (job.sequence == notedSequence_ && job.pendingSince != now) return;
  notedSequence_ = job.sequence;
  readyAtPending_ = !readyCores_.empty();
}

int Scheduler::choose(uint64_t now, uint64_t& wakeCycle) const {
  switch (policy_) {
    case SchedulerPolicy::CyclicFirstAvailable: {
      const int selected = static_cast<int>(now % static_cast<uint64_t>(coreCount_));
      const int first = readyCores_.firstFrom(selected);
      if (first == selected || first == CoreSet::kNone) return first;
      wakeCycle = now + static_cast<uint64_t>((first - selected + coreCount_) % coreCount_);
      return kNone;
    }
    case SchedulerPolicy::RoundRobin:
      return readyCores_.contains(nextInLine_) ? nextInLine_ : kNone;
    case SchedulerPolicy::FirstAvailable:
      return readyCores_.firstFrom(0);
  }
  return kNone;
}

void Scheduler::dispatch(int core) {
  const bool sameOffer = core == target_ && (core == kNone || offeredSequence_ == in->payload().sequence);
  if (sameOffer) return;
  if (target_ != kNone) core_[static_cast<size_t>(target_)]->withdraw();
  target_ = core;
  in->setReady(core != kNone);
  if (core == kNone) return;
  offeredSequence_ = in->payload().sequence;
  core_[static_cast<size_t>(core)]->offer(in->payload());
}

}  // namespace rtu
