#pragma once
// The channel every RTU module talks through (thesis chapter 6's ready-valid handshakes), as
// transfers that carry their cycle (issue 9). A transfer in cycle t is what the RTL's clock edge
// at the end of cycle t does when valid and ready are both high. Exactly one side decides its
// cycle:
//   - the consumer, for a payload the producer `offer`s from a cycle on (valid stays high until
//     the transfer, the AXI-stream rule): it calls `take(t)`;
//   - the producer, for a consumer that declared when it can take (`readyFrom`, or a pattern for
//     consumers whose ready is not one interval): it calls `deliver(payload, t)`.
// Each call puts the other side on the decision pump (decision_pump.h). The channel checks the
// protocol: at most one payload in flight, a transfer not before the offer nor before the
// consumer is ready, transfers in increasing cycles, and none behind simulated time.
//
// With a trace, the channel records the levels its transfers imply: valid from the offer to the
// transfer, ready from the declaration to the transfer (one cycle for a consumer that decides),
// and the id of the payload's ray (rayId) from its offer (or delivery) until the next payload's.
// A module whose levels do more than that (the job manager's combinational in_ready, the result
// manager's select) records the rest.

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sim/kernel/cycle_clock.h"
#include "sim/kernel/decision_pump.h"
#include "trace/cycle_trace.h"

namespace rtu {

constexpr uint64_t kNeverCycle = std::numeric_limits<uint64_t>::max();

template <class Payload>
class TransferChannel {
 public:
  // Whether the consumer takes `payload` in `cycle` (asked in increasing cycles), for consumers
  // whose ready is not one interval; Unknown until the consumer knows more, and then it tells
  // the producer (readinessChanged).
  enum class Ready { Yes, No, Unknown };
  using ReadyPattern = std::function<Ready(uint64_t cycle, const Payload& payload)>;

  TransferChannel(std::string name, const CycleClock& clock)
      : name_(std::move(name)), clock_(clock) {}

  // `producerPort` and `consumerPort` tell each side which of its channels this is.
  void connect(Agent& producer, int producerPort, Agent& consumer, int consumerPort) {
    producer_ = &producer;
    consumer_ = &consumer;
    producerPort_ = producerPort;
    consumerPort_ = consumerPort;
  }

  // ---- producer side
  // `payload` is valid from `cycle` until the consumer takes it.
  void offer(const Payload& payload, uint64_t cycle) {
    if (offering_) fail("offered while a payload waits", cycle);
    notBehind(cycle);
    payload_ = payload;
    offerCycle_ = cycle;
    offering_ = true;
    record(validSignal_, cycle, 1);
    record(raySignal_, cycle, rayId(payload));
    consumer_->heard(consumerPort_);
  }
  bool offering() const { return offering_; }
  // True once per transfer of an offer: the producer has seen it.
  bool collectTaken() {
    const bool news = takenUnseen_;
    takenUnseen_ = false;
    return news;
  }
  bool takenUnseen() const { return takenUnseen_; }
  uint64_t lastTransfer() const { return lastTransfer_; }

  // Whether the consumer takes `payload` in `cycle`.
  Ready readyIn(uint64_t cycle, const Payload& payload) const {
    if (always_) return Ready::Yes;
    if (pattern_) return pattern_(cycle, payload);
    if (readyCycle_ <= cycle) return Ready::Yes;
    return readyBound() > cycle ? Ready::No : Ready::Unknown;
  }
  // A consumer ready in every cycle: the producer may deliver in any order of cycles.
  bool alwaysReady() const { return always_; }
  // The cycle from which a consumer without a pattern is ready (kNeverCycle: not declared), and
  // the earliest it can be when it is not declared.
  uint64_t readyCycle() const { return readyCycle_; }
  uint64_t readyBound() const { return readyCycle_ != kNeverCycle ? readyCycle_ : readyBound_; }
  // The earliest cycle the producer can offer from, while it offers nothing.
  uint64_t offerBound() const { return offering_ ? offerCycle_ : offerBound_; }
  // Transfers `payload` in `cycle`, where the consumer is ready.
  void deliver(const Payload& payload, uint64_t cycle) {
    if (offering_) fail("delivered while an offer waits", cycle);
    if (readyIn(cycle, payload) != Ready::Yes)
      fail("delivered where the consumer is not ready", cycle);
    record(validSignal_, cycle, 1);
    record(raySignal_, cycle, rayId(payload));
    complete(cycle);
    if (!always_) record(readySignal_, cycle + 1, 0);
    delivered_.push_back({cycle, payload});
    consumer_->heard(consumerPort_);
  }
  // The producer's valid in a cycle without a transfer (a result manager whose select shows a
  // full buffer the host does not take).
  void traceValid(uint64_t cycle, bool level) { record(validSignal_, cycle, level); }
  // No offer before `cycle` (a core still traversing): lets the consumer decide earlier cycles.
  void noOfferBefore(uint64_t cycle) {
    offerBound_ = cycle;
    if (offerBoundsHeard_) consumer_->heard(consumerPort_);
  }

