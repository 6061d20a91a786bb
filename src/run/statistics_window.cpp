#include "run/statistics_window.h"

#include <utility>

namespace rtu {

RtuStatistics statisticsAfter(const RtuStatistics& whole, const RtuStatistics& prefix,
                              uint64_t rays, uint64_t cycles) {
  RtuStatistics part = whole;
  subtractStatisticsOf(part, prefix);
  part.rays = rays;
  part.totalCycles = cycles;
  return part;
}

void addStatistics(RtuStatistics& total, const RtuStatistics& part) {
  if (!total.coreTimes.empty()) return addStatisticsOf(total, part);
  RtuStatistics first = part;
  first.rays += total.rays;
  first.totalCycles += total.totalCycles;
  total = std::move(first);
}

}  // namespace rtu
