#pragma once
// The result manager (thesis 6.2.4, appendix C.5): one result buffer per core, drained to the host
// by a select counter that advances every cycle from reset. A core may hand over a result when its
// buffer is empty (core_ready = ~result_valid); the host sees the selected buffer
// (out_valid = result_valid[select]), so an untaken result is withdrawn when the select moves on,
// exactly as in the RTL. The module runs only in cycles where a buffer fills or empties or the
// select reaches a full buffer.

#include <cstdint>
#include <vector>

#include <systemc>

#include "core_set.h"
#include "cycle_clock.h"
#include "module_process.h"
#include "ready_valid.h"
#include "rtu_payloads.h"

namespace rtu {

struct ResultManagerStatistics {
  uint64_t maxBuffered = 0;  // most buffers full at once
};

class ResultManager : public sc_core::sc_module {
 public:
  sc_core::sc_port<ReadyValidIn<CoreResult>, 0> cores;
  sc_core::sc_port<ReadyValidOut<CoreResult>> out;

  ResultManager(sc_core::sc_module_name name, const CycleClock& clock);

  const ResultManagerStatistics& statistics() const { return statistics_; }

 private:
  static constexpr int kNone = -1;

  void end_of_elaboration() override;
  void evaluate();
  void takeTransfers(uint64_t now);
  void select(uint64_t now);
  // The first cycle after `now` whose select finds a full buffer, or 0 when all are empty.
  uint64_t nextFullSelect(uint64_t now) const;

  const CycleClock& clock_;
  int coreCount_ = 0;
  // The cores' channels, taken from the port once: indexing an sc_port checks bounds every time.
  std::vector<ReadyValidIn<CoreResult>*> core_;
  std::vector<const sc_core::sc_event*> handoverEdges_;
  struct Handover {
    int core;
    uint64_t cycle;  // whose levels made the transfer
  };
  std::vector<Handover> handingOver_;  // since the last look
  std::vector<CoreResult> buffer_;
  CoreSet full_;
  uint64_t buffered_ = 0;
  int offered_ = kNone;
  uint64_t handledCycle_ = ~0ull;
  CycleWake wake_;
  ResultManagerStatistics statistics_;
};

}  // namespace rtu
