#include "sim/rtu_config.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "base/timing_limits.h"
#include "kinds/registry.h"
#include "rtu/host_memory.h"
#include "sim/memory/cache_array.h"

namespace rtu {
namespace {

// The tag arrays are allocated whole when the model is built: refuse what this machine cannot hold,
// and cap them at 4 GiB whatever it holds (256MiB L1s of 4-byte lines at 4 cores took 8.5 GB and
// 35 s to allocate for an 8x8 frame).
constexpr uint64_t kMaxCacheTagBytes = uint64_t{4} << 30;

void checkCacheTagsFit(const RtuConfig& config) {
  if (config.memory.ideal) return;
  const uint64_t l1 = CacheArray::tagBytes(config.memory.l1);
  const uint64_t total =
      l1 * static_cast<uint64_t>(config.cores) + CacheArray::tagBytes(config.memory.l2);
  const uint64_t available = std::min(physicalMemoryBytes(), kMaxCacheTagBytes);
  if (total <= available) return;
  throw std::invalid_argument(
      "the cache tag arrays would need " + formatGiB(static_cast<double>(total)) + " (" +
      std::to_string(config.cores) + " L1 caches of " + formatGiB(static_cast<double>(l1)) +
      " and the L2), more than the " + formatGiB(static_cast<double>(available)) +
      " allowed (at most 4 GiB, and this machine's memory): lower --l1-size, --l2-size or "
      "--cores, or raise --l1-line or --l2-line");
}

// A kind's read of kWordsPerRead words, aligned to its size, lies within one line of each cache.
void checkAccessFitsLines(const RtuConfig& config) {
  if (config.memory.ideal) return;
  const uint32_t accessBytes = withCoreKind(config.core, [](auto kind) {
    return uint32_t{sizeof(uint32_t)} * decltype(kind)::kWordsPerRead;
  });
  for (const auto& [level, cache] : {std::pair{"L1", config.memory.l1}, {"L2", config.memory.l2}})
    if (cache.lineBytes < accessBytes)
      throw std::invalid_argument("the " + config.core + " core reads " +
                                  std::to_string(accessBytes) + " bytes at once, more than the " +
                                  level + "'s " + std::to_string(cache.lineBytes) +
                                  "-byte line: raise its line size");
}

// core.triangle.shared_by: 1 to the core count, for a kind with a triangle unit (with another it
// has no effect and is not checked).
void checkTriangleSharing(const RtuConfig& config) {
  const bool unit =
      withCoreKind(config.core, [](auto kind) { return HasTriangleUnit<decltype(kind)>::value; });
  if (!unit || (config.triangleSharedBy >= 1 && config.triangleSharedBy <= config.cores)) return;
  throw std::invalid_argument(
      "core.triangle.shared_by must be 1 to the core count (" + std::to_string(config.cores) +
      "): cores per ray/triangle unit, got " + std::to_string(config.triangleSharedBy));
}

}  // namespace

bool RtuConfig::trianglesShared() const {
  return triangleSharedBy > 1 &&
         withCoreKind(core, [](auto kind) { return HasTriangleUnit<decltype(kind)>::value; });
}

HostLinkConfig RtuConfig::outputLink() const {
  HostLinkConfig link = hostOutput;
  link.recordBytes = withCoreKind(core, [this](auto kind) {
    using Kind = decltype(kind);
    return Kind::resultRecordBytes(coreConfig<Kind>());
  });
  return link;
}

void validate(const RtuConfig& config) {
  if (config.cores < 1 || config.cores > kMaxCores)
    throw std::invalid_argument("the RTU needs 1 to " + std::to_string(kMaxCores) + " cores, got " +
                                std::to_string(config.cores));
  CoreKinds::validateConfigs(config.coreConfigs);
  checkTriangleSharing(config);
  if (!(config.clockMhz >= kMinClockMhz && config.clockMhz <= kMaxClockMhz))  // NaN fails too
    throw std::invalid_argument("clock must be 1 MHz to 1 THz (1 .. 1e6 MHz), got " +
                                std::to_string(config.clockMhz) + " MHz");
  config.sceneManager.validate();
  if (config.reorderCapacity < 0)
    throw std::invalid_argument("reorder buffer capacity must not be negative");
  if (config.warmFrames < 0 || config.warmFrames > kMaxWarmFrames)
    throw std::invalid_argument("warm_frames must be 0 to " + std::to_string(kMaxWarmFrames) +
                                ", got " + std::to_string(config.warmFrames));
  validate(config.memory);  // settings are checked even when ideal memory ignores them
  checkCacheTagsFit(config);
  checkAccessFitsLines(config);
  validate(config.hostInput, "host input");
  validate(config.hostOutput, "host output");
}

}  // namespace rtu
