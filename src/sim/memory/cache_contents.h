#pragma once
// The lines resident in the caches when a run starts: an L1 per core and the shared L2, their data
// there from cycle 0. Sampled simulation warms them functionally before each block
// (src/run/cache_warmer.h) instead of simulating every ray before it.

#include <vector>

#include "sim/memory/cache_array.h"

namespace rtu {

struct CacheContents {
  std::vector<CacheArray> l1;  // per core
  std::vector<CacheArray> l2;  // the shared L2
};

}  // namespace rtu
