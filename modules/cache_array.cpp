#include "cache_array.h"

#include <stdexcept>
#include <string>

namespace rtu {

namespace {

int log2Exact(uint32_t powerOfTwo) {
  int shift = 0;
  while ((1u << shift) < powerOfTwo) ++shift;
  return shift;
}

}  // namespace

CacheArray::CacheArray(const CacheConfig& config)
    : config_(config),
      lineShift_(log2Exact(config.lineBytes)),
      setMask_(config.sets() - 1),
      waysPerSet_(config.ways),
      lines_(size_t{config.sets()} * config.ways, kEmpty),
      ways_(lines_.size()),
      random_(config.seed) {}

bool CacheArray::touch(uint64_t byteAddress) {
  const uint64_t line = lineOf(byteAddress);
  size_t i = find(line);
  const bool resident = i != kAbsent;
  if (resident) {
    if (config_.replacement == Replacement::Lru) ways_[i].stamp = ++clock_;
  } else {
    i = wayFor(line);
    lines_[i] = line;
    ways_[i] = {0, ++clock_};
  }
  lastUsed_ = i;
  return resident;
}

bool CacheArray::contains(uint64_t byteAddress) const {
  return find(lineOf(byteAddress)) != kAbsent;
}

void CacheArray::failResident(uint64_t line) const {
  throw std::logic_error("CacheArray::allocate: line of address " +
                         std::to_string(line << lineShift_) + " is already resident");
}

// Empty ways keep stamp 0 (lines are never invalidated) and every allocation takes a new stamp,
// so the way with the smallest stamp, the first of equals, is the first empty way if there is one
// and else the LRU or FIFO victim: one pass, its minimum without a branch to mispredict.
size_t CacheArray::wayFor(uint64_t line) {
  const size_t first = firstWayOf(line);
  const size_t end = first + waysPerSet_;
  size_t oldest = first;
  uint64_t oldestStamp = UINT64_MAX;
  bool resident = false;
  for (size_t i = first; i < end; ++i) {
    resident |= lines_[i] == line;
    const uint64_t stamp = ways_[i].stamp;
    const bool older = stamp < oldestStamp;
    oldestStamp = older ? stamp : oldestStamp;
    oldest = older ? i : oldest;
  }
  if (resident) failResident(line);
  const bool empty = lines_[oldest] == kEmpty;
  // Modulo rather than std::uniform_int_distribution, whose output differs between standard
  // libraries: a seed then gives the same victims everywhere (the bias is below 2^-32).
  if (config_.replacement == Replacement::Random && !empty) return first + random_() % config_.ways;
  return oldest;
}

}  // namespace rtu
