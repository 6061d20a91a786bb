#include "reorder_buffer.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rtu {

ReorderBuffer::ReorderBuffer(sc_core::sc_module_name name, const CycleClock& clock, int capacity)
    : sc_core::sc_module(name), clock_(clock), capacity_(static_cast<uint64_t>(capacity)) {
  if (capacity < 1)
    throw std::invalid_argument("reorder buffer capacity must be at least 1, got " +
                                std::to_string(capacity));
}

void ReorderBuffer::end_of_elaboration() {
  spawnMethod("evaluate", [this] { evaluate(); },
              {&in->edge(), &in->offerChanged(), &out->edge()});
}

void ReorderBuffer::evaluate() {
  const uint64_t now = clock_.now();
  takeTransfers(now);
  const auto due = held_.find(nextDue_);
  if (!offering_ && due != held_.end()) {
    out->offer(due->second);
    offering_ = true;
  }
  // Combinational on the offered result, as its window check is.
  in->setReady(in->valid() && in->payload().sequence < nextDue_ + capacity_);
}

void ReorderBuffer::takeTransfers(uint64_t now) {
  if (handledCycle_ == now || now == 0) return;
  handledCycle_ = now;
  if (in->transferredIn(now - 1)) {
    const CoreResult& result = in->transferred();
    held_[result.sequence] = result;
    statistics_.maxOccupancy = std::max<uint64_t>(statistics_.maxOccupancy, held_.size());
  }
  if (offering_ && out->transferredIn(now - 1)) {
    held_.erase(nextDue_++);
    out->withdraw();
    offering_ = false;
  }
}

}  // namespace rtu
