#pragma once
// The host's input stream: offers the job records in order, record 0 from cycle 0 and each next
// one as soon as the link allows after the job manager took the previous, and holds it until
// taken. It is also what keeps the run near simulated time: it offers a record only once
// simulated time is within `lookAhead` cycles of the offer (decision_pump.h), so the modules
// after it never decide more than about that far ahead.

#include <cstdint>
#include <vector>

#include <systemc>

#include "kinds/host_stream.h"
#include "rtu/host_link.h"
#include "sim/ca/rtu_payloads.h"
#include "sim/kernel/cycle_clock.h"
#include "sim/kernel/decision_pump.h"
#include "sim/kernel/module_process.h"
#include "sim/kernel/transfer_channel.h"

namespace rtu {

class HostSource final : public sc_core::sc_module, public Agent {
 public:
  static constexpr int kOutPort = 0;  // its port on the transfer channel

  HostSource(sc_core::sc_module_name name, const CycleClock& clock, DecisionPump& pump,
             RecordSource records, HostLinkConfig link, uint64_t lookAhead);

  void bind(TransferChannel<HostPayload>& out);
  void decide() override;

 private:
  void end_of_elaboration() override;
  uint64_t offerCycle();

  const CycleClock& clock_;
  TransferChannel<HostPayload>* out_ = nullptr;
  const RecordSource records_;  // a vector's outlives the run
  HostLinkPacer pacer_;
  uint64_t lookAhead_;
  uint64_t next_ = 0;                  // index of the record offered or to be offered
  uint64_t allowedFrom_ = 0;           // the link's next slot
  uint64_t drawnOffer_ = kNeverCycle;  // a random link's offer cycle, once drawn
  CycleWake wake_;
};

}  // namespace rtu
