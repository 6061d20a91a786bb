#include "sim/ca/job_manager.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace rtu {

JobManager::JobManager(DecisionPump& pump, const CycleClock& clock, const JobManagerTiming& timing,
                       CoreJobSetup setup)
    : Agent(pump), clock_(clock), setup_(std::move(setup)) {
  if (timing.stages < 1 || timing.stages > 64 || timing.rayStages < 0 || timing.rayStages > 64)
    throw std::invalid_argument("job manager pipeline must have 1 to 64 stages (0 to 64 more for "
                                "rays), got " +
                                std::to_string(timing.stages) + " and " +
                                std::to_string(timing.rayStages));
  if (timing.headerFetchCycles < 0)
    throw std::invalid_argument("model header fetch cycles must not be negative");
}

void JobManager::bind(TransferChannel<HostPayload>& in, TransferChannel<CoreJob>& out) {
  in_ = &in;
  out_ = &out;
  traceReadyAt(0);
}

void JobManager::decide() {
  if (out_->collectTaken()) takeDispatch();
  if (!pipeline_.empty() && !frontOffered_) {
    InFlight& front = pipeline_.front();
    front.job.pendingSince = outputOf(front);
    out_->offer(front.job, outputOf(front));
    frontOffered_ = true;
    retraceReady();
  }
  if (in_->offering()) acceptOffered();
}

// The scheduler took the job at the output in D: its stall [A, D) holds every job behind it.
void JobManager::takeDispatch() {
  const uint64_t dispatch = out_->lastTransfer();
  const uint64_t stall = dispatch - outputOf(pipeline_.front());
  statistics_.stallCycles += stall;
  if (stall > 0) stalls_.push_back({outputOf(pipeline_.front()), dispatch});
  pipeline_.pop_front();
  lastDispatch_ = dispatch;
  stallShift_ += stall;  // every job behind it
  frontOffered_ = false;
  retraceReady();
}

void JobManager::acceptOffered() {
  const uint64_t cycle = acceptanceCycle(in_->offerCycle());
  if (cycle == kNeverCycle) return;  // the job at the output is due first: wait for its dispatch
  const HostPayload& host = in_->payload();  // take() leaves it in place until the next offer
  in_->take(cycle);
  accept(host, cycle);
}

// The first cycle from `offered` in which the pipeline moves, or kNeverCycle while that depends
// on the dispatch of the job at the output.
uint64_t JobManager::acceptanceCycle(uint64_t offered) const {
  uint64_t cycle = offered;
  for (const Window& fetch : fetches_) cycle = std::max(cycle, fetch.to);
  for (const Window& stall : stalls_)
    if (stall.from <= cycle && cycle < stall.to) cycle = stall.to;
  if (frontOffered_ && outputOf(pipeline_.front()) <= cycle) return kNeverCycle;
  return cycle;
}

void JobManager::accept(const HostPayload& host, uint64_t cycle) {
  accepted_ = true;
  lastAccepted_ = cycle;
  while (!stalls_.empty() && stalls_.front().to <= cycle) stalls_.pop_front();
  while (!fetches_.empty() && fetches_.front().to <= cycle) fetches_.pop_front();
  const CoreKindJobSetUp set = setup_(host.record);
  if (set.headerFetch > 0) fetches_.push_back({cycle + 1, cycle + 1 + set.headerFetch});
  // Stalls decided before this acceptance but after its cycle held this job too.
  uint64_t outputCycle = cycle + set.latency;
  for (const Window& stall : stalls_)
    if (stall.from > cycle) outputCycle += stall.to - stall.from;
  // Behind the job ahead, which may have left already: its dispatch can be decided before this
  // acceptance (after a header fetch that outlasted a stall, the next ray is accepted late).
  if (!pipeline_.empty()) outputCycle = std::max(outputCycle, outputOf(pipeline_.back()) + 1);
  if (lastDispatch_) outputCycle = std::max(outputCycle, *lastDispatch_ + 1);
  pipeline_.push_back(InFlight{CoreJob{host.ids, set.idWord, set.job}, outputCycle - stallShift_});
  traceReadyAt(cycle + 1);
  if (set.headerFetch > 0) traceReadyAt(cycle + 1 + set.headerFetch);
  // The new job may be the one at the output now.
  if (pipeline_.size() == 1) decide();
}

// in_ready = pipeline_enable and no header fetch under way.
bool JobManager::readyIn(uint64_t cycle) const {
  for (const Window& fetch : fetches_)
    if (fetch.from <= cycle && cycle < fetch.to) return false;
  for (const Window& stall : stalls_)
    if (stall.from <= cycle && cycle < stall.to) return false;
  return !(frontOffered_ && outputOf(pipeline_.front()) <= cycle);
}

void JobManager::traceReadyAt(uint64_t cycle) {
  if (!in_->traced()) return;
  readyPoints_.push_back(cycle);
  in_->traceReady(cycle, readyIn(cycle));
}

// A stall began or ended: every traced level from the oldest undecided cycle on is recorded
// again (the last record of a cycle counts), with the stall's own edges.
void JobManager::retraceReady() {
  if (!in_->traced()) return;
  // No window starts behind simulated time or at the last acceptance and before (a stall there
  // was known when the record was accepted; a header fetch starts after it).
  const auto final = [this](uint64_t cycle) {
    return cycle < clock_.now() || (accepted_ && cycle <= lastAccepted_);
  };
  readyPoints_.erase(std::remove_if(readyPoints_.begin(), readyPoints_.end(), final),
                     readyPoints_.end());
  for (const Window& stall : stalls_) {
    readyPoints_.push_back(stall.from);
    readyPoints_.push_back(stall.to);
  }
  if (frontOffered_) readyPoints_.push_back(outputOf(pipeline_.front()));
  std::sort(readyPoints_.begin(), readyPoints_.end());
  readyPoints_.erase(std::unique(readyPoints_.begin(), readyPoints_.end()), readyPoints_.end());
  for (uint64_t cycle : readyPoints_)
    if (!final(cycle)) in_->traceReady(cycle, readyIn(cycle));
}

}  // namespace rtu
