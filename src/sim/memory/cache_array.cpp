#include "sim/memory/cache_array.h"

#include <stdexcept>
#include <string>

namespace rtu {

namespace {

// The bits of ceil(log2(count)): log2 for a power of two, enough for the numbers below count.
int bitsFor(uint32_t count) {
  int shift = 0;
  while ((uint64_t{1} << shift) < count) ++shift;
  return shift;
}

}  // namespace

const StatisticGroup<CacheStats>& CacheStats::declaration() {
  static const StatisticGroup<CacheStats> group =
      StatisticGroup<CacheStats>("a cache")
          .count(Statistic("accesses", "reads", "lines looked up: hits + merged + misses"),
                 &CacheStats::accesses)
          .count(Statistic("hits", "reads", "the line resident and filled"), &CacheStats::hits)
          .count(Statistic("merged", "reads",
                           "the line resident but still in flight: a merged miss"),
                 &CacheStats::merged)
          .count(Statistic("misses", "reads", "the line not resident: a fill"), &CacheStats::misses)
          .count(Statistic("evictions", "lines", "allocations that replaced a valid line"),
                 &CacheStats::evictions)
          .derived(Statistic("hit_rate", "",
                             "share of reads answered by a resident line: (hits + merged) / "
                             "accesses, 0 without reads"),
                   hitRate);
  return group;
}

double hitRate(const CacheStats& stats) {
  return stats.accesses == 0
             ? 0.0
             : static_cast<double>(stats.hits + stats.merged) / static_cast<double>(stats.accesses);
}

CacheArray::CacheArray(const CacheConfig& config)
    : config_(config),
      lineShift_(bitsFor(config.lineBytes)),
      setMask_(config.sets() - 1),
      waysPerSet_(config.ways),
      wayBits_(bitsFor(config.ways)),
      wayMask_((uint64_t{1} << wayBits_) - 1),
      lines_(size_t{config.sets()} * config.ways, kEmpty),
      ways_(lines_.size()),
      mostRecent_(config.sets(), 0),
      random_(config.seed) {
  for (size_t i = 0; i < ways_.size(); ++i) ways_[i].stamp = i % waysPerSet_;  // order 0
}

bool CacheArray::touch(uint64_t byteAddress) {
  const uint64_t line = lineOf(byteAddress);
  const size_t set = line & setMask_;
  const size_t first = set * waysPerSet_;
  size_t i = find(line, first);
  const bool resident = i != kAbsent;
  if (resident) {
    if (config_.replacement == Replacement::Lru) ways_[i].stamp = newStamp(i - first);
  } else {
    i = victimFor(first);
    lines_[i] = line;
    ways_[i] = {0, newStamp(i - first)};
    missedLine_ = kEmpty;
  }
  mostRecent_[set] = static_cast<uint32_t>(i - first);
  return resident;
}

bool CacheArray::contains(uint64_t byteAddress) const {
  return find(lineOf(byteAddress)) != kAbsent;
}

void CacheArray::failResident(uint64_t line) const {
  throw std::logic_error("CacheArray::allocate: line of address " +
                         std::to_string(line << lineShift_) + " is already resident");
}

// Modulo rather than std::uniform_int_distribution, whose output differs between standard
// libraries: a seed then gives the same victims everywhere (the bias is below 2^-32).
size_t CacheArray::randomWay(size_t first) { return first + random_() % config_.ways; }

}  // namespace rtu
