#pragma once
// Functional warming (SMARTS, Wunderlich et al. 2003): the caches' contents brought up to date
// with rays that are not simulated, by tracing them untimed and touching, for each word a traversal
// reads, its line in an L1 and, when the L1 did not hold it, in the L2. Nothing is timed or
// counted. Which core runs a ray depends on timing the warmer does not model, so ray i warms the
// L1 of core i mod cores, as the cyclic scheduler hands out rays of equal cost.

#include <cstdint>
#include <vector>

#include "kinds/svo/golden_model.h"
#include "sim/memory/cache_contents.h"
#include "sim/rtu_config.h"

namespace rtu {

class CacheWarmer {
 public:
  // `config.memory` must be cached.
  CacheWarmer(WordMemory memory, const RtuConfig& config);

  // Traces jobs[next .. end) untimed, touching their lines; `next` is where the last call ended.
  void warmUpTo(const std::vector<TraversalJob>& jobs, uint64_t end);
  uint64_t next() const { return next_; }
  const CacheContents& contents() const { return contents_; }

 private:
  void touch(int core, uint32_t wordAddress);

  WordMemory memory_;
  GoldenConfig golden_;
  int cores_;
  TraversalCore<FixedArith> core_;
  CacheContents contents_;
  uint64_t next_ = 0;
};

}  // namespace rtu
