#include "l2_cache_timing.h"

#include <algorithm>
#include <stdexcept>
#include <string>

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

L2CacheTiming::L2CacheTiming(const CacheConfig& cache, const DramConfig& dram)
    : array_(validated(cache)), dram_(validated(dram)) {}

uint64_t L2CacheTiming::read(uint64_t byteAddress, uint64_t requestCycle) {
  const uint64_t accept = acceptRequest(requestCycle);
  const uint64_t tagCheckDone = accept + array_.config().hitLatency;
  const CacheLookup line = array_.access(byteAddress, accept);
  if (line.present) return std::max(tagCheckDone, line.fillCycle);
  const uint64_t fill = fetchLine(tagCheckDone);
  array_.allocate(byteAddress, fill);
  return fill;
}

uint64_t L2CacheTiming::acceptRequest(uint64_t requestCycle) {
  if (requestCycle < lastRequestCycle_)
    throw std::logic_error("L2 requests must come in cycle order: cycle " +
                           std::to_string(requestCycle) + " after cycle " +
                           std::to_string(lastRequestCycle_));
  lastRequestCycle_ = requestCycle;
  const uint64_t accept = std::max(requestCycle, portFree_);
  portFree_ = accept + 1;
  portQueueCycles_ += accept - requestCycle;
  return accept;
}

// Returns the cycle the line is filled; it holds an MSHR until then.
uint64_t L2CacheTiming::fetchLine(uint64_t tagCheckDone) {
  const uint64_t issue = claimMshr(tagCheckDone);
  mshrQueueCycles_ += issue - tagCheckDone;
  const uint64_t fill = dram_.read(array_.config().lineBytes, issue);
  mshrReleases_.push(fill);
  return fill;
}

// The cycle, not before `cycle`, at which an MSHR is free; takes it off the busy list.
uint64_t L2CacheTiming::claimMshr(uint64_t cycle) {
  while (!mshrReleases_.empty() && mshrReleases_.top() <= cycle) mshrReleases_.pop();
  if (mshrReleases_.size() < array_.config().maxOutstandingMisses) return cycle;
  const uint64_t release = mshrReleases_.top();
  mshrReleases_.pop();
  return release;
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
