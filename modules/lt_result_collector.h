#pragma once
// The result manager and the output link of the loosely-timed model, at transaction level: a
// core hands its result over (lt_transactions.h) and learns when it is idle again. As in the
// cycle-accurate model (docs/cycle-semantics.md), with one result buffer per core:
//   handover K = max(OUT, the cycle after the core's previous result drained); idle from K + 1;
//   drain    R = the first cycle t >= K + 1 with t mod N = the core (the select counter) and,
//              with a paced output link, in a free slot of it.
// A paced output link is cut into slots of P = ceil(record bytes / bytes per cycle) cycles, one
// record each, taken out of cycle order (slot_calendar.h): an approximation of host_link.h's
// pacing, which spreads fractional rates over records and starts a record P cycles after the
// previous one, not on a grid. Slots keep the link's throughput where free runs booked out of
// order would leave gaps shorter than a record.

#include <cstdint>
#include <vector>

#include "host_link.h"
#include "lt_time.h"
#include "lt_transactions.h"
#include "occupancy_peak.h"
#include "slot_calendar.h"
#include "svo_traversal_core.h"

namespace rtu {

struct LtArrival {
  uint64_t cycle = 0;  // the host's handshake (drain)
  CoreResult result;
};

class LtResultCollector : public sc_core::sc_module, public LtResultSinkIf {
 public:
  // `output` as RtuConfig::outputLink() gives it (records of the format's width).
  LtResultCollector(sc_core::sc_module_name name, int cores, const HostLinkConfig& output,
                    size_t expected, const LtTime& time);

  uint64_t handOver(int core, uint64_t outCycle, const CoreResult& result) override;

  // In the order they came (not cycle order).
  const std::vector<LtArrival>& arrivals() const { return arrivals_; }
  // Per core: jobs, busy (cost), blocked, OUT cycles and overflow counts.
  const std::vector<CoreStatistics>& coreStatistics() const { return cores_; }
  // The most results buffered at once (each from K + 1 to R + 1, as the result manager counts).
  uint64_t maxBuffersFull() const { return buffered_.peak(); }

 private:
  uint64_t drainCycle(int core, uint64_t from);

  LtTime time_;
  uint64_t coreCount_;
  uint64_t linkCycles_;  // cycles a record takes on the output link (0: unlimited)
  SlotCalendar linkSlots_;  // slot k: cycles [k P, (k + 1) P)
  std::vector<uint64_t> lastDrain_;  // per core, kNoDrain before the first
  std::vector<CoreStatistics> cores_;
  std::vector<LtArrival> arrivals_;
  OccupancyPeak buffered_;
};

}  // namespace rtu
