#pragma once
// The tag store of a set-associative cache. It holds tags only: the SVO image is read-only, so
// the data always equals the backing store's and a timing model needs to know only which lines
// are resident and from which cycle their data is there.
//
// Addresses are byte addresses. A line is allocated as soon as its miss is known, with the cycle
// its fill completes; an access to it before then finds it "in flight" (a merged miss, counted
// apart from the hits) and waits for that cycle. Allocation fills an empty way first, else evicts
// by policy:
//   LRU     the way accessed (or allocated) longest ago,
//   FIFO    the way allocated longest ago,
//   random  a uniformly chosen way, from std::mt19937_64 seeded with the configuration's seed.
// Lines in flight are not protected from eviction; an evicted line's fill still takes place, for
// nothing.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "base/statistics.h"
#include "sim/memory/memory_config.h"

namespace rtu {

struct CacheStats {
  uint64_t accesses = 0;  // hits + merged + misses
  uint64_t hits = 0;      // line resident and filled
  uint64_t merged = 0;    // line resident but still in flight
  uint64_t misses = 0;
  uint64_t evictions = 0;  // allocations that replaced a valid line

  static const StatisticGroup<CacheStats>& declaration();
};

// Share of a cache's reads answered by a resident line (hits and merged); 0 without reads.
double hitRate(const CacheStats& stats);

struct CacheLookup {
  bool present = false;    // resident, filled or in flight
  uint64_t fillCycle = 0;  // when present: the cycle the line's data is (or was) there
};

class CacheArray {
 public:
  // `config` must have passed validate().
  explicit CacheArray(const CacheConfig& config);

  // Looks the line of `byteAddress` up at `cycle` and, if present, makes it most recently used.
  // Inline: every L1 lookup of a cached run comes here.
  CacheLookup access(uint64_t byteAddress, uint64_t cycle) {
    ++stats_.accesses;
    const uint64_t line = lineOf(byteAddress);
    const size_t set = line & setMask_;
    const size_t first = set * waysPerSet_;
    size_t i = first + mostRecent_[set];
    // The set's most recently used way holds its newest stamp; found there, the line keeps that
    // rank without a new stamp (stamps are compared within a set only).
    if (lines_[i] != line) {
      i = find(line, first);
      if (i == kAbsent) {
        ++stats_.misses;
        missedLine_ = line;
        return {};
      }
      if (config_.replacement == Replacement::Lru) ways_[i].stamp = newStamp(i - first);
      mostRecent_[set] = static_cast<uint32_t>(i - first);
    }
    const uint64_t fillCycle = ways_[i].fillCycle;
    if (fillCycle > cycle) ++stats_.merged;  // hits are what is left: stats() counts them
    return {true, fillCycle};
  }
  // Installs the line of `byteAddress` after access() missed it; its data arrives at fillCycle.
  // Inline, as access(): each L1 miss comes here.
  void allocate(uint64_t byteAddress, uint64_t fillCycle) {
    const uint64_t line = lineOf(byteAddress);
    const size_t set = line & setMask_;
    const size_t first = set * waysPerSet_;
    // Right after access() missed it (nothing allocated since) the line is known to be absent.
    if (line != missedLine_ && find(line, first) != kAbsent) failResident(line);
    missedLine_ = kEmpty;
    const size_t i = victimFor(first);
    if (lines_[i] != kEmpty) ++stats_.evictions;
    lines_[i] = line;
    ways_[i] = {fillCycle, newStamp(i - first)};
    mostRecent_[set] = static_cast<uint32_t>(i - first);
  }
  // Functional warming (no timing, nothing counted): makes the line of `byteAddress` resident
  // and most recently used, its data there from cycle 0; returns whether it already was.
  bool touch(uint64_t byteAddress);
  // Whether the line is resident, without counting or touching the replacement state.
  bool contains(uint64_t byteAddress) const;

  const CacheConfig& config() const { return config_; }
  // Memory the tag store of `config` takes; it is allocated whole when the cache is made.
  static uint64_t tagBytes(const CacheConfig& config) {
    return uint64_t{config.sizeBytes / config.lineBytes} * (sizeof(uint64_t) + sizeof(Way)) +
           uint64_t{config.sets()} * sizeof(uint32_t);
  }
  CacheStats stats() const {
    CacheStats stats = stats_;
    stats.hits = stats.accesses - stats.misses - stats.merged;
    return stats;
  }

 private:
  // What a resident line's way holds beside its line number.
  struct Way {
    uint64_t fillCycle = 0;
    // Order of the last use (LRU) or of the allocation (FIFO) above the way's number in its set
    // (newStamp); the smallest is the victim.
    uint64_t stamp = 0;
  };

  static constexpr size_t kAbsent = SIZE_MAX;
  // The line number of an empty way: no byte address has it (lines are 4 bytes or more).
  static constexpr uint64_t kEmpty = UINT64_MAX;

  uint64_t lineOf(uint64_t byteAddress) const { return byteAddress >> lineShift_; }
  size_t firstWayOf(uint64_t line) const { return (line & setMask_) * waysPerSet_; }
  // Index of the way holding `line`, or kAbsent. The line numbers are an array of their own, so
  // a set's search is one comparison a way within one or two host cache lines.
  size_t find(uint64_t line) const { return find(line, firstWayOf(line)); }
  size_t find(uint64_t line, size_t first) const {
    for (size_t i = first; i < first + waysPerSet_; ++i)
      if (lines_[i] == line) return i;
    return kAbsent;
  }

  // A stamp for way `wayInSet`: the next order above the way's number, so that stamps are unique
  // and the smallest names its way.
  uint64_t newStamp(size_t wayInSet) { return ++clock_ << wayBits_ | wayInSet; }

  // The way a missing line goes to in the set from way `first` on: an empty one first, else by
  // policy. Empty ways keep their order 0 (lines are never invalidated) and every allocation
  // takes a new stamp, so the smallest stamp is the first empty way's if there is one and else
  // the LRU or FIFO victim's: one pass for the minimum, without a branch to mispredict, and its
  // low bits name the way.
  size_t victimFor(size_t first) {
    uint64_t oldestStamp = UINT64_MAX;
    for (size_t i = first; i < first + waysPerSet_; ++i)
      oldestStamp = std::min(oldestStamp, ways_[i].stamp);
    const size_t oldest = first + (oldestStamp & wayMask_);
    if (config_.replacement == Replacement::Random && lines_[oldest] != kEmpty)
      return randomWay(first);
    return oldest;
  }
  size_t randomWay(size_t first);
  // Out of line, so that allocate() needs no stack frame for the message.
  [[noreturn, gnu::noinline, gnu::cold]] void failResident(uint64_t line) const;

  CacheConfig config_;
  int lineShift_;
  uint64_t setMask_;
  size_t waysPerSet_;
  int wayBits_;                       // bits of the largest way number in a set
  uint64_t wayMask_;                  // those bits of a stamp
  std::vector<uint64_t> lines_;       // per way, sets x ways, set-major: its line number or kEmpty
  std::vector<Way> ways_;             // per way, as lines_
  std::vector<uint32_t> mostRecent_;  // per set, its most recently used way
  uint64_t clock_ = 0;                // source of stamps
  uint64_t missedLine_ = kEmpty;      // the line access() missed last, until an allocation
  CacheStats stats_;                  // all but the hits, which stats() derives
  std::mt19937_64 random_;  // 2.5 KB, last: the fields every access reads share host cache lines
};

}  // namespace rtu
