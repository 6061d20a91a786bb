#include "sim/rtu_resources.h"

#include <algorithm>

#include "kinds/registry.h"

namespace rtu {
namespace {

int log2Of(uint64_t value) {
  int bits = 0;
  while (value > 1) {
    value >>= 1;
    ++bits;
  }
  return bits;
}

CoreResources chosenCore(const RtuConfig& config) {
  return withCoreKind(config.core, [&config](auto kind) {
    return coreResources(config.coreConfig<decltype(kind)>());
  });
}

}  // namespace

void addCache(const CacheConfig& cache, const std::string& name, int64_t count,
              ResourceEstimate& estimate) {
  const int tag = 32 - log2Of(cache.sets()) - log2Of(cache.lineBytes);
  estimate.memories.push_back({name + " data", int64_t{cache.sizeBytes} / 8, 64, count});
  estimate.memories.push_back(
      {name + " tags", cache.sets(), static_cast<int>(cache.ways) * (tag + 1), count});
}

ResourceEstimate rtuResources(const RtuConfig& config, uint64_t imageWords) {
  return rtuResources(config, imageWords, chosenCore(config));
}

ResourceEstimate rtuResources(const RtuConfig& config, uint64_t imageWords,
                              const CoreResources& core) {
  ResourceEstimate estimate;
  estimate.add(core.core, config.cores);
  const int shared = std::max(config.triangleSharedBy, 1);
  estimate.add(core.triangleUnit, (config.cores + shared - 1) / shared);
  if (config.memory.ideal) {
    estimate.memories.push_back({"scene memory", static_cast<int64_t>(imageWords), 32});
  } else {
    addCache(config.memory.l1, "l1", config.cores, estimate);
    addCache(config.memory.l2, "l2", 1, estimate);
  }
  const int resultBits = static_cast<int>(config.outputLink().recordBytes * 8);
  estimate.memories.push_back({"result buffers", 1, resultBits, config.cores});
  if (config.reorderCapacity > 0)
    estimate.memories.push_back({"reorder buffer", config.reorderCapacity, resultBits});
  return estimate;
}

}  // namespace rtu
