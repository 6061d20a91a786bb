#pragma once
// Configuration of the memory hierarchy behind the traversal cores: the thesis's ideal ROM, or a
// private L1 per core, a shared L2 and DRAM (section 5.3.5 leaves the memory to future work).
// Sizes are in bytes, latencies and times in core clock cycles.

#include <cstdint>
#include <string>

namespace rtu {

enum class Replacement { Lru, Fifo, Random };

// "lru", "fifo" or "random"; anything else throws std::invalid_argument.
Replacement parseReplacement(const std::string& name);
const char* toString(Replacement replacement);

struct CacheConfig {
  uint32_t sizeBytes = 4 * 1024;
  uint32_t lineBytes = 32;
  uint32_t ways = 4;
  Replacement replacement = Replacement::Lru;
  // Cycles from accepting a request to the data of a resident line; a miss goes to the next
  // level after this tag check.
  uint32_t hitLatency = 1;
  uint32_t maxOutstandingMisses = 1;
  // Seed of the victim choice under Replacement::Random.
  uint64_t seed = 1;

  // Only meaningful once validate() accepted the configuration.
  uint32_t sets() const { return sizeBytes / (lineBytes * ways); }

  // The defaults of each level.
  static CacheConfig l1() { return {}; }
  static CacheConfig l2() {
    CacheConfig config;
    config.sizeBytes = 128 * 1024;
    config.lineBytes = 64;
    config.ways = 8;
    config.hitLatency = 8;
    config.maxOutstandingMisses = 8;
    return config;
  }
};

struct DramConfig {
  // Cycles from issuing a read to the start of its data transfer.
  uint32_t latency = 40;
  // Width of the data bus that transfers lines one after another.
  double bytesPerCycle = 8.0;
};

struct MemoryConfig {
  // The thesis's ROM, every word available at once; the cache and DRAM settings are then unused
  // (validate() still checks them: an impossible option is an error either way).
  bool ideal = false;
  CacheConfig l1 = CacheConfig::l1();
  CacheConfig l2 = CacheConfig::l2();
  DramConfig dram;
};

// Throws std::invalid_argument naming the level and the problem for configurations that cannot
// be built: lines that are not a power of two of at least one word, a size that is not a whole
// power-of-two number of sets, no ways, no miss slots, a DRAM bus without bandwidth, or an L2
// line shorter than the L1 line (an L1 fill must come from a single L2 line).
void validate(const CacheConfig& cache, const std::string& level);
void validate(const DramConfig& dram);
void validate(const MemoryConfig& memory);

}  // namespace rtu
