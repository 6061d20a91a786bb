#include "run/statistics_window.h"

#include <algorithm>

namespace rtu {
namespace {

// sign +1 adds `b` to `a`, -1 subtracts it.
void combine(uint64_t& a, uint64_t b, int sign) { a = sign > 0 ? a + b : a - std::min(a, b); }

void combine(CacheStats& a, const CacheStats& b, int sign) {
  combine(a.accesses, b.accesses, sign);
  combine(a.hits, b.hits, sign);
  combine(a.merged, b.merged, sign);
  combine(a.misses, b.misses, sign);
  combine(a.evictions, b.evictions, sign);
}

void combine(CoreStatistics& a, const CoreStatistics& b, int sign) {
  combine(a.jobs, b.jobs, sign);
  combine(a.busyCycles, b.busyCycles, sign);
  combine(a.blockedCycles, b.blockedCycles, sign);
  combine(a.outCycles, b.outCycles, sign);
  combine(a.stackOverflows, b.stackOverflows, sign);
  combine(a.tOverflows, b.tOverflows, sign);
}

void combineCounters(RtuStatistics& a, const RtuStatistics& b, int sign) {
  for (size_t i = 0; i < a.coreTimes.size() && i < b.coreTimes.size(); ++i)
    combine(a.coreTimes[i], b.coreTimes[i], sign);
  for (size_t i = 0; i < a.l1.size() && i < b.l1.size(); ++i) combine(a.l1[i], b.l1[i], sign);
  combine(a.l2.cache, b.l2.cache, sign);
  combine(a.l2.dram.reads, b.l2.dram.reads, sign);
  combine(a.l2.dram.bytes, b.l2.dram.bytes, sign);
  combine(a.l2.dram.busyCycles, b.l2.dram.busyCycles, sign);
  combine(a.l2.portQueueCycles, b.l2.portQueueCycles, sign);
  combine(a.l2.mshrQueueCycles, b.l2.mshrQueueCycles, sign);
  for (const auto& [wait, jobs] : b.waitHistogram) {
    combine(a.waitHistogram[wait], jobs, sign);
    if (a.waitHistogram[wait] == 0) a.waitHistogram.erase(wait);
  }
  combine(a.jobManagerStallCycles, b.jobManagerStallCycles, sign);
  combine(a.stackOverflows, b.stackOverflows, sign);
  combine(a.belowResolution, b.belowResolution, sign);
  combine(a.totalCost, b.totalCost, sign);
  combine(a.totalBlocked, b.totalBlocked, sign);
}

}  // namespace

RtuStatistics statisticsAfter(const RtuStatistics& whole, const RtuStatistics& prefix,
                              uint64_t rays, uint64_t cycles) {
  RtuStatistics part = whole;
  combineCounters(part, prefix, -1);
  part.rays = rays;
  part.totalCycles = cycles;
  return part;
}

void addStatistics(RtuStatistics& total, const RtuStatistics& part) {
  if (total.coreTimes.empty()) {
    const uint64_t rays = total.rays, cycles = total.totalCycles;
    total = part;
    total.rays = rays + part.rays;
    total.totalCycles = cycles + part.totalCycles;
    return;
  }
  combineCounters(total, part, +1);
  total.rays += part.rays;
  total.totalCycles += part.totalCycles;
  total.maxWait = std::max(total.maxWait, part.maxWait);
  total.maxWaitWithReadyCore = std::max(total.maxWaitWithReadyCore, part.maxWaitWithReadyCore);
  total.resultBuffersMaxFull = std::max(total.resultBuffersMaxFull, part.resultBuffersMaxFull);
  total.reorderMaxOccupancy = std::max(total.reorderMaxOccupancy, part.reorderMaxOccupancy);
  total.maxCost = std::max(total.maxCost, part.maxCost);
  total.maxBlocked = std::max(total.maxBlocked, part.maxBlocked);
  total.hostSeconds += part.hostSeconds;
}

}  // namespace rtu
