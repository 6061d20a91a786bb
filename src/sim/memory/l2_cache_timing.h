#pragma once
// Timing of the shared L2 cache and the DRAM behind it. The cores run ahead of global time, so
// the model answers "a read of this line requested at cycle R: at which cycle is its data at the
// L2's output?". With RequestOrder::Cycle (the cycle-accurate model) requests must come in
// non-decreasing R (the caller orders the cores' requests by cycle); an earlier one throws
// std::logic_error. With RequestOrder::Any (the loosely-timed model, whose traversals run one
// after another) they may come in any order, as a documented approximation: the port and the DRAM
// bus give a request the first free gap from its cycle on (resource_booking.h), a miss counts the
// MSHRs busy at T (issued by T, released after it) without checking the later cycles its own use
// covers, a request behind the latest one that finds its line in flight waits no longer than its
// own uncontended miss would (the miss in flight may have been issued after it), and the tag
// store sees the requests
// in the order they come. In cycle order both give the same answers.
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
// The DRAM may instead be another component's (the loosely-timed model's DRAM target): a
// DramRead given to the constructor then transfers the lines.

#include <algorithm>
#include <cstdint>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

#include "sim/memory/cache_array.h"
#include "sim/memory/dram_channel.h"
#include "sim/memory/memory_config.h"
#include "sim/memory/resource_booking.h"

namespace rtu {

struct L2Stats {
  CacheStats cache;              // requests = cache.accesses; hits, merged, misses, evictions
  DramStats dram;                // bytes read, bus busy cycles
  uint64_t portQueueCycles = 0;  // sum of accept - R
  uint64_t mshrQueueCycles = 0;  // sum of issue - T over misses

  // The L2's counts under "l2" and the DRAM's beside them under "dram".
  static const StatisticGroup<L2Stats>& declaration();
};

class L2CacheTiming {
 public:
  // The cycle the last byte of a line read issued at `issueCycle` has arrived.
  using DramRead = std::function<uint64_t(uint32_t bytes, uint64_t issueCycle)>;

  // Validates both configurations (std::invalid_argument). Without `dram`, its own DramChannel.
  L2CacheTiming(const CacheConfig& cache, const DramConfig& dram,
                RequestOrder order = RequestOrder::Cycle, DramRead external = nullptr);

  // The cycle the data of the line holding `byteAddress` is at the L2's output.
  uint64_t read(uint64_t byteAddress, uint64_t requestCycle);

  // RequestOrder::Any: no later request comes for a cycle before `cycle`.
  void forgetBefore(uint64_t cycle);

  L2Stats stats() const;
  const CacheArray& array() const { return array_; }
  // Starts from these lines (functional warming); `lines` has this cache's configuration.
  void startFrom(const CacheArray& lines) { array_ = lines; }

 private:
  // Inline: every request comes here.
  uint64_t acceptRequest(uint64_t requestCycle) {
    if (order_ == RequestOrder::Cycle && requestCycle < lastRequestCycle_)
      failOutOfOrder(requestCycle);
    lastRequestCycle_ = std::max(lastRequestCycle_, requestCycle);
    const uint64_t accept = port_.book(requestCycle, 1);
    portQueueCycles_ += accept - requestCycle;
    return accept;
  }
  // Out of line, so that acceptRequest() needs no stack frame for the message.
  [[noreturn, gnu::noinline, gnu::cold]] void failOutOfOrder(uint64_t requestCycle) const;
  uint64_t mergedFill(uint64_t fillCycle, uint64_t tagCheckDone) const;
  uint64_t fetchLine(uint64_t tagCheckDone);
  uint64_t claimMshr(uint64_t cycle);
  uint64_t claimMshrInOrder(uint64_t cycle);
  uint64_t claimMshrAnyOrder(uint64_t cycle);
  void keepMshrUse(uint64_t issue, uint64_t release);
  void forgetMshrsBefore(uint64_t cycle);

  CacheArray array_;
  DramChannel dram_;
  DramRead externalDram_;
  RequestOrder order_;
  uint64_t lastRequestCycle_ = 0;  // the latest request so far
  ResourceBooking port_;
  uint64_t uncontendedMiss_;  // DRAM latency and one line's transfer
  // RequestOrder::Cycle: release cycles of the busy MSHRs, earliest on top.
  std::priority_queue<uint64_t, std::vector<uint64_t>, std::greater<uint64_t>> mshrReleases_;
  // RequestOrder::Any: how many MSHRs are busy at each cycle. A use [issue, release) adds 1 at
  // its issue and -1 at its release, so the count at T is the sum of the changes at cycles up to
  // T. The cycles with a change are the keys of a treap (a search tree balanced by random
  // priorities), each subtree knowing the sum of its changes and the least sum of a prefix of
  // them: the count at T and the first cycle from T on with fewer than n busy are each one
  // descent, O(log uses).
  class BusyCount {
   public:
    // Adds `uses` (1, or -1 to remove one) busy from `issue` until `release` (issue < release).
    void add(uint64_t issue, uint64_t release, int64_t uses);
    // The first cycle from `cycle` on in which fewer than `limit` (at least 1) are busy.
    uint64_t firstBelow(uint64_t cycle, int64_t limit);
    void clear();

   private:
    using Index = uint32_t;  // into nodes_; 0 is no node
    struct Node {
      uint64_t cycle;
      uint64_t priority;  // a parent's is at least its children's
      int64_t change;     // at this cycle, never 0
      int64_t sum;        // of the subtree's changes
      int64_t minPrefix;  // the least sum of its changes up to one of its cycles, in cycle order
      Index left, right;  // earlier and later cycles
    };
    void change(uint64_t cycle, int64_t by);
    std::pair<Index, Index> split(Index node, uint64_t cycle, bool withCycle);
    Index merge(Index earlier, Index later);
    void update(Index node);
    Index root_ = 0;
    std::vector<Node> nodes_ = std::vector<Node>(1);
    std::vector<Index> unused_;              // nodes_ free for reuse
    uint64_t random_ = 0x9E3779B97F4A7C15u;  // xorshift state of the priorities
  };
  // RequestOrder::Any: the MSHRs' uses, [issue, release), that may still be busy for a request.
  // In real frames at most a few hundred are (a quantum's misses), and a scan of them is the
  // cheapest claim; past that (requests queued far ahead of the forgotten cycles) the uses are
  // also in mshrBusy_ and mshrUses_ is a heap by release (earliest on top) for forgetMshrsBefore,
  // until forgetting leaves few again (kManyMshrUses, kFewMshrUses). Both give the same answers.
  struct MshrUse {
    uint64_t issue, release;
    // The heap's order: the earliest release on top.
    bool operator<(const MshrUse& other) const { return release > other.release; }
  };
  std::vector<MshrUse> mshrUses_;
  bool mshrUsesCounted_ = false;  // in mshrBusy_, and a heap
  BusyCount mshrBusy_;
  uint64_t portQueueCycles_ = 0;
  uint64_t mshrQueueCycles_ = 0;
};

}  // namespace rtu
