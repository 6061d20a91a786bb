#pragma once
// The designed caches of seed 001's ray pipe (R1 RAYTRACER/caches/cache.sv, raypipe.cache =
// set_associative): their behaviour, untimed, shared by the per-cycle reference and the timed
// model, which each time it by the rules of docs/raypipe.md, "The set-associative caches".
//
// A cache has two ways of `sets` lines (the RTL's NUM_LINES); a line holds `itemsPerLine` of the
// items its unit reads (the RTL's block offset: tcache 8 nodes of 48 bits in 384, lcache 16 list
// entries of 16 bits in 256, icache one 288-bit triangle matrix), `lineBytes` read from DRAM in
// 32-bit words (transSize = LINE_W / 32). An item's line is its address (node id, list index,
// triangle id) divided by itemsPerLine; the set is the line modulo sets, the rest its tag. The
// tag store (TwoWayTags) is empty at the frame's start; a fill writes the way the RTL's way_choice
// flip-flop names in the fill's cycle (it toggles every clock from reset: pseudo-random), whether
// or not the other way is empty, so a fill can evict a line the other way would have kept.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "raypipe/raypipe_config.h"

namespace rtu {

// The memory request arbiter's ports (R1 raypipe_2trav.sv: addr_cache_to_sdram[0..3]).
enum class RaypipeCacheId { Icache = 0, Tcache = 1, Lcache = 2, Tcache1 = 3 };
constexpr int kRaypipeDramPorts = 4;  // R1 COMMON/defines.sv `numcaches`

struct RaypipeCacheGeometry {
  uint32_t itemsPerLine = 1;
  uint32_t lineBytes = 4;
  uint32_t sets = 1;
  uint64_t lineOf(uint32_t address) const { return address / itemsPerLine; }
};

RaypipeCacheGeometry raypipeCacheGeometry(RaypipeCacheId id, const RaypipeCacheSettings& s);

// The way the RTL's way_choice names in `cycle` (cycles from the frame's start; vgaPhase from
// reset to it): 0 on even cycles since reset.
inline int raypipeWayChoice(int64_t cycle, int64_t cyclesFromReset) {
  return static_cast<int>((cycle + cyclesFromReset) & 1);
}

// The tag store: which line each way of each set holds.
class TwoWayTags {
 public:
  explicit TwoWayTags(uint32_t sets) : sets_(sets), ways_(size_t{sets} * 2, kEmpty) {}
  bool holds(uint64_t line) const {
    const size_t first = (line % sets_) * 2;
    return ways_[first] == line || ways_[first + 1] == line;
  }
  // The line's data is written into `way` of its set (evicting what it held).
  void fill(uint64_t line, int way) { ways_[(line % sets_) * 2 + static_cast<size_t>(way)] = line; }

 private:
  static constexpr uint64_t kEmpty = UINT64_MAX;
  uint64_t sets_;
  std::vector<uint64_t> ways_;
};

// What a run counts of one cache (declared in raypipe_statistics.h).
struct RaypipeCacheCounts {
  std::string cache;
  int64_t hits = 0;      // lookups that found their line (a fill's reissued item among them)
  int64_t misses = 0;    // lookups that did not (an item missing twice counts twice)
  int64_t fills = 0;     // lines read from DRAM
  int64_t reissues = 0;  // missed items sent through the cache again
  int64_t stalls = 0;    // cycles an item was offered and the cache refused it
};

struct RaypipeDramCounts {
  int64_t reads = 0, bytes = 0;
  int64_t busyCycles = 0;  // cycles the data bus transferred
};

}  // namespace rtu
