#pragma once
// A reorder buffer between the result manager and the host (thesis future work): results leave in
// the order the host submitted the jobs. It holds at most `capacity` results and accepts only
// results within `capacity` of the next one due, so the one due always fits and the buffer cannot
// deadlock; others wait in their result manager buffers (and their cores in OUT). Its ready is
// combinational on the offered result, so the result manager asks it cycle by cycle.

#include <cstdint>
#include <deque>
#include <map>
#include <utility>

#include "base/occupancy_peak.h"
#include "sim/ca/rtu_payloads.h"
#include "sim/kernel/cycle_clock.h"
#include "sim/kernel/decision_pump.h"
#include "sim/kernel/transfer_channel.h"

namespace rtu {

struct ReorderBufferStatistics {
  uint64_t maxOccupancy = 0;
};

class ReorderBuffer : public Agent {
 public:
  static constexpr int kInPort = 0, kOutPort = 1;  // its ports on the transfer channels

  ReorderBuffer(DecisionPump& pump, const CycleClock& clock, int capacity);

  void bind(TransferChannel<CoreResult>& in, TransferChannel<CoreResult>& out);
  void decide() override;

  ReorderBufferStatistics statistics() const { return {occupancy_.peak()}; }

 private:
  using Ready = TransferChannel<CoreResult>::Ready;
  struct Held {
    CoreResult result;
    uint64_t from;  // the cycle after it arrived
  };

  Ready accepts(uint64_t cycle, const CoreResult& result);
  uint64_t dueIn(uint64_t cycle);

  const CycleClock& clock_;
  uint64_t capacity_;
  TransferChannel<CoreResult>* in_ = nullptr;
  TransferChannel<CoreResult>* out_ = nullptr;
  std::map<uint64_t, Held> held_;  // by job id
  uint64_t nextDue_ = 0;
  uint64_t lastSent_ = kNeverCycle;
  std::deque<std::pair<uint64_t, uint64_t>> dueChanges_;  // (from cycle, next due)
  OccupancyPeak occupancy_;
};

}  // namespace rtu
