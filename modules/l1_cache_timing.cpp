#include "l1_cache_timing.h"

#include <algorithm>
#include <utility>

namespace rtu {

namespace {

// Validation has to precede the array's construction, hence in the initializer list.
const CacheConfig& validated(const CacheConfig& config) {
  validate(config, "L1");
  return config;
}

}  // namespace

L1CacheTiming::L1CacheTiming(const CacheConfig& config, NextLevel next)
    : array_(validated(config)), next_(std::move(next)) {}

L1Lookup L1CacheTiming::lookup(uint32_t wordAddress, uint64_t cycle) {
  const uint64_t address = byteAddress(wordAddress);
  const uint64_t tagCheckDone = cycle + array_.config().hitLatency;
  const uint64_t lineAddress = address & ~uint64_t{array_.config().lineBytes - 1};
  const CacheLookup line = array_.access(address, cycle);
  if (line.present) return {true, std::max(tagCheckDone, line.fillCycle), lineAddress};
  return {false, tagCheckDone, lineAddress};
}

uint64_t L1CacheTiming::fill(uint32_t wordAddress, uint64_t readyCycle) {
  array_.allocate(byteAddress(wordAddress), readyCycle);
  return readyCycle;
}

uint64_t L1CacheTiming::read(uint32_t wordAddress, uint64_t cycle) {
  const L1Lookup result = lookup(wordAddress, cycle);
  if (result.hit) return result.cycle;
  return fill(wordAddress, next_(result.lineAddress, result.cycle));
}

}  // namespace rtu
