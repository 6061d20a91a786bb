#pragma once
// The host's output stream: takes results whenever the link allows (every cycle unless paced or
// randomly throttled) and keeps them with their arrival cycles. Without pacing it is ready in
// every cycle, so results may be delivered to it in any order of cycles (result_manager.h); it
// sorts them by arrival at the end, in place. A sink given a taker hands each result to it as it
// arrives and keeps none: then only the counts and the first and last arrival remain.

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "rtu/host_link.h"
#include "sim/ca/rtu_payloads.h"
#include "sim/kernel/decision_pump.h"
#include "sim/kernel/transfer_channel.h"

namespace rtu {

class HostSink final : public Agent {
 public:
  static constexpr int kInPort = 0;  // its port on the transfer channel

  // The results received, a column per field, so a run takes them over without a copy.
  struct Arrivals {
    std::vector<uint64_t> cycles;
    std::vector<CoreKindResult> results;
    std::vector<uint64_t> rays;  // each result's ids.ray
    std::vector<uint64_t> jobs;  // and ids.job
    std::vector<uint32_t> blockedCycles;
    std::vector<int> instances;
    size_t size() const { return cycles.size(); }
  };

  // Takes each result with its arrival cycle as it arrives (in the order of receipt, which is
  // not quite the order of cycles).
  using Take = std::function<void(uint64_t cycle, const CoreResult& result)>;

  HostSink(DecisionPump& pump, uint64_t expected, HostLinkConfig link, Take take = {});

  void bind(TransferChannel<CoreResult>& in);
  void decide() override;

  // In arrival order once the run is complete (arrange()).
  const Arrivals& arrivals() const { return arrivals_; }
  // Moves them out (the sink is then empty).
  Arrivals takeArrivals() { return std::move(arrivals_); }
  bool complete() const { return received_ == expected_; }
  uint64_t received() const { return received_; }
  // The first arrival's cycle (0 before any).
  uint64_t firstArrival() const { return firstArrival_; }
  uint64_t expected() const { return expected_; }
  uint64_t lastArrival() const { return lastArrival_; }
  // How many results arrived before `cycle` (asked in increasing cycles).
  uint64_t arrivedBefore(uint64_t cycle);
  void arrange();

 private:
  void receive(uint64_t cycle, const CoreResult& result);
  // Whether the arrival received a-th goes before the one received b-th.
  bool before(size_t a, size_t b) const;
  void sortAll();
  TransferChannel<CoreResult>::Ready readyIn(uint64_t cycle);
  uint64_t firstReadyFrom(uint64_t cycle);

  TransferChannel<CoreResult>* in_ = nullptr;
  uint64_t expected_;
  HostLinkConfig link_;
  HostLinkPacer pacer_;
  uint64_t allowedFrom_ = 0;
  uint64_t drawnUntil_ = 0;       // a random link: cycles drawn so far ...
  std::vector<bool> activeFrom_;  // ... and their outcomes from allowedFrom_
  Take take_;
  Arrivals arrivals_;  // empty with a taker
  uint64_t received_ = 0;
  uint64_t firstArrival_ = 0;
  uint64_t lastArrival_ = 0;
  std::vector<uint64_t> notYetArrived_;  // cycles of results not yet counted by arrivedBefore
  uint64_t arrived_ = 0;
};

}  // namespace rtu
