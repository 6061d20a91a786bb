#pragma once
// The timed model of seed 001's ray pipe: R1's memory request arbiter
// (SDRAM/memory_request_arbiter.sv) in front of rtusim's DRAM channel (sim/memory/dram_channel.h),
// lazy in time. Timing rules (docs/raypipe.md, "The set-associative caches"):
//   Idle from cycle F with its pointer at port c, the arbiter looks at port (c + t - F) mod 4 in
//   cycle t (at cycle 0: cyclesSinceReset mod 4, startAfter). Port p asking from cycle b (its miss
//   handler in B) is granted in the first cycle g >= max(b, F) whose port is p, unless another
//   asking port's such cycle comes first. Granted in g, its line's doneRead rises in
//   d = DramChannel::read(bytes, g) = g + latency + ceil(bytes / bytesPerCycle) (the arbiter
//   serialises the reads, so the bus is always free); the arbiter is idle again from F = d + 1
//   with its pointer at p + 1.
// Every request with b <= t is known before cycle t (a miss handler asks two cycles after the
// miss is seen at the latest), so advance(t) decides every grant up to t; the arbiter books each
// asking port's group for the cycle of its next possible grant and, once granted, for d.

#include <array>
#include <cstdint>

#include "raypipe/raypipe_cache.h"
#include "sim/memory/dram_channel.h"
#include "sim/raypipe/wake_calendar.h"

namespace rtu {
namespace raypipe_timed {

class DramArbiter {
 public:
  explicit DramArbiter(const RaypipeCacheSettings& s)
      : channel_(DramConfig{static_cast<uint32_t>(s.dramLatency), s.dramBytesPerCycle}) {}
  // Cycle 0 is `cyclesFromReset` after reset: the pointer has turned every cycle since.
  void startAfter(int64_t cyclesFromReset) {
    pointer_ = static_cast<int>(cyclesFromReset % kRaypipeDramPorts);
  }
  void bookOn(WakeCalendar& calendar, int port, uint32_t groups) {
    calendar_ = &calendar;
    ports_[static_cast<size_t>(port)].groups = groups;
  }
  // Port `port` asks from cycle `from` (made in an earlier cycle, `now`) for `bytes`.
  void request(int port, int64_t from, uint32_t bytes, int64_t now);
  // Decides every grant in a cycle up to `now`.
  void advance(int64_t now);
  // doneRead has risen for the port's request by `now`.
  bool done(int port, int64_t now) const {
    const Port& p = ports_[static_cast<size_t>(port)];
    return p.done >= 0 && now >= p.done;
  }
  // The port's line was taken: it asks no more.
  void finished(int port) {
    Port& p = ports_[static_cast<size_t>(port)];
    p.asking = false;
    p.done = -1;
  }
  RaypipeDramCounts counts() const;

 private:
  struct Port {
    uint32_t groups = 0;
    bool asking = false;
    int64_t from = 0, done = -1;
    uint32_t bytes = 0;
  };
  int64_t grantCycle(int port) const;
  void bookNextGrants(int64_t now);
  DramChannel channel_;
  std::array<Port, kRaypipeDramPorts> ports_{};
  int64_t idleFrom_ = 0;
  int pointer_ = 0;  // the port looked at in idleFrom_
  WakeCalendar* calendar_ = nullptr;
};

}  // namespace raypipe_timed
}  // namespace rtu
