#pragma once
// Timing of the shared L2 cache and the DRAM behind it. The cores run ahead of global time, so
// the model answers "a read of this line requested at cycle R: at which cycle is its data at the
// L2's output?". Requests must come in non-decreasing R (the caller orders the cores' requests
// by cycle); an earlier one throws std::logic_error.
//
// The model, with h = hitLatency:
//   Port     one request accepted per cycle: accept = max(R, portFree); portFree = accept + 1.
//   Hit      line filled by `accept`:                    ready = accept + h.
//   Merged   line in flight (its fill at F > accept):    ready = max(accept + h, F).
//   Miss     the tag check ends at T = accept + h; the miss then needs one of
//            maxOutstandingMisses MSHRs, each busy from its miss's issue to its line's fill:
//              issue = T, or the earliest MSHR release if all are busy at T;
//            DRAM (see dram_channel.h) transfers the line:
//              start = max(issue + dram.latency, dramBusFree);
//              F = start + ceil(lineBytes / bytesPerCycle); dramBusFree = F;
//            the MSHR is released at F (free for a miss issuing at F), the line is allocated
//            at once with fill cycle F, ready = F.
// A line being allocated at the miss means later requests for it merge instead of missing again.

#include <cstdint>
#include <functional>
#include <queue>
#include <vector>

#include "cache_array.h"
#include "dram_channel.h"
#include "memory_config.h"

namespace rtu {

struct L2Stats {
  CacheStats cache;  // requests = cache.accesses; hits, merged, misses, evictions
  DramStats dram;    // bytes read, bus busy cycles
  uint64_t portQueueCycles = 0;  // sum of accept - R
  uint64_t mshrQueueCycles = 0;  // sum of issue - T over misses
};

class L2CacheTiming {
 public:
  // Validates both configurations (std::invalid_argument).
  L2CacheTiming(const CacheConfig& cache, const DramConfig& dram);

  // The cycle the data of the line holding `byteAddress` is at the L2's output.
  uint64_t read(uint64_t byteAddress, uint64_t requestCycle);

  L2Stats stats() const;
  const CacheArray& array() const { return array_; }
  // Starts from these lines (functional warming); `lines` has this cache's configuration.
  void startFrom(const CacheArray& lines) { array_ = lines; }

 private:
  uint64_t acceptRequest(uint64_t requestCycle);
  uint64_t fetchLine(uint64_t tagCheckDone);
  uint64_t claimMshr(uint64_t cycle);

  CacheArray array_;
  DramChannel dram_;
  uint64_t lastRequestCycle_ = 0;
  uint64_t portFree_ = 0;
  // Release cycles of the busy MSHRs, earliest on top.
  std::priority_queue<uint64_t, std::vector<uint64_t>, std::greater<uint64_t>> mshrReleases_;
  uint64_t portQueueCycles_ = 0;
  uint64_t mshrQueueCycles_ = 0;
};

}  // namespace rtu
