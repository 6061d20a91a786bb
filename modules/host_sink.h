#pragma once
// The host's output stream: takes results whenever the link allows (every cycle unless paced or
// randomly throttled) and keeps them in arrival order with their cycles.

#include <cstdint>
#include <vector>

#include <systemc>

#include "cycle_clock.h"
#include "host_link.h"
#include "module_process.h"
#include "ready_valid.h"
#include "rtu_payloads.h"

namespace rtu {

class HostSink : public sc_core::sc_module {
 public:
  sc_core::sc_port<ReadyValidIn<CoreResult>> in;

  HostSink(sc_core::sc_module_name name, const CycleClock& clock, uint64_t expected,
           HostLinkConfig link);

  const std::vector<CoreResult>& results() const { return results_; }
  const std::vector<uint64_t>& arrivalCycles() const { return arrivalCycles_; }
  bool complete() const { return results_.size() == expected_; }
  uint64_t expected() const { return expected_; }

 private:
  void end_of_elaboration() override;
  void evaluate();

  const CycleClock& clock_;
  uint64_t expected_;
  HostLinkPacer pacer_;
  uint64_t allowedFrom_ = 0;
  uint64_t handledCycle_ = ~0ull;
  CycleWake wake_;
  std::vector<CoreResult> results_;
  std::vector<uint64_t> arrivalCycles_;
};

}  // namespace rtu
