#pragma once
// The timed model of seed 001's ray pipe: one cache (R1 RAYTRACER/caches/cache.sv with
// miss_handler.sv), lazy in time; with raypipe.cache = block_ram only its block-RAM read (the pipe
// and the FIFO of MemoryRead). The tag store is raypipe/raypipe_cache.h's. Timing rules
// (docs/raypipe.md, "The set-associative caches"):
//   an item entering the pipe in t (from upstream, or a reissue, which goes first and stalls
//   upstream) looks its line up in the tags as they stand at t; it leaves at t + latency: a hit
//   into the 3-entry hit FIFO, a miss into the reissue FIFO (register, 8 entries; a new item
//   stalls while it holds 5 or more at the cycle's start), and its line into the miss request FIFO
//   unless it is there already (at the cycle's start): that item then waits for the line's data.
//   The miss handler takes the request FIFO's head from the cycle it is shown when idle (a) and
//   asks the arbiter from a + 1 (dram_arbiter.h). The reissue FIFO's head goes into the pipe when
//   the pipe does not stall and, if it waits for its line, from the line's doneRead d on: the
//   line is written into the way raypipeWayChoice names then and the item hits; the handler is
//   idle again from the cycle after.
#include <cstdint>
#include <deque>
#include <string>
#include <utility>

#include "raypipe/raypipe_cache.h"
#include "sim/raypipe/dram_arbiter.h"
#include "sim/raypipe/memory_read.h"
#include "sim/raypipe/ray_token.h"

namespace rtu {
namespace raypipe_timed {

struct Reissue {
  RayToken token;
  bool wait = false;  // it asked for its line (cache.sv's RIF flag)
};
inline uint64_t traceHead(const Reissue& r, bool pixels) { return traceHead(r.token, pixels); }

class TimedCache {
 public:
  TimedCache(const std::string& name, RaypipeCacheId id, const RaypipeConfig& c, DramArbiter& dram);
  void bookOn(WakeCalendar& calendar, uint32_t groups);
  // An item leaving the pipe in `now` that hit, for takeHit to give its data to the hit FIFO; a
  // miss leaving goes to the reissue FIFO instead (false). Before cycle().
  bool hitExiting(int64_t now) {
    if (!read.pipe.exiting(now)) return false;
    return !setAssociative_ || read.pipe.front().cacheHit || missed(now);
  }
  RayToken takeHit(int64_t now) {
    counts_.hits += setAssociative_ ? 1 : 0;
    return read.pipe.take(now);
  }
  // The cycle's reissue (before any upstream item) and the upstream stall, the downstream's given.
  bool cycle(int64_t now, bool dsStall, int64_t cyclesFromReset) {
    const bool pipeStall = read.usStall(now, dsStall);
    return setAssociative_ ? reissue(now, pipeStall, cyclesFromReset) : pipeStall;
  }
  void accept(int64_t now, const RayToken& t);
  void refused() { ++counts_.stalls; }
  const RaypipeCacheCounts& counts() const { return counts_; }

  MemoryRead read;

 private:
  uint64_t lineOf(const RayToken& t) const;
  bool missed(int64_t now);  // false: the exiting miss went to the reissue FIFO
  bool reissue(int64_t now, bool pipeStall, int64_t cyclesFromReset);
  bool requested(uint64_t line, int64_t now) const;
  void ask(int64_t from, int64_t now);
  void deliver(int64_t now);
  RaypipeCacheId id_;
  bool setAssociative_;
  RaypipeCacheGeometry geometry_;
  TwoWayTags tags_;
  DramArbiter& dram_;
  TimedQueue<Reissue> reissue_;
  std::deque<std::pair<uint64_t, int64_t>> requests_;  // the MRF: line, cycle written
  bool asking_ = false;                                // for the MRF's head
  int64_t handlerIdleFrom_ = 0;
  RaypipeCacheCounts counts_;
};

}  // namespace raypipe_timed
}  // namespace rtu
