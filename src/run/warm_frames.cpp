#include "run/warm_frames.h"

#include "kinds/registry.h"
#include "run/cache_warmer.h"

namespace rtu {

std::optional<CacheContents> warmedCaches(const WordMemory& memory,
                                          const std::vector<HostRecord>& records,
                                          const RtuConfig& config) {
  if (config.warmFrames <= 0 || config.memory.ideal) return std::nullopt;
  return withCoreKind(config.core, [&](auto kind) {
    CacheWarmer<decltype(kind)> warmer(memory, config);
    warmer.warmFrames(records, config.warmFrames);
    return warmer.contents();
  });
}

}  // namespace rtu
