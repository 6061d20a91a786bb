// The memory hierarchy's timing models: the tag store against an obviously correct reference
// (per-set lists), and the L1/L2/DRAM timing against cycles worked out by hand in the comments.
#include <catch2/catch.hpp>

#include <cmath>
#include <list>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include "base/timing_limits.h"
#include "sim/memory/cache_array.h"
#include "sim/memory/l1_cache_timing.h"
#include "sim/memory/l2_cache_timing.h"
#include "sim/memory/memory_config.h"

using namespace rtu;

namespace {

CacheConfig cacheConfig(uint32_t sizeBytes, uint32_t lineBytes, uint32_t ways,
                        Replacement replacement) {
  CacheConfig config;
  config.sizeBytes = sizeBytes;
  config.lineBytes = lineBytes;
  config.ways = ways;
  config.replacement = replacement;
  return config;
}

// 256 bytes of 16-byte lines in 4 ways: 4 sets, so lines 64 bytes apart share a set.
CacheConfig smallCache(Replacement replacement) { return cacheConfig(256, 16, 4, replacement); }
constexpr uint64_t kSmallSetStride = 64;

// LRU or FIFO the slow, plain way: each set is a list of line numbers, front = next victim. A
// hit moves the line to the back under LRU and leaves it in place under FIFO.
class ReferenceCache {
 public:
  explicit ReferenceCache(const CacheConfig& config) : config_(config), sets_(config.sets()) {}

  bool access(uint64_t byteAddress) {
    const uint64_t line = byteAddress / config_.lineBytes;
    std::list<uint64_t>& set = sets_[line % sets_.size()];
    for (auto it = set.begin(); it != set.end(); ++it) {
      if (*it != line) continue;
      if (config_.replacement == Replacement::Lru) set.splice(set.end(), set, it);
      return true;
    }
    if (set.size() == config_.ways) {
      set.pop_front();
      ++evictions;
    }
    set.push_back(line);
    return false;
  }

  uint64_t evictions = 0;

