#include "run/cache_warmer.h"

#include "sim/memory/l1_cache_timing.h"

namespace rtu {

CacheWarmer::CacheWarmer(WordMemory memory, const RtuConfig& config)
    : memory_(memory),
      golden_(config.golden()),
      cores_(config.cores),
      core_(FixedArith{golden_.format}, golden_.stackFrames) {
  contents_.l1.assign(static_cast<size_t>(cores_), CacheArray(config.memory.l1));
  contents_.l2.assign(1, CacheArray(config.memory.l2));
}

void CacheWarmer::warmUpTo(const std::vector<TraversalJob>& jobs, uint64_t end) {
  for (; next_ < end; ++next_) {
    const TraversalJob& job = jobs[next_];
    const int core = static_cast<int>(next_ % static_cast<uint64_t>(cores_));
    core_.start(convertToFixed(job.t0Bits, golden_.format, golden_.conversion),
                convertToFixed(job.t1Bits, golden_.format, golden_.conversion), job.a, job.root);
    while (core_.busy())
      core_.step([&](uint32_t address) {
        touch(core, address);
        return memory_.read(address);
      });
    core_.finish();
  }
}

void CacheWarmer::touch(int core, uint32_t wordAddress) {
  const uint64_t byteAddress = L1CacheTiming::byteAddress(wordAddress);
  if (!contents_.l1[static_cast<size_t>(core)].touch(byteAddress))
    contents_.l2.front().touch(byteAddress);
}

}  // namespace rtu
