#include "sim/memory/l2_cache_timing.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace rtu {

namespace {

// Validation has to precede the members' construction, hence in the initializer list.
const CacheConfig& validated(const CacheConfig& cache) {
  validate(cache, "L2");
  return cache;
}

const DramConfig& validated(const DramConfig& dram) {
  validate(dram);
  return dram;
}

}  // namespace

L2CacheTiming::L2CacheTiming(const CacheConfig& cache, const DramConfig& dram,
                             RequestOrder order, DramRead external)
    : array_(validated(cache)),
      dram_(validated(dram), order),
      externalDram_(std::move(external)),
      order_(order),
      port_(order),
      uncontendedMiss_(dram.latency + dram_.transferCycles(cache.lineBytes)) {}

uint64_t L2CacheTiming::read(uint64_t byteAddress, uint64_t requestCycle) {
  const bool inCycleOrder = requestCycle >= lastRequestCycle_;
  const uint64_t accept = acceptRequest(requestCycle);
  const uint64_t tagCheckDone = accept + array_.config().hitLatency;
  const CacheLookup line = array_.access(byteAddress, accept);
  if (line.present)
    return std::max(tagCheckDone,
                    inCycleOrder ? line.fillCycle : mergedFill(line.fillCycle, tagCheckDone));
  const uint64_t fill = fetchLine(tagCheckDone);
  array_.allocate(byteAddress, fill);
  return fill;
}

// A request behind the latest one finds a line in flight: the miss that allocated it may have
// been issued after this request's tag check. In cycle order this request would have missed and
// that one merged, so it waits no longer than its own uncontended miss would.
uint64_t L2CacheTiming::mergedFill(uint64_t fillCycle, uint64_t tagCheckDone) const {
  return std::min(fillCycle, tagCheckDone + uncontendedMiss_);
}

void L2CacheTiming::failOutOfOrder(uint64_t requestCycle) const {
  throw std::logic_error("L2 requests must come in cycle order: cycle " +
                         std::to_string(requestCycle) + " after cycle " +
                         std::to_string(lastRequestCycle_));
}

// Returns the cycle the line is filled; it holds an MSHR until then.
uint64_t L2CacheTiming::fetchLine(uint64_t tagCheckDone) {
  const uint64_t issue = claimMshr(tagCheckDone);
  mshrQueueCycles_ += issue - tagCheckDone;
  const uint32_t bytes = array_.config().lineBytes;
  const uint64_t fill = externalDram_ ? externalDram_(bytes, issue) : dram_.read(bytes, issue);
  if (order_ == RequestOrder::Cycle)
    mshrReleases_.push(fill);
  else
    mshrUses_.push_back({issue, fill});
  return fill;
}

// The first cycle from `cycle` on in which fewer than maxOutstandingMisses MSHRs are busy.
uint64_t L2CacheTiming::claimMshr(uint64_t cycle) {
  return order_ == RequestOrder::Cycle ? claimMshrInOrder(cycle) : claimMshrAnyOrder(cycle);
}

// In cycle order the busy MSHRs are those released after `cycle`: a heap of at most
// maxOutstandingMisses releases, the earliest taken over when all are busy.
uint64_t L2CacheTiming::claimMshrInOrder(uint64_t cycle) {
  while (!mshrReleases_.empty() && mshrReleases_.top() <= cycle) mshrReleases_.pop();
  if (mshrReleases_.size() < array_.config().maxOutstandingMisses) return cycle;
  const uint64_t release = mshrReleases_.top();
  mshrReleases_.pop();
  return release;
}

// Out of order a use may have been issued after `cycle`: the busy ones at a cycle are those
// issued by it and released after it.
uint64_t L2CacheTiming::claimMshrAnyOrder(uint64_t cycle) {
  for (;;) {
    uint32_t busy = 0;
    uint64_t firstRelease = UINT64_MAX;
    for (const MshrUse& use : mshrUses_) {
      if (use.issue > cycle || use.release <= cycle) continue;
      ++busy;
      firstRelease = std::min(firstRelease, use.release);
    }
    if (busy < array_.config().maxOutstandingMisses) return cycle;
    cycle = firstRelease;
  }
}

void L2CacheTiming::forgetMshrsBefore(uint64_t cycle) {
  mshrUses_.erase(std::remove_if(mshrUses_.begin(), mshrUses_.end(),
                                 [cycle](const MshrUse& use) { return use.release <= cycle; }),
                  mshrUses_.end());
}

void L2CacheTiming::forgetBefore(uint64_t cycle) {
  port_.forgetBefore(cycle);
  dram_.forgetBefore(cycle);
  forgetMshrsBefore(cycle);
}

const StatisticGroup<L2Stats>& L2Stats::declaration() {
  static const StatisticGroup<L2Stats> group =
      StatisticGroup<L2Stats>("the L2 and the DRAM behind it")
          .group(Statistic("l2", "", "the shared L2: requests from the L1s"), &L2Stats::cache)
          .count(Statistic("l2/port_queue_cycles", "cycles",
                           "cycles requests waited for the L2's port: sum of accept - request"),
                 &L2Stats::portQueueCycles)
          .count(Statistic("l2/mshr_queue_cycles", "cycles",
                           "cycles misses waited for an MSHR: sum of issue - tag check"),
                 &L2Stats::mshrQueueCycles)
          .group(Statistic("dram", "", "the DRAM channel behind the L2"), &L2Stats::dram);
  return group;
}

L2Stats L2CacheTiming::stats() const {
  L2Stats stats;
  stats.cache = array_.stats();
  stats.dram = dram_.stats();
  stats.portQueueCycles = portQueueCycles_;
  stats.mshrQueueCycles = mshrQueueCycles_;
  return stats;
}

}  // namespace rtu
