#pragma once
// The per-cycle reference of seed 001's ray pipe: its caches (R1 RAYTRACER/caches/cache.sv,
// miss_handler.sv) and the memory request arbiter in front of the DRAM
// (SDRAM/memory_request_arbiter.sv), stepped once a cycle; docs/raypipe.md, "The set-associative
// caches", gives the rules. With raypipe.cache = block_ram a CacheRead is the block-RAM read
// (MemoryRead) and nothing else. The tag store is raypipe/raypipe_cache.h's.

#include <array>
#include <cstdint>
#include <string>

#include "raypipe/raypipe_cache.h"
#include "raypipe/raypipe_config.h"
#include "reference/raypipe_fifo.h"
#include "reference/raypipe_flit.h"
#include "reference/raypipe_pipe.h"

namespace rtu {
namespace raypipe_ref {

// The memory request arbiter over the DRAM. Idle, it looks at one port a cycle (currC, turned
// every cycle it does not grant); a port asking in that cycle (its miss handler in B or C) is
// granted: the DRAM's words arrive from `latency` cycles on, `bytesPerCycle` a cycle, and doneRead
// is raised in the cycle after the last (g + latency + ceil(bytes / bytesPerCycle)), when currC
// turns and the arbiter is idle again from the next cycle.
class DramArbiter {
 public:
  explicit DramArbiter(const RaypipeCacheSettings& s) : settings_(s) {}
  // Cycle 0 is `cyclesFromReset` after reset: the pointer has turned every cycle since.
  void startAfter(int64_t cyclesFromReset) {
    current_ = static_cast<int>(cyclesFromReset % kRaypipeDramPorts);
  }
  bool doneRead(int port, int64_t now) const { return busy_ && port_ == port && done_ == now; }
  // The cycle's end; asking[p]: port p's readReq at the cycle's start, of bytes[p] bytes.
  void tick(int64_t now, const std::array<bool, kRaypipeDramPorts>& asking,
            const std::array<uint32_t, kRaypipeDramPorts>& bytes);
  const RaypipeDramCounts& counts() const { return counts_; }

 private:
  RaypipeCacheSettings settings_;
  bool busy_ = false;
  int current_ = 0, port_ = 0;
  int64_t done_ = 0;
  RaypipeDramCounts counts_;
};

// A missed item waiting to go through the cache again; `wait`: it asked for its line (the RIF's
// flag) and goes only with the line's data.
struct Reissue {
  Flit flit;
  bool wait = false;
};

// One cache: a pipe of the read latency whose exit looks the item's line up (as the tag store
// stood when the item entered), the 3-entry hit FIFO behind it (HDF); a miss goes to the reissue
// FIFO and, when its line is not asked for yet, its line to the miss request FIFO (MRF); the miss
// handler reads the MRF's head from DRAM, one line at a time.
class CacheRead {
 public:
  CacheRead(const std::string& name, RaypipeCacheId id, const RaypipeConfig& c);
  // The cycle's reissue (before any upstream item) and the upstream stall, the downstream's given.
  bool cycle(int64_t now, bool dsStall, const DramArbiter& dram, int64_t cyclesFromReset);
  // The item leaving the pipe in `now` that hit, for its data to be read into the hit FIFO; a miss
  // goes to the reissue FIFO instead (false).
  bool exitHit(int64_t now, Flit& out);
  void accept(const Flit& f);
  void refused() { ++counts_.stalls; }
  bool asking() const { return state_ == Mh::Request || state_ == Mh::Wait; }
  uint32_t lineBytes() const { return geometry_.lineBytes; }
  int port() const { return static_cast<int>(id_); }
  // The cycle's end: the miss handler (with the arbiter's doneRead of the cycle), then the FIFOs.
  void tick(int64_t now, const DramArbiter& dram);
  const RaypipeCacheCounts& counts() const { return counts_; }

  PipeValidStall<Flit> pipe;
  RegFifo<Flit> fifo;  // the hit FIFO

 private:
  enum class Mh { Idle, Request, Wait, Hold };  // miss_handler.sv's A, B, C, D
  uint64_t lineOf(const Flit& f) const;
  bool fromMhValid(int64_t now, const DramArbiter& dram) const {
    return (state_ == Mh::Wait && dram.doneRead(port(), now)) || state_ == Mh::Hold;
  }
  RaypipeCacheId id_;
  bool setAssociative_;
  RaypipeCacheGeometry geometry_;
  TwoWayTags tags_;
  RegFifo<Reissue> reissue_;
  RegFifo<uint64_t> requests_;
  Mh state_ = Mh::Idle;
  bool taken_ = false;  // the line's data went in with its item this cycle
  RaypipeCacheCounts counts_;
};

}  // namespace raypipe_ref
}  // namespace rtu
