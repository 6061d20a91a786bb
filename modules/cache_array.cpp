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

bool CacheArray::touch(uint64_t byteAddress) {
  const uint64_t line = lineOf(byteAddress);
  size_t i = find(line);
  const bool resident = i != kAbsent;
  if (resident) {
    if (config_.replacement == Replacement::Lru) ways_[i].stamp = ++clock_;
  } else {
    i = wayFor(line);
    ways_[i] = {line, 0, ++clock_};
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

size_t CacheArray::wayFor(uint64_t line) {
  const size_t first = firstWayOf(line);
  const size_t end = first + config_.ways;
  size_t empty = kAbsent, oldest = first;
  uint64_t oldestStamp = ways_[first].stamp;  // in a register, not loaded again for each way
  for (size_t i = first; i < end; ++i) {
    const Way& way = ways_[i];
    if (!way.valid()) {
      if (empty == kAbsent) empty = i;
    } else if (way.line == line) {
      failResident(line);
    } else if (way.stamp < oldestStamp) {
      oldest = i;
      oldestStamp = way.stamp;
    }
  }
  if (empty != kAbsent) return empty;
  // Modulo rather than std::uniform_int_distribution, whose output differs between standard
  // libraries: a seed then gives the same victims everywhere (the bias is below 2^-32).
  if (config_.replacement == Replacement::Random) return first + random_() % config_.ways;
  return oldest;
}

}  // namespace rtu
