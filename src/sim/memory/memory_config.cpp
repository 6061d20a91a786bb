#include "sim/memory/memory_config.h"

#include <cmath>
#include <stdexcept>

#include "base/timing_limits.h"

namespace rtu {

namespace {

bool isPowerOfTwo(uint64_t value) { return value != 0 && (value & (value - 1)) == 0; }

void require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument(message);
}

// "; nearest valid sizes: A or B bytes": `unit` times the powers of two either side of `size`
// (sizes given in kB are multiples of 1000, not of 1024: 4KB is 4000 bytes).
std::string nearestValid(uint64_t size, uint64_t unit) {
  uint64_t below = unit;
  while (below * 2 <= size) below *= 2;
  if (below > size) return "; the nearest valid size: " + std::to_string(below) + " bytes";
  return "; nearest valid sizes: " + std::to_string(below) + " or " + std::to_string(below * 2) +
         " bytes";
}

}  // namespace

Replacement parseReplacement(const std::string& name) {
  if (name == "lru") return Replacement::Lru;
  if (name == "fifo") return Replacement::Fifo;
  if (name == "random") return Replacement::Random;
  throw std::invalid_argument("unknown replacement policy '" + name +
                              "' (expected lru, fifo or random)");
}

const char* toString(Replacement replacement) {
  switch (replacement) {
    case Replacement::Lru: return "lru";
    case Replacement::Fifo: return "fifo";
    case Replacement::Random: return "random";
  }
  return "?";
}

void validate(const CacheConfig& cache, const std::string& level) {
  const std::string prefix = level + " cache: ";
  const std::string line = std::to_string(cache.lineBytes) + "-byte line";
  require(cache.lineBytes >= 4, prefix + line + " is shorter than a 4-byte word");
  require(isPowerOfTwo(cache.lineBytes),
          prefix + line + " is not a power of two" + nearestValid(cache.lineBytes, 1));
  require(cache.ways > 0, prefix + "needs at least one way");
  require(cache.sizeBytes >= cache.lineBytes,
          prefix + std::to_string(cache.sizeBytes) + " bytes do not hold one " + line);
  // 64 bits: lineBytes * ways may not fit in 32.
  const uint64_t setBytes = uint64_t{cache.lineBytes} * cache.ways;
  require(cache.sizeBytes % setBytes == 0,
          prefix + "size " + std::to_string(cache.sizeBytes) + " is not a multiple of " +
              std::to_string(cache.ways) + " ways x " + line + " (" + std::to_string(setBytes) +
              " bytes)" + nearestValid(cache.sizeBytes, setBytes));
  const uint64_t sets = cache.sizeBytes / setBytes;
  // The set index is a field of the address.
  require(isPowerOfTwo(sets), prefix + std::to_string(sets) + " sets is not a power of two" +
                                  nearestValid(cache.sizeBytes, setBytes));
  require(cache.maxOutstandingMisses > 0, prefix + "needs at least one outstanding miss");
  require(cache.hitLatency <= kMaxLatencyCycles,
          prefix + "hit latency " + std::to_string(cache.hitLatency) + " is above the limit of " +
              std::to_string(kMaxLatencyCycles) + " cycles");
}

void validate(const DramConfig& dram) {
  // Written so that NaN fails too.
  require(dram.bytesPerCycle >= kMinBytesPerCycle && dram.bytesPerCycle <= kMaxBytesPerCycle,
          "DRAM: bytes per cycle must be in " + rateRange() + ", not " +
              std::to_string(dram.bytesPerCycle));
  require(dram.latency <= kMaxLatencyCycles, "DRAM: latency " + std::to_string(dram.latency) +
                                                 " is above the limit of " +
                                                 std::to_string(kMaxLatencyCycles) + " cycles");
}

void validate(const MemoryConfig& memory) {
  validate(memory.l1, "L1");
  validate(memory.l2, "L2");
  validate(memory.dram);
  require(memory.l2.lineBytes >= memory.l1.lineBytes,
          "L2 line (" + std::to_string(memory.l2.lineBytes) +
              " bytes) is shorter than the L1 line (" + std::to_string(memory.l1.lineBytes) +
              " bytes)");
}

}  // namespace rtu
