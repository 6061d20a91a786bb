#pragma once
// The host's output stream: takes results whenever the link allows (every cycle unless paced or
// randomly throttled) and keeps them with their arrival cycles. Without pacing it is ready in
// every cycle, so results may be delivered to it in any order of cycles (result_manager.h); it
// sorts them by arrival at the end, in place.

#include <cstdint>
#include <vector>

#include "decision_pump.h"
#include "host_link.h"
#include "rtu_payloads.h"
#include "transfer_channel.h"

namespace rtu {

class HostSink : public Agent {
 public:
  struct Arrival {
    uint64_t cycle;
    CoreResult result;
  };

  HostSink(DecisionPump& pump, uint64_t expected, HostLinkConfig link);

  void bind(TransferChannel<CoreResult>& in);
  void decide() override;

  // In arrival order once the run is complete (arrange()).
  const std::vector<Arrival>& arrivals() const { return arrivals_; }
  bool complete() const { return arrivals_.size() == expected_; }
  uint64_t expected() const { return expected_; }
  uint64_t lastArrival() const { return lastArrival_; }
  // How many results arrived before `cycle` (asked in increasing cycles).
  uint64_t arrivedBefore(uint64_t cycle);
  void arrange();

 private:
  void receive(uint64_t cycle, const CoreResult& result);
  TransferChannel<CoreResult>::Ready readyIn(uint64_t cycle);
  uint64_t firstReadyFrom(uint64_t cycle);

  TransferChannel<CoreResult>* in_ = nullptr;
  uint64_t expected_;
  HostLinkConfig link_;
  HostLinkPacer pacer_;
  uint64_t allowedFrom_ = 0;
  uint64_t drawnUntil_ = 0;           // a random link: cycles drawn so far ...
  std::vector<bool> activeFrom_;      // ... and their outcomes from allowedFrom_
  std::vector<Arrival> arrivals_;
  uint64_t lastArrival_ = 0;
  std::vector<uint64_t> notYetArrived_;  // cycles of results not yet counted by arrivedBefore
  uint64_t arrived_ = 0;
};

}  // namespace rtu
