#include "run/recurrence_statistics.h"

#include <algorithm>

namespace rtu {

RecurrenceStatistics::RecurrenceStatistics(const RtuConfig& config)
    : stats_(RtuStatistics::of(config)), busyUntil_(static_cast<size_t>(config.cores), 0) {
  stats_.coreTimes.resize(static_cast<size_t>(config.cores));
}

void RecurrenceStatistics::add(const JobCycles& cycles, const CoreKindResult& result,
                               uint64_t blocked) {
  const uint32_t cost = resultCost(result);
  ++stats_.rays;
  CoreStatistics& core = stats_.coreTimes[static_cast<size_t>(cycles.core)];
  ++core.jobs;
  core.busyCycles += cost;
  core.blockedCycles += blocked;
  core.outCycles += cycles.handover + 1 - (cycles.dispatch + 1 + cost + blocked);
  countResult(result, core);
  stats_.count(result, blocked);
  const uint64_t wait = cycles.dispatch - cycles.pending;
  stats_.jobManagerStallCycles += wait;
  if (wait < shortWaits_.size())
    ++shortWaits_[wait];
  else
    ++stats_.waitHistogram[wait];
  stats_.maxWait = std::max(stats_.maxWait, wait);
  const size_t place = cycles.job - nextInOrder_;
  if (place >= ahead_.size()) ahead_.resize(place + 1);
  ahead_[place] = Ordered{cycles.pending, wait, cycles.handover, cycles.core};
  for (; !ahead_.empty() && ahead_.front(); ++nextInOrder_) {
    inJobOrder(*ahead_.front());
    ahead_.pop_front();
  }
}

// Whether some core was idle in the cycle a job became pending (eq. 6.7's case). A core is busy
// from the cycle after its dispatch to its handover; every earlier job was dispatched before
// that cycle, and a core's earlier jobs handed over before its last one was dispatched, so only
// each core's last job so far can still be busy. Only a wait that would raise the maximum needs
// the cores asked.
void RecurrenceStatistics::inJobOrder(const Ordered& job) {
  if (job.wait > stats_.maxWaitWithReadyCore &&
      std::any_of(busyUntil_.begin(), busyUntil_.end(),
                  [&job](uint64_t until) { return until <= job.pending; }))
    stats_.maxWaitWithReadyCore = job.wait;
  busyUntil_[static_cast<size_t>(job.core)] = job.handover + 1;
}

RtuStatistics RecurrenceStatistics::finish(const RecurrenceTotals& totals) {
  stats_.totalCycles = totals.totalCycles;
  stats_.resultBuffersMaxFull = totals.resultBuffersMaxFull;
  for (uint64_t wait = 0; wait < shortWaits_.size(); ++wait)
    if (shortWaits_[wait] > 0) stats_.waitHistogram[wait] += shortWaits_[wait];
  return stats_;
}

}  // namespace rtu
