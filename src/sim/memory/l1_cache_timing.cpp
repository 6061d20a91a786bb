#include "sim/memory/l1_cache_timing.h"

#include <utility>

namespace rtu {

namespace {

// Validation has to precede the array's construction, hence in the initializer list.
const CacheConfig& validated(const CacheConfig& config) {
  validate(config, "L1");
  return config;
}

}  // namespace

L1CacheTiming::L1CacheTiming(const CacheConfig& config, NextLevel next, uint64_t unitsPerCycle)
    : array_(validated(config)),
      next_(std::move(next)),
      hitLatency_(uint64_t{config.hitLatency} * unitsPerCycle) {}

uint64_t L1CacheTiming::read(uint32_t wordAddress, uint64_t cycle) {
  const L1Lookup result = lookup(wordAddress, cycle);
  if (result.hit) return result.cycle;
  return fill(wordAddress, next_(result.lineAddress, result.cycle));
}

}  // namespace rtu
