#pragma once
// The ready-valid channel every RTU module talks through (thesis chapter 6). The producer drives
// valid and the payload, the consumer drives ready; a transfer happens in each cycle whose final
// levels have both high, as on the clock edge that ends that cycle in the RTL.
//
// Levels behave like sc_signal: a write becomes visible in the next delta cycle, so a module can
// compute a combinational level (the RTL's `assign`) in a later delta of the same cycle. A level
// holds until it is written again, so nobody has to run in cycles where nothing changes. When the
// last delta of cycle t ends with both levels high, both sides are woken at the start of cycle
// t + 1 by `edge()` and see `transferredIn(t)` and the `transferred()` payload.
//
// A producer that sees a transfer must write again (offer the next payload or withdraw) in the
// next cycle. A stable channel also checks the AXI-stream rule: once offered, a payload stays
// until it is taken. The RTL's result manager withdraws untaken results when its select moves
// on, so its output is declared `MayWithdraw`.

#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include <systemc>

#include "cycle_clock.h"
#include "cycle_trace.h"

namespace rtu {

enum class OfferRule { Stable, MayWithdraw };

// What the producer's port sees.
template <class Payload>
class ReadyValidOut : public virtual sc_core::sc_interface {
 public:
  virtual void offer(const Payload& payload) = 0;
  virtual void withdraw() = 0;
  virtual bool ready() const = 0;
  virtual bool transferredIn(uint64_t cycle) const = 0;
  virtual const sc_core::sc_event& edge() const = 0;
  virtual const sc_core::sc_event& readyChanged() const = 0;
  // Calls `watcher` with the new level whenever ready changes, in the update phase: a module
  // with many channels keeps their levels in its own index instead of querying each.
  virtual void watchReady(std::function<void(bool)> watcher) = 0;
};

// What the consumer's port sees.
template <class Payload>
class ReadyValidIn : public virtual sc_core::sc_interface {
 public:
  virtual void setReady(bool ready) = 0;
  virtual bool valid() const = 0;
  virtual const Payload& payload() const = 0;
  virtual bool transferredIn(uint64_t cycle) const = 0;
  virtual const Payload& transferred() const = 0;
  virtual const sc_core::sc_event& edge() const = 0;
  virtual const sc_core::sc_event& offerChanged() const = 0;
  // Calls `watcher` in the update phase of a cycle whose levels make a transfer (the levels may
  // still change later in that cycle: confirm with transferredIn), so a module with many
  // channels visits only those with a transfer.
  virtual void watchTransfer(std::function<void()> watcher) = 0;
};

template <class Payload>
class ReadyValid final : public sc_core::sc_prim_channel,
                   public ReadyValidOut<Payload>,
                   public ReadyValidIn<Payload> {
 public:
  ReadyValid(const char* name, const CycleClock& clock, OfferRule rule = OfferRule::Stable)
      : sc_core::sc_prim_channel(name), clock_(clock), rule_(rule) {}

  // Producer side.
  void offer(const Payload& payload) override {
    nextPayload_ = payload;
    nextValid_ = true;
    producerWrote_ = true;
    request_update();
  }
  void withdraw() override {
    if (!nextValid_) return;
    nextValid_ = false;
    producerWrote_ = true;
    request_update();
  }
  // Consumer side.
  void setReady(bool ready) override {
    if (nextReady_ == ready) return;
    nextReady_ = ready;
    request_update();
  }

  bool valid() const override { return valid_; }
  bool ready() const override { return ready_; }
  const Payload& payload() const override { return payload_; }

  bool transferredIn(uint64_t cycle) const override {
    return (pending_ == cycle && clock_.now() > cycle) || last_ == cycle;
  }
  // The payload of the most recent completed transfer.
  // Until the producer writes again (in the cycle after the transfer) the payload it offered is
  // still the current one.
  const Payload& transferred() const override {
    return pending_ != kNever && pending_ < clock_.now() ? payload_ : lastPayload_;
  }

  const sc_core::sc_event& edge() const override { return edge_; }
  // Notified after every producer write: valid rose or fell, or a new payload is offered.
  // Only events someone asked for are notified: most channels have no listener for one of them.
  const sc_core::sc_event& offerChanged() const override {
    offerListened_ = true;
    return offerChanged_;
  }
  const sc_core::sc_event& readyChanged() const override {
    readyListened_ = true;
    return readyChanged_;
  }

  void watchReady(std::function<void(bool)> watcher) override { readyWatcher_ = std::move(watcher); }
  void watchTransfer(std::function<void()> watcher) override {
    transferWatcher_ = std::move(watcher);
  }

  void trace(CycleTrace& trace, const std::string& scope) {
    trace_ = &trace;
    validSignal_ = trace.declare(scope, "valid", 1);
    readySignal_ = trace.declare(scope, "ready", 1);
    trace.record(validSignal_, 0, 0);
    trace.record(readySignal_, 0, 0);
  }

 private:
  static constexpr uint64_t kNever = std::numeric_limits<uint64_t>::max();

  void update() override {
    const uint64_t now = clock_.now();
    commitEarlierTransfer(now);
    checkOfferRule(now);
    if (producerWrote_ && offerListened_) offerChanged_.notify(sc_core::SC_ZERO_TIME);
    if (nextValid_ != valid_) {
      valid_ = nextValid_;
      if (valid_) validSince_ = now;
      if (trace_) trace_->record(validSignal_, now, valid_);
    }
    if (nextReady_ != ready_) {
      ready_ = nextReady_;
      if (readyListened_) readyChanged_.notify(sc_core::SC_ZERO_TIME);
      if (readyWatcher_) readyWatcher_(ready_);
      if (trace_) trace_->record(readySignal_, now, ready_);
    }
    if (producerWrote_) payload_ = nextPayload_;
    producerWrote_ = false;
    if (valid_ && ready_) {
      pending_ = now;
      edge_.notify(clock_.period());
      if (transferWatcher_) transferWatcher_();
    } else if (pending_ == now) {
      pending_ = kNever;
      edge_.cancel();
    }
  }

  void commitEarlierTransfer(uint64_t now) {
    if (pending_ == kNever || pending_ >= now) return;
    last_ = pending_;
    lastPayload_ = payload_;  // not yet replaced: commits run before a write is applied
    pending_ = kNever;
  }

  // Valid was high in an earlier cycle and nothing took the payload: a stable producer must not
  // touch it. (Writes in the cycle after a transfer are the next offer.)
  void checkOfferRule(uint64_t now) const {
    if (rule_ != OfferRule::Stable || !producerWrote_ || !valid_ || validSince_ >= now) return;
    if (last_ == now - 1) return;
    throw std::logic_error(std::string(name()) + ": payload changed or withdrawn in cycle " +
                           std::to_string(now) + " while offered and not taken");
  }

  const CycleClock& clock_;
  OfferRule rule_;
  bool valid_ = false, ready_ = false, nextValid_ = false, nextReady_ = false;
  bool producerWrote_ = false;
  Payload payload_{}, nextPayload_{}, lastPayload_{};
  uint64_t validSince_ = 0;
  uint64_t pending_ = kNever;  // cycle whose levels currently make a transfer
  uint64_t last_ = kNever;     // last completed transfer
  sc_core::sc_event edge_, offerChanged_, readyChanged_;
  mutable bool offerListened_ = false, readyListened_ = false;
  std::function<void(bool)> readyWatcher_;
  std::function<void()> transferWatcher_;
  CycleTrace* trace_ = nullptr;
  int validSignal_ = CycleTrace::kNoSignal, readySignal_ = CycleTrace::kNoSignal;
};

}  // namespace rtu
