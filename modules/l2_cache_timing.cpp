#include "l2_cache_timing.h"

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
      port_(order) {}

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
  if (order_ == RequestOrder::Cycle) {
    if (requestCycle < lastRequestCycle_)
      throw std::logic_error("L2 requests must come in cycle order: cycle " +
                             std::to_string(requestCycle) + " after cycle " +
                             std::to_string(lastRequestCycle_));
    lastRequestCycle_ = requestCycle;
  }
  const uint64_t accept = port_.book(requestCycle, 1);
  portQueueCycles_ += accept - requestCycle;
  return accept;
}

// Returns the cycle the line is filled; it holds an MSHR until then.
uint64_t L2CacheTiming::fetchLine(uint64_t tagCheckDone) {
  const uint64_t issue = claimMshr(tagCheckDone);
  mshrQueueCycles_ += issue - tagCheckDone;
  const uint32_t bytes = array_.config().lineBytes;
  const uint64_t fill = externalDram_ ? externalDram_(bytes, issue) : dram_.read(bytes, issue);
  mshrReleases_.push_back(fill);
  return fill;
}

// The cycle, not before `cycle`, at which an MSHR is free; an MSHR busy then is taken off the
// list (the caller adds the release of its new miss).
uint64_t L2CacheTiming::claimMshr(uint64_t cycle) {
  if (order_ == RequestOrder::Cycle) forgetMshrsBefore(cycle);
  auto earliest = mshrReleases_.end();
  uint32_t busy = 0;
  for (auto release = mshrReleases_.begin(); release != mshrReleases_.end(); ++release) {
    if (*release <= cycle) continue;
    ++busy;
    if (earliest == mshrReleases_.end() || *release < *earliest) earliest = release;
  }
  if (busy < array_.config().maxOutstandingMisses) return cycle;
  const uint64_t release = *earliest;
  mshrReleases_.erase(earliest);
  return release;
}

void L2CacheTiming::forgetMshrsBefore(uint64_t cycle) {
  mshrReleases_.erase(std::remove_if(mshrReleases_.begin(), mshrReleases_.end(),
                                     [cycle](uint64_t release) { return release <= cycle; }),
                      mshrReleases_.end());
}

void L2CacheTiming::forgetBefore(uint64_t cycle) {
  port_.forgetBefore(cycle);
  dram_.forgetBefore(cycle);
  forgetMshrsBefore(cycle);
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
