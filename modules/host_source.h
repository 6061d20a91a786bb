#pragma once
// The host's input stream: offers the job records in order from the first cycle after reset, each
// as soon as the link allows, and holds it until the job manager takes it.

#include <cstdint>
#include <vector>

#include <systemc>

#include "cycle_clock.h"
#include "host_link.h"
#include "module_process.h"
#include "ready_valid.h"
#include "rtu_payloads.h"

namespace rtu {

class HostSource : public sc_core::sc_module {
 public:
  sc_core::sc_port<ReadyValidOut<HostJob>> out;

  HostSource(sc_core::sc_module_name name, const CycleClock& clock,
             std::vector<HostRecord> records, HostLinkConfig link);

 private:
  void end_of_elaboration() override;
  void evaluate();

  const CycleClock& clock_;
  std::vector<HostRecord> records_;
  HostLinkPacer pacer_;
  uint64_t next_ = 0;        // index of the job offered or to be offered
  uint64_t allowedFrom_ = 0;
  bool offering_ = false;
  CycleWake wake_;
};

}  // namespace rtu
