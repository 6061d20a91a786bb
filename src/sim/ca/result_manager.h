#pragma once
// The result manager (thesis 6.2.4, appendix C.5): one result buffer per core, drained to the host
// by a select counter that advances every cycle from reset. A core hands over a result when its
// buffer is empty (core_ready = ~result_valid): in K = max(the cycle OUT begins, the cycle after
// the buffer drained), and the buffer is full from K + 1. The host sees the selected buffer
// (out_valid = result_valid[select]): a result drains in the first cycle from K + 1 whose select
// shows its buffer and in which the host takes it; an untaken result is withdrawn when the select
// moves on, exactly as in the RTL.
//
// A host that takes a result in every cycle makes the drains independent of each other (each
// cycle's select shows one buffer), so each is decided at its handover. Otherwise (a paced or
// throttled link, a reorder buffer) the drains are decided in cycle order, each once no core can
// hand over a result that would drain earlier.

#include <cstdint>
#include <unordered_set>
#include <vector>

#include <systemc>

#include "base/modulo.h"
#include "base/occupancy_peak.h"
#include "sim/ca/rtu_payloads.h"
#include "sim/kernel/cycle_clock.h"
#include "sim/kernel/decision_pump.h"
#include "sim/kernel/module_process.h"
#include "sim/kernel/transfer_channel.h"

namespace rtu {

struct ResultManagerStatistics {
  uint64_t maxBuffered = 0;  // most buffers full at once
};

class ResultManager final : public sc_core::sc_module, public Agent {
 public:
  // Its ports: core i's results come in on port i.
  static constexpr int kOutPort = -1;

  ResultManager(sc_core::sc_module_name name, const CycleClock& clock, DecisionPump& pump);

  void bind(std::vector<TransferChannel<CoreResult>*> cores, TransferChannel<CoreResult>& out);
  void decide() override;
  void heard(int port) override;

  ResultManagerStatistics statistics() const { return {occupancy_.peak()}; }

 private:
  struct Buffer {
    bool full = false;
    CoreResult result;
    uint64_t fullFrom = 0;
    uint64_t freeFrom = 0;  // the cycle after its last drain
  };

  void end_of_elaboration() override;
  void handOver(int core);
  void drainAtSelect(int core);
  void drainInCycleOrder();
  void publishDrainBounds();
  uint64_t nextFullSelect(int& core) const;
  uint64_t nextSelect(size_t core, uint64_t from) const;
  // The earliest cycle a buffer now empty can fill.
  uint64_t fillHorizon() const;
  void rememberDrain(uint64_t cycle);
  void drain(int core, uint64_t cycle);

  const CycleClock& clock_;
  CycleWake wake_;
  std::vector<TransferChannel<CoreResult>*> cores_;
  TransferChannel<CoreResult>* out_ = nullptr;
  Modulo select_{1};  // the select counter: cycle mod N, without a division for 2^k cores
  std::vector<Buffer> buffers_;
  std::vector<int> heard_;     // cores whose channel changed since the last decision
  std::vector<int> deciding_;  // those being decided now
  int fullBuffers_ = 0;
  uint64_t scan_ = 0;                         // cycle order: every cycle before it is decided
  std::unordered_set<uint64_t> drainCycles_;  // traced drains, for the valid level
  // The buffers full in a cycle, counted as the RTL's registers see them: a buffer from its
  // handover's next cycle to the cycle after its drain.
  OccupancyPeak occupancy_;
};

}  // namespace rtu
