#include "sim/ca/reorder_buffer.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rtu {

ReorderBuffer::ReorderBuffer(DecisionPump& pump, const CycleClock& clock, int capacity)
    : Agent(pump), clock_(clock), capacity_(static_cast<uint64_t>(capacity)) {
  if (capacity < 1)
    throw std::invalid_argument("reorder buffer capacity must be at least 1, got " +
                                std::to_string(capacity));
}

void ReorderBuffer::bind(TransferChannel<CoreResult>& in, TransferChannel<CoreResult>& out) {
  in_ = &in;
  out_ = &out;
  in_->readyWhen(
      [this](uint64_t cycle, const CoreResult& result) { return accepts(cycle, result); });
}

void ReorderBuffer::decide() {
  in_->collectDelivered([this](uint64_t cycle, const CoreResult& result) {
    held_[result.id()] = Held{result, cycle + 1};
    occupancy_.enter(cycle + 1);
  });
  if (out_->collectTaken()) {
    const uint64_t sent = out_->lastTransfer();
    occupancy_.leave(sent + 2);
    held_.erase(nextDue_++);
    lastSent_ = sent;
    dueChanges_.push_back({sent + 1, nextDue_});
    in_->readinessChanged();
  }
  const auto due = held_.find(nextDue_);
  if (!out_->offering() && due != held_.end()) {
    const uint64_t from = lastSent_ == kNeverCycle ? due->second.from
                                                   : std::max(due->second.from, lastSent_ + 1);
    out_->offer(due->second.result, from);
  }
  occupancy_.settle(clock_.now());
}

// in_ready = the offered result lies within the window of the next one due in that cycle.
ReorderBuffer::Ready ReorderBuffer::accepts(uint64_t cycle, const CoreResult& result) {
  // The due result is on its way to the host: the window moves once that is settled.
  if (out_->takenUnseen() || (out_->offering() && cycle > out_->offerCycle()))
    return Ready::Unknown;
  const bool ready = result.id() < dueIn(cycle) + capacity_;
  in_->traceReady(cycle, ready);
  in_->traceReady(cycle + 1, false);
  return ready ? Ready::Yes : Ready::No;
}

// The next one due in `cycle`: the value of the last change by then (asked in increasing cycles).
uint64_t ReorderBuffer::dueIn(uint64_t cycle) {
  while (dueChanges_.size() > 1 && dueChanges_[1].first <= cycle) dueChanges_.pop_front();
  if (dueChanges_.empty()) return nextDue_;
  return dueChanges_.front().first <= cycle ? dueChanges_.front().second
                                            : dueChanges_.front().second - 1;
}

}  // namespace rtu