  // ---- consumer side
  const Payload& payload() const { return payload_; }
  uint64_t offerCycle() const { return offerCycle_; }
  void take(uint64_t cycle) {
    if (!offering_) fail("took with nothing offered", cycle);
    if (cycle < offerCycle_) fail("took before the offer", cycle);
    record(readySignal_, cycle, 1);
    record(readySignal_, cycle + 1, 0);
    offering_ = false;
    complete(cycle);
    takenUnseen_ = true;
    producer_->heard(producerPort_);
  }
  // Ready in every cycle from `cycle` until the next transfer.
  void readyFrom(uint64_t cycle) {
    notBehind(cycle);
    readyCycle_ = cycle;
    record(readySignal_, cycle, 1);
    producer_->heard(producerPort_);
  }
  // The consumer decides nothing from the producer's offer bounds: noOfferBefore() records them
  // without waking it (a cached run's cores bound their next offer at every miss).
  void offerBoundsUnheard() { offerBoundsHeard_ = false; }
  // Ready when `pattern` says (replaces readyFrom).
  void readyWhen(ReadyPattern pattern) { pattern_ = std::move(pattern); }
  // Ready in every cycle of the run (the host without pacing).
  void readyAlways() { always_ = true; }
  // The consumer's readiness changed in a way only its pattern knows.
  void readinessChanged() { producer_->heard(producerPort_); }
  // Not ready before `cycle` (a busy core): lets the producer decide earlier cycles.
  void notReadyBefore(uint64_t cycle) {
    readyBound_ = cycle;
    producer_->heard(producerPort_);
  }
  // Calls `take(cycle, payload)` for each payload delivered since the last call.
  template <class Take>
  void collectDelivered(Take&& take) {
    for (const auto& [cycle, payload] : delivered_) take(cycle, payload);
    delivered_.clear();
  }
  void traceReady(uint64_t cycle, bool level) { record(readySignal_, cycle, level); }
  bool traced() const { return trace_ != nullptr; }

  void trace(CycleTrace& trace, const std::string& scope) {
    trace_ = &trace;
    validSignal_ = trace.declare(scope, "valid", 1);
    readySignal_ = trace.declare(scope, "ready", 1);
    raySignal_ = trace.declare(scope, "ray", 32);  // unknown until the first payload
    trace.record(validSignal_, 0, 0);
    trace.record(readySignal_, 0, 0);
  }

 private:
  void complete(uint64_t cycle) {
    notBehind(cycle);
    if (!always_ && lastTransfer_ != kNeverCycle && cycle <= lastTransfer_)
      fail("transfer not after the previous one in cycle " + std::to_string(lastTransfer_), cycle);
    lastTransfer_ = cycle;
    readyCycle_ = kNeverCycle;
    readyBound_ = cycle + 1;
    record(validSignal_, cycle + 1, 0);
  }
  void notBehind(uint64_t cycle) const {
    if (cycle < clock_.now()) fail("decided behind simulated time", cycle);
  }
  void record(int signal, uint64_t cycle, uint64_t value) {
    if (trace_) trace_->record(signal, cycle, value);
  }
  [[noreturn]] void fail(const std::string& what, uint64_t cycle) const {
    throw std::logic_error(name_ + ": " + what + " (cycle " + std::to_string(cycle) + ")");
  }

  std::string name_;
  const CycleClock& clock_;
  Agent* producer_ = nullptr;
  Agent* consumer_ = nullptr;
  int producerPort_ = 0, consumerPort_ = 0;
  uint64_t offerBound_ = 0, readyBound_ = 0;
  Payload payload_{};
  bool offering_ = false;
  uint64_t offerCycle_ = 0;
  uint64_t readyCycle_ = kNeverCycle;
  ReadyPattern pattern_;
  bool always_ = false;
  bool offerBoundsHeard_ = true;
  uint64_t lastTransfer_ = kNeverCycle;
  bool takenUnseen_ = false;
  std::vector<std::pair<uint64_t, Payload>> delivered_;  // not yet collected by the consumer
  CycleTrace* trace_ = nullptr;
  int validSignal_ = CycleTrace::kNoSignal, readySignal_ = CycleTrace::kNoSignal;
  int raySignal_ = CycleTrace::kNoSignal;
};

}  // namespace rtu
