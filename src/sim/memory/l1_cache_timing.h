#pragma once
// Timing of a traversal core's private L1 cache. The core reads 32-bit words by word address
// (byte address = 4 x word address) and blocks until the word is there. With h = hitLatency, a
// read at cycle C:
//   Hit     (line present)  data at max(C + h, the line's fill cycle);
//   Miss    the tag check ends at C + h, where the line is requested from the next level; the
//           data is there when the next level delivers the line, and the line is allocated
//           with that fill cycle.
// maxOutstandingMisses is validated but not modelled: the core blocks on its miss, so it never
// has a second one.
//
// Two ways to use it:
//   read()            one step, with a callback for the next level (tests, untimed drivers);
//   lookup() + fill() the miss split in two, for a caller that must first bring global time to
//                     the request cycle (the shared L2 takes requests in cycle order):
//                       L1Lookup l = l1.lookup(word, now);
//                       if (!l.hit) l1.fill(word, l2.read(l.lineAddress, l.cycle));
//                     fill() returns the cycle the data is there. Each missing lookup() must
//                     be followed by its fill() before the core's next lookup().
// Times are cycles, or any finer unit of which a cycle has `unitsPerCycle` (all times given to one
// cache in the same unit): the loosely-timed L1 counts the picoseconds of its annotated delays,
// so that a hit converts nothing.

#include <algorithm>
#include <cstdint>
#include <functional>

#include "sim/memory/cache_array.h"
#include "sim/memory/memory_config.h"

namespace rtu {

struct L1Lookup {
  bool hit = false;
  // Hit: the cycle the data is there. Miss: the cycle of the next-level request.
  uint64_t cycle = 0;
  // Byte address of the line's first byte: what a miss requests from the next level.
  uint64_t lineAddress = 0;
};

class L1CacheTiming {
 public:
  // Returns the cycle the line holding `byteAddress`, requested at `cycle`, is delivered.
  using NextLevel = std::function<uint64_t(uint64_t byteAddress, uint64_t cycle)>;

  // Validates `config` (std::invalid_argument). `next` is needed by read() only.
  explicit L1CacheTiming(const CacheConfig& config, NextLevel next = nullptr,
                         uint64_t unitsPerCycle = 1);

  // Inline: a cached run's cores call it for nearly every state that reads memory.
  L1Lookup lookup(uint32_t wordAddress, uint64_t cycle) {
    const uint64_t address = byteAddress(wordAddress);
    const uint64_t tagCheckDone = cycle + hitLatency_;
    const uint64_t lineAddress = address & ~uint64_t{array_.config().lineBytes - 1};
    const CacheLookup line = array_.access(address, cycle);
    if (line.present) return {true, std::max(tagCheckDone, line.fillCycle), lineAddress};
    return {false, tagCheckDone, lineAddress};
  }
  // Allocates the missing line of `wordAddress`, its data arriving at readyCycle; returns it.
  // Inline: a cached run's shared requests each end here.
  uint64_t fill(uint32_t wordAddress, uint64_t readyCycle) {
    array_.allocate(byteAddress(wordAddress), readyCycle);
    return readyCycle;
  }
  // The cycle the word read at `cycle` is there.
  uint64_t read(uint32_t wordAddress, uint64_t cycle);

  CacheStats stats() const { return array_.stats(); }
  const CacheArray& array() const { return array_; }
  // Starts from these lines (functional warming); `lines` has this cache's configuration.
  void startFrom(const CacheArray& lines) { array_ = lines; }

  static uint64_t byteAddress(uint32_t wordAddress) { return uint64_t{wordAddress} * 4; }

 private:
  CacheArray array_;
  NextLevel next_;
  uint64_t hitLatency_;  // in the caller's unit
};

}  // namespace rtu
