#include "sim/ca/result_manager.h"

#include <algorithm>
#include <iterator>

namespace rtu {

ResultManager::ResultManager(sc_core::sc_module_name name, const CycleClock& clock,
                             DecisionPump& pump)
    : sc_core::sc_module(name), Agent(pump), clock_(clock), wake_(clock) {}

void ResultManager::end_of_elaboration() {
  spawnReaction("drain", [this] { pump().runWith(*this); }, {&wake_.event()});
  // The cores' offer bounds matter to drains in cycle order alone (a host that is not always
  // ready).
  if (out_->alwaysReady())
    for (TransferChannel<CoreResult>* core : cores_) core->offerBoundsUnheard();
}

void ResultManager::bind(std::vector<TransferChannel<CoreResult>*> cores,
                         TransferChannel<CoreResult>& out) {
  cores_ = std::move(cores);
  out_ = &out;
  select_ = Modulo(cores_.size());
  buffers_.resize(cores_.size());
  for (TransferChannel<CoreResult>* core : cores_) core->traceReady(0, true);
}

void ResultManager::heard(int port) {
  heard_.push_back(port);
  Agent::heard(port);
}

void ResultManager::decide() {
  deciding_.swap(heard_);  // both keep their capacity: no allocation per decision
  for (int core : deciding_)
    if (core >= 0) handOver(core);
  deciding_.clear();
  if (out_->alwaysReady()) return;
  drainInCycleOrder();
  publishDrainBounds();
}

// A core whose result waits for its full buffer learns the earliest cycle of that buffer's drain
// still possible (its next select from the first undecided cycle), so the scheduler need not
// wait for the drain itself to know the core stays busy until then.
void ResultManager::publishDrainBounds() {
  for (size_t core = 0; core < buffers_.size(); ++core) {
    TransferChannel<CoreResult>& channel = *cores_[core];
    if (!buffers_[core].full || !channel.offering()) continue;
    const uint64_t from = std::max(scan_, buffers_[core].fullFrom);
    const uint64_t select = nextSelect(core, from);
    if (channel.readyBound() < select + 1) channel.notReadyBefore(select + 1);
  }
}

// A core offers a result and its buffer is empty: the handover is decided.
void ResultManager::handOver(int core) {
  TransferChannel<CoreResult>& channel = *cores_[static_cast<size_t>(core)];
  Buffer& buffer = buffers_[static_cast<size_t>(core)];
  if (buffer.full || !channel.offering()) return;
  const uint64_t cycle = std::max(channel.offerCycle(), buffer.freeFrom);
  buffer.result = channel.payload();
  channel.take(cycle);
  buffer.full = true;
  buffer.fullFrom = cycle + 1;
  occupancy_.enter(cycle + 1);
  ++fullBuffers_;
  if (out_->alwaysReady()) drainAtSelect(core);
}

// The host takes every cycle: the first select from the buffer's first full cycle.
void ResultManager::drainAtSelect(int core) {
  const uint64_t from = buffers_[static_cast<size_t>(core)].fullFrom;
  drain(core, nextSelect(static_cast<size_t>(core), from));
}

// From the first undecided cycle on: the cycles whose select shows a full buffer, until one of
// them lies where an empty buffer could still fill.
void ResultManager::drainInCycleOrder() {
  while (fullBuffers_ > 0) {
    int core = -1;
    const uint64_t cycle = nextFullSelect(core);
    const uint64_t horizon = fillHorizon();
    if (cycle >= horizon) {
      // An idle core may still get a job whose result drains earlier; decisions never fall
      // behind simulated time, so by simulated time cycle - 2 it could no longer.
      wake_.at(std::max(clock_.now() + 1, cycle - 2));
      return;
    }
    Buffer& buffer = buffers_[static_cast<size_t>(core)];
    switch (out_->readyIn(cycle, buffer.result)) {
      case TransferChannel<CoreResult>::Ready::Unknown: return;
      case TransferChannel<CoreResult>::Ready::No:
        out_->traceValid(cycle, true);
        out_->traceValid(cycle + 1, false);
        scan_ = cycle + 1;
        break;
      case TransferChannel<CoreResult>::Ready::Yes:
        drain(core, cycle);
        scan_ = cycle + 1;
        pump().schedule(*this);  // after the host has seen it: its readiness may change
        return;
    }
  }
}

// The first cycle from scan_ whose select shows a buffer full by then, and that buffer.
uint64_t ResultManager::nextFullSelect(int& core) const {
  uint64_t best = kNeverCycle;
  for (size_t i = 0; i < buffers_.size(); ++i) {
    if (!buffers_[i].full) continue;
    const uint64_t from = std::max(scan_, buffers_[i].fullFrom);
    const uint64_t select = nextSelect(i, from);
    if (select < best) {
      best = select;
      core = static_cast<int>(i);
    }
  }
  return best;
}

// The first cycle from `from` in which the select counter (cycle mod N) shows `core`.
uint64_t ResultManager::nextSelect(size_t core, uint64_t from) const {
  const uint64_t shown = select_.of(from);
  return from + (core >= shown ? core - shown : core + cores_.size() - shown);
}

// The first cycle an empty buffer could be full: after a handover, which follows an offer.
uint64_t ResultManager::fillHorizon() const {
  const uint64_t idleOffer =
      clock_.now() + 2;  // a job dispatched from now on offers then at the earliest
  uint64_t horizon = kNeverCycle;
  for (size_t core = 0; core < buffers_.size(); ++core) {
    if (buffers_[core].full) continue;
    const TransferChannel<CoreResult>& channel = *cores_[core];
    const uint64_t offer = channel.offering() ? channel.offerCycle()
                                              : std::max(channel.offerBound(), idleOffer);
    horizon = std::min(horizon, std::max(offer, buffers_[core].freeFrom) + 1);
  }
  return horizon;
}

void ResultManager::drain(int core, uint64_t cycle) {
  Buffer& buffer = buffers_[static_cast<size_t>(core)];
  TransferChannel<CoreResult>& channel = *cores_[static_cast<size_t>(core)];
  const bool traced = channel.traced();
  if (traced && drainCycles_.count(cycle + 1)) {
    // The next cycle drains another buffer, decided before this one: its valid level stands.
    out_->deliver(buffer.result, cycle);
    out_->traceValid(cycle + 1, true);
  } else {
    out_->deliver(buffer.result, cycle);
  }
  if (traced) rememberDrain(cycle);
  occupancy_.leave(cycle + 2);  // the RTL's count sees the buffer until the cycle after
  buffer.full = false;
  buffer.freeFrom = cycle + 1;
  --fullBuffers_;
  channel.traceReady(cycle + 1, true);
  handOver(core);
  occupancy_.settle(clock_.now());
}

void ResultManager::rememberDrain(uint64_t cycle) {
  drainCycles_.insert(cycle);
  if (drainCycles_.size() < 4096) return;
  const uint64_t now = clock_.now();
  for (auto it = drainCycles_.begin(); it != drainCycles_.end();)
    it = *it + 1 < now ? drainCycles_.erase(it) : std::next(it);
}

}  // namespace rtu
