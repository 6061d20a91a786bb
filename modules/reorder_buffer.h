#pragma once
// A reorder buffer between the result manager and the host (thesis future work): results leave in
// the order the host submitted the jobs. It holds at most `capacity` results and accepts only
// results within `capacity` of the next one due, so the one due always fits and the buffer cannot
// deadlock; others wait in their result manager buffers (and their cores in OUT).

#include <cstdint>
#include <map>

#include <systemc>

#include "cycle_clock.h"
#include "module_process.h"
#include "ready_valid.h"
#include "rtu_payloads.h"

namespace rtu {

struct ReorderBufferStatistics {
  uint64_t maxOccupancy = 0;
};

class ReorderBuffer : public sc_core::sc_module {
 public:
  sc_core::sc_port<ReadyValidIn<CoreResult>> in;
  sc_core::sc_port<ReadyValidOut<CoreResult>> out;

  ReorderBuffer(sc_core::sc_module_name name, const CycleClock& clock, int capacity);

  const ReorderBufferStatistics& statistics() const { return statistics_; }

 private:
  void end_of_elaboration() override;
  void evaluate();
  void takeTransfers(uint64_t now);

  const CycleClock& clock_;
  uint64_t capacity_;
  std::map<uint64_t, CoreResult> held_;  // by sequence
  uint64_t nextDue_ = 0;
  bool offering_ = false;
  uint64_t handledCycle_ = ~0ull;
  ReorderBufferStatistics statistics_;
};

}  // namespace rtu
