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
      ways_(size_t{config.sets()} * config.ways),
      random_(config.seed) {}

void CacheArray::allocate(uint64_t byteAddress, uint64_t fillCycle) {
  const uint64_t line = lineOf(byteAddress);
  if (find(line) != kAbsent)
    throw std::logic_error("CacheArray::allocate: line of address " +
                           std::to_string(byteAddress) + " is already resident");
  Way& way = ways_[victim(firstWayOf(line))];
  if (way.valid) ++stats_.evictions;
  way = {true, line, fillCycle, ++clock_};
}

bool CacheArray::touch(uint64_t byteAddress) {
  const uint64_t line = lineOf(byteAddress);
  const size_t i = find(line);
  if (i != kAbsent) {
    if (config_.replacement == Replacement::Lru) ways_[i].stamp = ++clock_;
    return true;
  }
  ways_[victim(firstWayOf(line))] = {true, line, 0, ++clock_};
  return false;
}

bool CacheArray::contains(uint64_t byteAddress) const {
  return find(lineOf(byteAddress)) != kAbsent;
}

size_t CacheArray::victim(size_t firstWay) {
  const size_t end = firstWay + config_.ways;
  for (size_t i = firstWay; i < end; ++i)
    if (!ways_[i].valid) return i;
  // Modulo rather than std::uniform_int_distribution, whose output differs between standard
  // libraries: a seed then gives the same victims everywhere (the bias is below 2^-32).
  if (config_.replacement == Replacement::Random) return firstWay + random_() % config_.ways;
  size_t oldest = firstWay;
  for (size_t i = firstWay + 1; i < end; ++i)
    if (ways_[i].stamp < ways_[oldest].stamp) oldest = i;
  return oldest;
}

}  // namespace rtu