 private:
  CacheConfig config_;
  std::vector<std::list<uint64_t>> sets_;
};

// The way a cache model is driven: look up, allocate on a miss. Fills complete at once, so
// every later access to the line is a plain hit.
bool accessAndAllocate(CacheArray& array, uint64_t byteAddress) {
  if (array.access(byteAddress, 0).present) return true;
  array.allocate(byteAddress, 0);
  return false;
}

// Runs `addresses` through the model and the reference, access by access.
void checkAgainstReference(const CacheConfig& config, const std::vector<uint64_t>& addresses) {
  CacheArray array(config);
  ReferenceCache reference(config);
  uint64_t hits = 0;
  for (size_t i = 0; i < addresses.size(); ++i) {
    const bool expected = reference.access(addresses[i]);
    INFO("access " << i << " of address " << addresses[i]);
    REQUIRE(accessAndAllocate(array, addresses[i]) == expected);
    hits += expected;
  }
  const CacheStats& stats = array.stats();
  CHECK(stats.accesses == addresses.size());
  CHECK(stats.hits == hits);
  CHECK(stats.misses == addresses.size() - hits);
  CHECK(stats.merged == 0);
  CHECK(stats.evictions == reference.evictions);
}

std::vector<uint64_t> randomAddresses(uint64_t seed, size_t count, uint64_t range) {
  std::mt19937_64 random(seed);
  std::vector<uint64_t> addresses(count);
  for (uint64_t& address : addresses) address = random() % range;
  return addresses;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Configuration

TEST_CASE("Memory configuration: defaults are valid and as specified", "[cache]") {
  const MemoryConfig memory;
  REQUIRE_NOTHROW(validate(memory));
  CHECK(memory.l1.sizeBytes == 4096);
  CHECK(memory.l1.lineBytes == 32);
  CHECK(memory.l1.ways == 4);
  CHECK(memory.l1.sets() == 32);
  CHECK(memory.l1.hitLatency == 1);
  CHECK(memory.l1.maxOutstandingMisses == 1);
  CHECK(memory.l2.sizeBytes == 128 * 1024);
  CHECK(memory.l2.lineBytes == 64);
  CHECK(memory.l2.ways == 8);
  CHECK(memory.l2.sets() == 256);
  CHECK(memory.l2.hitLatency == 8);
  CHECK(memory.l2.maxOutstandingMisses == 8);
  CHECK(memory.l2.replacement == Replacement::Lru);
  CHECK(memory.dram.latency == 40);
  CHECK(memory.dram.bytesPerCycle == 8.0);
}

TEST_CASE("Memory configuration: impossible caches are rejected with the reason", "[cache]") {
  using Catch::Contains;
  MemoryConfig memory;
  CacheConfig& l1 = memory.l1;

  SECTION("line not a power of two") {
    l1.lineBytes = 24;
    CHECK_THROWS_WITH(validate(memory), Contains("L1 cache") && Contains("not a power of two") &&
                                            Contains("nearest valid sizes: 16 or 32 bytes"));
  }
  SECTION("line shorter than a word") {
    l1.lineBytes = 2;
    CHECK_THROWS_WITH(validate(memory), Contains("shorter than a 4-byte word"));
  }
  SECTION("no ways") {
    l1.ways = 0;
    CHECK_THROWS_WITH(validate(memory), Contains("at least one way"));
  }
  SECTION("cache smaller than a line") {
    l1.sizeBytes = 16;
    CHECK_THROWS_WITH(validate(memory), Contains("do not hold one 32-byte line"));
  }
  SECTION("size not a multiple of line x ways") {
    l1.sizeBytes = 96;  // 2 ways x 32 bytes = 64 per set
    l1.ways = 2;
    CHECK_THROWS_WITH(validate(memory), Contains("not a multiple of 2 ways x 32-byte line") &&
                                            Contains("nearest valid sizes: 64 or 128 bytes"));
  }
  SECTION("line x ways overflowing 32 bits") {
    l1.ways = 1u << 31;
    CHECK_THROWS_WITH(validate(memory), Contains("not a multiple"));
  }
  SECTION("sets not a power of two") {
    l1.sizeBytes = 96;  // 3 sets of one 32-byte line
    l1.ways = 1;
    CHECK_THROWS_WITH(validate(memory), Contains("3 sets is not a power of two") &&
                                            Contains("nearest valid sizes: 64 or 128 bytes"));
  }
  SECTION("a size in kB, not KiB") {
    l1.sizeBytes = 4000;  // 4KB; 4 ways x 32-byte lines: sets of 128 bytes
    l1.ways = 4;
    l1.lineBytes = 32;
    CHECK_THROWS_WITH(validate(memory), Contains("nearest valid sizes: 2048 or 4096 bytes"));
  }
  SECTION("no outstanding misses") {
    memory.l2.maxOutstandingMisses = 0;
    CHECK_THROWS_WITH(validate(memory), Contains("L2 cache") && Contains("outstanding miss"));
  }
  SECTION("DRAM without bandwidth") {
    // 1e-18 overflowed the transfer time into a fast bus, 1e-13 .. 1e-16 stalled.
    for (double bytesPerCycle : {0.0, -8.0, std::nan(""), HUGE_VAL, 1e-18, 1e-13, 9e-4, 2e6}) {
      memory.dram.bytesPerCycle = bytesPerCycle;
      CHECK_THROWS_WITH(validate(memory), Contains("DRAM: bytes per cycle"));
    }
  }
  SECTION("latencies beyond the limit") {
    memory.dram.latency = kMaxLatencyCycles + 1;
    CHECK_THROWS_WITH(validate(memory), Contains("DRAM: latency 1000001 is above the limit"));
    memory.dram.latency = kMaxLatencyCycles;
    memory.l2.hitLatency = kMaxLatencyCycles + 1;
    CHECK_THROWS_WITH(validate(memory), Contains("L2 cache: hit latency 1000001"));
  }
  SECTION("L2 line shorter than the L1 line") {
    memory.l2.lineBytes = 16;
    CHECK_THROWS_WITH(validate(memory), Contains("shorter than the L1 line"));
  }
  SECTION("the timing models validate their own configuration") {
    l1.ways = 0;
    CHECK_THROWS_AS(L1CacheTiming(l1), std::invalid_argument);
    CHECK_THROWS_AS(L2CacheTiming(l1, memory.dram), std::invalid_argument);
    memory.dram.bytesPerCycle = 0;
    CHECK_THROWS_AS(L2CacheTiming(memory.l2, memory.dram), std::invalid_argument);
  }
}

TEST_CASE("Memory configuration: edge geometries are valid", "[cache]") {
  CHECK_NOTHROW(validate(cacheConfig(32, 32, 1, Replacement::Lru), "L1"));   // one line
  CHECK_NOTHROW(validate(cacheConfig(256, 4, 64, Replacement::Lru), "L1"));  // fully associative
  CHECK_NOTHROW(validate(cacheConfig(96, 32, 3, Replacement::Lru), "L1"));   // 3 ways, 1 set
}

TEST_CASE("Replacement names", "[cache]") {
  for (Replacement policy : {Replacement::Lru, Replacement::Fifo, Replacement::Random})
    CHECK(parseReplacement(toString(policy)) == policy);
  CHECK(parseReplacement("lru") == Replacement::Lru);
  CHECK(parseReplacement("fifo") == Replacement::Fifo);
  CHECK(parseReplacement("random") == Replacement::Random);
  CHECK_THROWS_WITH(parseReplacement("plru"),
                    "unknown replacement policy 'plru' (expected lru, fifo or random)");
}

// ---------------------------------------------------------------------------------------------
// Tag store

TEST_CASE("Cache array: a line holds every byte in it", "[cache]") {
  CacheArray array(smallCache(Replacement::Lru));
  CHECK_FALSE(accessAndAllocate(array, 0x100));
  for (uint64_t address = 0x100; address < 0x110; address += 4) CHECK(array.contains(address));
  CHECK(accessAndAllocate(array, 0x10F));
  CHECK_FALSE(array.contains(0xFF));
  CHECK_FALSE(array.contains(0x110));
}

TEST_CASE("Cache array: LRU keeps a re-used line, FIFO evicts it", "[cache]") {
  // Five lines of set 0: A B C D fill its 4 ways, A is used again, E needs a victim.
  const uint64_t a = 0, b = kSmallSetStride, c = 2 * kSmallSetStride, d = 3 * kSmallSetStride,
                 e = 4 * kSmallSetStride;
  for (Replacement policy : {Replacement::Lru, Replacement::Fifo}) {
    INFO(toString(policy));
    CacheArray array(smallCache(policy));
    for (uint64_t line : {a, b, c, d}) CHECK_FALSE(accessAndAllocate(array, line));
    CHECK(accessAndAllocate(array, a));
    CHECK_FALSE(accessAndAllocate(array, e));
    // LRU order was B C D A: B goes. FIFO order is A B C D regardless of the hit: A goes.
    const bool lru = policy == Replacement::Lru;
    CHECK(array.contains(a) == lru);
    CHECK(array.contains(b) == !lru);
    CHECK(array.contains(c));
    CHECK(array.contains(d));
    CHECK(array.contains(e));
    CHECK(array.stats().evictions == 1);
    // The other sets are untouched.
    CHECK_FALSE(array.contains(16));
  }
}

TEST_CASE("Cache array: ways + 1 lines cycling through one set always miss", "[cache]") {
  // LRU and FIFO both evict exactly the line that comes next.
  std::vector<uint64_t> addresses;
  for (int round = 0; round < 10; ++round)
    for (uint64_t line = 0; line < 5; ++line) addresses.push_back(line * kSmallSetStride);
  for (Replacement policy : {Replacement::Lru, Replacement::Fifo}) {
    INFO(toString(policy));
    CacheArray array(smallCache(policy));
    for (uint64_t address : addresses) REQUIRE_FALSE(accessAndAllocate(array, address));
    CHECK(array.stats().misses == 50);
    CHECK(array.stats().evictions == 46);
    checkAgainstReference(smallCache(policy), addresses);
  }
}

TEST_CASE("Cache array: ways lines in one set stay resident", "[cache]") {
  CacheArray array(smallCache(Replacement::Fifo));
  for (int round = 0; round < 5; ++round)
    for (uint64_t line = 0; line < 4; ++line) accessAndAllocate(array, line * kSmallSetStride);
  CHECK(array.stats().misses == 4);
  CHECK(array.stats().hits == 16);
  CHECK(array.stats().evictions == 0);
}

TEST_CASE("Cache array: hand-made sequences match the reference", "[cache]") {
  const uint64_t s = kSmallSetStride;
  const std::vector<uint64_t> sequence = {0,     s,     2 * s, 3 * s, 0,     4 * s, s,
                                          16,    2 * s, 5 * s, 0,     3 * s, 4 * s, 17,
                                          6 * s, s,     0,     2 * s, 48,    3 * s};
  for (Replacement policy : {Replacement::Lru, Replacement::Fifo}) {
    INFO(toString(policy));
    checkAgainstReference(smallCache(policy), sequence);
  }
}

TEST_CASE("Cache array: random sequences match the reference", "[cache]") {
  for (Replacement policy : {Replacement::Lru, Replacement::Fifo}) {
    for (const CacheConfig& geometry : {cacheConfig(256, 16, 4, policy),     // 4 sets x 4 ways
                                        cacheConfig(512, 32, 1, policy),     // direct-mapped
                                        cacheConfig(256, 16, 16, policy),    // fully associative
                                        cacheConfig(384, 32, 3, policy)}) {  // 4 sets x 3 ways
      INFO(toString(policy) << ", " << geometry.ways << " ways");
      // Addresses over three times the capacity: plenty of hits and of evictions.
      for (uint64_t seed : {1, 2, 3})
        checkAgainstReference(geometry, randomAddresses(seed, 20000, 3 * geometry.sizeBytes));
    }
  }
}

TEST_CASE("Cache array: random replacement evicts one line of the set", "[cache]") {
  const CacheConfig config = smallCache(Replacement::Random);
  CacheArray array(config);
  // The model's contents as far as the test knows them: one set of lines per set.
  std::vector<std::set<uint64_t>> sets(config.sets());
  for (uint64_t address : randomAddresses(7, 20000, 3 * config.sizeBytes)) {
    const uint64_t line = address / config.lineBytes;
    std::set<uint64_t>& set = sets[line % config.sets()];
    const bool hit = accessAndAllocate(array, address);
    REQUIRE(hit == (set.count(line) == 1));
    if (hit) continue;
    std::set<uint64_t> evicted;
    for (uint64_t old : set)
      if (!array.contains(old * config.lineBytes)) evicted.insert(old);
    // A free way is used first; else exactly one line of this set goes.
    REQUIRE(evicted.size() == (set.size() == config.ways ? 1u : 0u));
    for (uint64_t old : evicted) set.erase(old);
    set.insert(line);
  }
  // The other sets never lost a line: each set's residents are exactly what the test tracks.
  for (size_t s = 0; s < sets.size(); ++s)
    for (uint64_t line : sets[s]) REQUIRE(array.contains(line * config.lineBytes));
}

TEST_CASE("Cache array: random replacement picks every way about equally", "[cache]") {
  // Fill set 0 with lines 0..3, then a fifth line evicts one; over 400 seeds each line should be
  // the victim about 100 times.
  std::vector<int> victimCounts(4);
  for (uint64_t seed = 1; seed <= 400; ++seed) {
    CacheConfig config = smallCache(Replacement::Random);
    config.seed = seed;
    CacheArray array(config);
    for (uint64_t line = 0; line < 5; ++line) accessAndAllocate(array, line * kSmallSetStride);
    for (uint64_t line = 0; line < 4; ++line)
      if (!array.contains(line * kSmallSetStride)) ++victimCounts[line];
  }
  CHECK(victimCounts[0] + victimCounts[1] + victimCounts[2] + victimCounts[3] == 400);
  for (int count : victimCounts) CHECK((count > 60 && count < 140));
}

TEST_CASE("Cache array: random replacement is deterministic per seed", "[cache]") {
  auto hitPattern = [](uint64_t seed) {
    CacheConfig config = smallCache(Replacement::Random);
    config.seed = seed;
    CacheArray array(config);
    std::vector<bool> hits;
    for (uint64_t address : randomAddresses(11, 5000, 3 * config.sizeBytes))
      hits.push_back(accessAndAllocate(array, address));
    return hits;
  };
  CHECK(hitPattern(5) == hitPattern(5));
  CHECK(hitPattern(5) != hitPattern(6));
}

TEST_CASE("Cache array: an access before the fill completes is a merged miss", "[cache]") {
  CacheArray array(smallCache(Replacement::Lru));
  CHECK_FALSE(array.access(0x40, 10).present);
  array.allocate(0x40, 50);
  const CacheLookup inFlight = array.access(0x44, 20);
  CHECK(inFlight.present);
  CHECK(inFlight.fillCycle == 50);
  const CacheLookup filled = array.access(0x48, 50);  // filled at 50: a hit from 50 on
  CHECK(filled.present);
  CHECK(filled.fillCycle == 50);
  const CacheStats& stats = array.stats();
  CHECK(stats.accesses == 3);
  CHECK(stats.misses == 1);
  CHECK(stats.merged == 1);
  CHECK(stats.hits == 1);
  CHECK_THROWS_AS(array.allocate(0x40, 60), std::logic_error);  // already resident
}

// ---------------------------------------------------------------------------------------------
// L2 + DRAM timing. Defaults unless said otherwise: 64-byte lines, hit latency 8, 8 MSHRs,
// DRAM latency 40 at 8 bytes per cycle, so a line takes 8 cycles on the bus.

TEST_CASE("L2 timing: a miss goes to DRAM, then the line hits", "[cache]") {
  L2CacheTiming l2(CacheConfig::l2(), DramConfig{});
  // Accept 0, tag check until 8, DRAM transfer from 8 + 40 = 48 for 8 cycles: 56.
  CHECK(l2.read(0x1000, 0) == 56);
  // Another word of the filled line: 100 + 8.
  CHECK(l2.read(0x103C, 100) == 108);
  const L2Stats stats = l2.stats();
  CHECK(stats.cache.accesses == 2);
  CHECK(stats.cache.misses == 1);
  CHECK(stats.cache.hits == 1);
  CHECK(stats.dram.bytes == 64);
  CHECK(stats.dram.busyCycles == 8);
  CHECK(stats.portQueueCycles == 0);
  CHECK(stats.mshrQueueCycles == 0);
}

TEST_CASE("L2 timing: same-cycle requests are serialised by the port", "[cache]") {
  L2CacheTiming l2(CacheConfig::l2(), DramConfig{});
  l2.read(0x000, 0);  // fills at 56
  l2.read(0x040, 1);  // fills at 64
  // Three hits requested at 200 are accepted at 200, 201, 202.
  CHECK(l2.read(0x000, 200) == 208);
  CHECK(l2.read(0x040, 200) == 209);
  CHECK(l2.read(0x000, 200) == 210);
  CHECK(l2.stats().portQueueCycles == 0 + 1 + 2);
  // The port is free again once time has moved past the queue.
  CHECK(l2.read(0x040, 300) == 308);
  CHECK(l2.stats().portQueueCycles == 3);
}

TEST_CASE("L2 timing: requests for a line in flight merge with its miss", "[cache]") {
  L2CacheTiming l2(CacheConfig::l2(), DramConfig{});
  CHECK(l2.read(0x200, 0) == 56);
  // Same line at 10: in flight until 56, no second DRAM read.
  CHECK(l2.read(0x220, 10) == 56);
  // At 50 it is still in flight; the tag check (50 + 8 = 58) ends after the fill.
  CHECK(l2.read(0x200, 50) == 58);
  // At 56 it is filled: a plain hit.
  CHECK(l2.read(0x204, 56) == 64);
  const L2Stats stats = l2.stats();
  CHECK(stats.cache.misses == 1);
  CHECK(stats.cache.merged == 2);
  CHECK(stats.cache.hits == 1);
  CHECK(stats.dram.reads == 1);
}

TEST_CASE("L2 timing: DRAM bandwidth spaces back-to-back fills", "[cache]") {
  L2CacheTiming l2(CacheConfig::l2(), DramConfig{});
  // A: accept 0, issue 8, transfer 48..56. B: accept 1 (port), issue 9, its data could start at
  // 49 but the bus is busy until 56: 56..64. C: accept 2, issue 10, bus 64..72.
  CHECK(l2.read(0x000, 0) == 56);
  CHECK(l2.read(0x040, 0) == 64);
  CHECK(l2.read(0x080, 0) == 72);
  CHECK(l2.stats().dram.busyCycles == 24);
  CHECK(l2.stats().dram.bytes == 192);
  CHECK(l2.stats().mshrQueueCycles == 0);

  // A miss long after finds the bus idle: 100 + 8 + 40 + 8.
  CHECK(l2.read(0x0C0, 100) == 156);
}

TEST_CASE("L2 timing: a fractional bus width rounds the transfer up", "[cache]") {
  DramConfig dram;
  dram.bytesPerCycle = 3.0;  // 64 / 3 = 21.3: 22 cycles
  L2CacheTiming l2(CacheConfig::l2(), dram);
  CHECK(l2.read(0, 0) == 8 + 40 + 22);
  CHECK(l2.stats().dram.busyCycles == 22);
}

TEST_CASE("L2 timing: a miss waits for a free MSHR", "[cache]") {
  CacheConfig config = CacheConfig::l2();
  config.maxOutstandingMisses = 1;
  L2CacheTiming l2(config, DramConfig{});
  // A: issue 8, fill 56, holding the only MSHR until then.
  CHECK(l2.read(0x000, 0) == 56);
  // B: tag check until 9, then waits for A's MSHR until 56; DRAM 56 + 40 = 96, fill 104.
  CHECK(l2.read(0x040, 1) == 104);
  CHECK(l2.stats().mshrQueueCycles == 56 - 9);
  // A hit meanwhile does not need an MSHR: 60 + 8.
  CHECK(l2.read(0x000, 60) == 68);
  // C: tag check ends at 104, just as B releases the MSHR: no wait; fill 104 + 40 + 8.
  CHECK(l2.read(0x080, 96) == 152);
  CHECK(l2.stats().mshrQueueCycles == 47);
}

TEST_CASE("L2 timing: MSHRs are taken in release order", "[cache]") {
  CacheConfig config = CacheConfig::l2();
  config.maxOutstandingMisses = 2;
  L2CacheTiming l2(config, DramConfig{});
  CHECK(l2.read(0x000, 0) == 56);  // issue 8, bus 48..56
  CHECK(l2.read(0x040, 0) == 64);  // accept 1, issue 9, bus 56..64
  // Both MSHRs busy at 10: waits for the first release, 56; bus 96..104.
  CHECK(l2.read(0x080, 0) == 104);
  // Tag check at 11: the MSHR released at 64 is the earliest; bus 104..112.
  CHECK(l2.read(0x0C0, 0) == 112);
  CHECK(l2.stats().mshrQueueCycles == (56 - 10) + (64 - 11));
}

TEST_CASE("L2 timing: requests must come in cycle order", "[cache]") {
  L2CacheTiming l2(CacheConfig::l2(), DramConfig{});
  l2.read(0, 10);
  CHECK_NOTHROW(l2.read(64, 10));
  CHECK_THROWS_AS(l2.read(0, 9), std::logic_error);
}

// RequestOrder::Any (the loosely-timed L2): a miss counts the MSHRs busy at its tag check's end
// T, those issued by T and released after it, whenever they were requested. The DRAM here is a
// function of the issue cycle, so that only the port and the MSHRs shape the cycles.

TEST_CASE("L2 out of order: a miss waits until fewer than all MSHRs are busy, cycles by hand",
          "[cache]") {
  CacheConfig config = CacheConfig::l2();  // hit latency 8
  config.maxOutstandingMisses = 2;
  // The DRAM delivers the n-th read latencies[n] cycles after its issue, and notes the issue.
  const std::vector<uint64_t> latencies{100, 30, 132, 10, 10, 20};
  std::vector<uint64_t> issues;
  L2CacheTiming l2(config, DramConfig{}, RequestOrder::Any, [&](uint32_t, uint64_t issue) {
    issues.push_back(issue);
    return issue + latencies.at(issues.size() - 1);
  });
  // A at 200: tag check to 208, none busy: issue 208, fill 308.              A uses [208, 308)
  CHECK(l2.read(0 * 64, 200) == 308);
  // B at 220: tag check to 228, A busy, one of two: issue 228, fill 258.     B uses [228, 258)
  CHECK(l2.read(1 * 64, 220) == 258);
  // C at 100, before both: tag check to 108, A and B are issued later, none busy: issue 108,
  // fill 240, although three are then busy in 228..240 (the documented approximation).
  //                                                                          C uses [108, 240)
  CHECK(l2.read(2 * 64, 100) == 240);
  // D at 222: tag check to 230, A, B and C busy. C's release at 240 leaves two (A, B) busy,
  // B's at 258 one: issue 258, fill 268.                                     D uses [258, 268)
  CHECK(l2.read(3 * 64, 222) == 268);
  // E at 150: tag check to 158, only C busy: issue 158, fill 168.            E uses [158, 168)
  CHECK(l2.read(4 * 64, 150) == 168);
  // F at 240: tag check to 248, A and B busy (C released at 240, D issues at 258). At 258 B's
  // release and D's issue keep two busy (A, D); D's release at 268 leaves one: issue 268, fill
  // 288.
  CHECK(l2.read(5 * 64, 240) == 288);
  CHECK(issues == std::vector<uint64_t>{208, 228, 108, 258, 158, 268});
  const L2Stats stats = l2.stats();
  CHECK(stats.cache.misses == 6);
  CHECK(stats.portQueueCycles == 0);
  CHECK(stats.mshrQueueCycles == (258 - 230) + (268 - 248));
}

TEST_CASE("L2 out of order: 4096 misses behind full MSHRs take them in arrival order", "[cache]") {
  // 8 MSHRs (the default); the DRAM answers a read kLatency cycles after its issue.
  constexpr uint64_t kLatency = 1000000, kMshrs = 8, kCount = 4096;
  L2CacheTiming l2(CacheConfig::l2(), DramConfig{}, RequestOrder::Any,
                   [](uint32_t, uint64_t issue) { return issue + kLatency; });
  // 8 misses at cycle 1000: accepted at 1000..1007, issued at 1008..1015, so all 8 MSHRs are
  // busy from 1015 until they are released at X .. X + 7, X = 1008 + kLatency.
  const uint64_t x = 1008 + kLatency;
  for (uint64_t i = 0; i < kMshrs; ++i) REQUIRE(l2.read(i * 64, 1000) == x + i);
  // Then 4096 misses at cycles 1100 + 4095 down to 1100, the latest first, each accepted at
  // once. Every tag check ends in 1108..5203, while those 8 hold all the MSHRs and the misses
  // that came before it are not issued yet (they are from X on). So the misses queue in the
  // order they come: the k-th takes the MSHR released at X + k for k < 8, and the one the
  // (k - 8)-th releases kLatency after its issue for the others, which all happen later still:
  // issue X + k % 8 + (k / 8) * kLatency. Each of these waits counts the MSHRs at many cycles
  // (X, X + 1, ...), ever more of them: the case a claim scanning the uses at each release made
  // cubic.
  uint64_t mshrQueue = 0;
  for (uint64_t k = 0; k < kCount; ++k) {
    const uint64_t request = 1100 + (kCount - 1 - k);
    const uint64_t issue = x + k % kMshrs + (k / kMshrs) * kLatency;
    mshrQueue += issue - (request + 8);
    INFO("miss " << k << " requested at " << request);
    REQUIRE(l2.read((kMshrs + k) * 64, request) == issue + kLatency);
  }
  const L2Stats stats = l2.stats();
  CHECK(stats.cache.misses == kMshrs + kCount);
  CHECK(stats.portQueueCycles == 0 + 1 + 2 + 3 + 4 + 5 + 6 + 7);
  CHECK(stats.mshrQueueCycles == mshrQueue);
}

TEST_CASE("L2 out of order: forgetting the cycles no request comes for changes no answer",
          "[cache]") {
  CacheConfig config = CacheConfig::l2();
  config.sizeBytes = 4096;
  config.maxOutstandingMisses = 2;
  L2CacheTiming forgetting(config, DramConfig{}, RequestOrder::Any),
      keeping(config, DramConfig{}, RequestOrder::Any);
  std::mt19937_64 random(11);
  uint64_t floor = 0;  // no request comes for a cycle before it
  for (int i = 0; i < 3000; ++i) {
    floor += random() % 3;
    forgetting.forgetBefore(floor);
    const uint64_t cycle = floor + random() % 200;  // out of cycle order
    const uint64_t address = (random() % 256) * 64;
    REQUIRE(forgetting.read(address, cycle) == keeping.read(address, cycle));
  }
  CHECK(forgetting.stats().cache.misses == keeping.stats().cache.misses);
  CHECK(forgetting.stats().mshrQueueCycles == keeping.stats().mshrQueueCycles);
  CHECK(forgetting.stats().mshrQueueCycles > 0);  // the MSHRs were a limit
  CHECK(forgetting.stats().portQueueCycles == keeping.stats().portQueueCycles);
}

// ---------------------------------------------------------------------------------------------
// L1 timing. Defaults: 32-byte lines (8 words), hit latency 1.

TEST_CASE("L1 timing: hits, and misses through the next level", "[cache]") {
  std::vector<std::pair<uint64_t, uint64_t>> requests;  // (byte address, cycle)
  L1CacheTiming l1(CacheConfig::l1(), [&](uint64_t address, uint64_t cycle) {
    requests.emplace_back(address, cycle);
    return cycle + 20;
  });
  // Word 3 = byte 12, line 0: tag check until 1, next level 1 + 20.
  CHECK(l1.read(3, 0) == 21);
  // Word 7 is in the same line: 30 + 1.
  CHECK(l1.read(7, 30) == 31);
  // Word 8 = byte 32 starts the next line: requested at 41, there at 61.
  CHECK(l1.read(8, 40) == 61);
  CHECK(requests == std::vector<std::pair<uint64_t, uint64_t>>{{0, 1}, {32, 41}});
  CHECK(l1.stats().hits == 1);
  CHECK(l1.stats().misses == 2);
}

TEST_CASE("L1 timing: the miss split in lookup and fill", "[cache]") {
  L1CacheTiming l1(CacheConfig::l1());
  // Word 10 = byte 40, in the line at 32.
  const L1Lookup miss = l1.lookup(10, 5);
  CHECK_FALSE(miss.hit);
  CHECK(miss.cycle == 6);
  CHECK(miss.lineAddress == 32);
  CHECK(l1.fill(10, 100) == 100);
  // While the line is in flight a lookup waits for it; afterwards it is a plain hit.
  const L1Lookup inFlight = l1.lookup(11, 50);
  CHECK(inFlight.hit);
  CHECK(inFlight.cycle == 100);
  const L1Lookup hit = l1.lookup(15, 100);
  CHECK(hit.hit);
  CHECK(hit.cycle == 101);
  CHECK(hit.lineAddress == 32);
  CHECK(l1.stats().merged == 1);
  CHECK(l1.stats().hits == 1);
}

TEST_CASE("L1 timing: word addresses span more than 32 bits of bytes", "[cache]") {
  L1CacheTiming l1(CacheConfig::l1());
  const L1Lookup miss = l1.lookup(0xFFFFFFFFu, 0);  // byte 0x3'FFFF'FFFC
  CHECK(miss.lineAddress == 0x3FFFFFFE0u);
  l1.fill(0xFFFFFFFFu, 10);
  CHECK(l1.array().contains(0x3FFFFFFFCu));
  CHECK_FALSE(l1.array().contains(0xFFFFFFFCu));  // not aliased onto the 32-bit byte address
}

TEST_CASE("L1 timing: two cores' L1s in front of the shared L2", "[cache]") {
  L2CacheTiming l2(CacheConfig::l2(), DramConfig{});
  L1CacheTiming core0(CacheConfig::l1());
  L1CacheTiming core1(CacheConfig::l1());
  // Core 0 misses word 0 at 0: L2 request at 1, L2 tag check until 9, DRAM 49..57.
  const L1Lookup miss0 = core0.lookup(0, 0);
  CHECK(core0.fill(0, l2.read(miss0.lineAddress, miss0.cycle)) == 57);
  // Core 1 misses word 8 (byte 32, another L1 line, the same L2 line) at 2: L2 request at 3
  // merges with the miss in flight; tag check until 11, data at the fill, 57.
  const L1Lookup miss1 = core1.lookup(8, 2);
  CHECK(miss1.lineAddress == 32);
  CHECK(core1.fill(8, l2.read(miss1.lineAddress, miss1.cycle)) == 57);
  // Core 0 then reads word 8: its own L1 misses (line 32), the L2 hits: 60 + 1, + 8.
  const L1Lookup miss2 = core0.lookup(8, 60);
  CHECK(core0.fill(8, l2.read(miss2.lineAddress, miss2.cycle)) == 69);
  CHECK(l2.stats().cache.misses == 1);
  CHECK(l2.stats().cache.merged == 1);
  CHECK(l2.stats().cache.hits == 1);
}
