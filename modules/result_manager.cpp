#include "result_manager.h"

#include <algorithm>

namespace rtu {

ResultManager::ResultManager(sc_core::sc_module_name name, const CycleClock& clock)
    : sc_core::sc_module(name), clock_(clock), wake_(clock) {}

void ResultManager::end_of_elaboration() {
  coreCount_ = cores.size();
  buffer_.resize(static_cast<size_t>(coreCount_));
  full_.assign(static_cast<size_t>(coreCount_), false);
  for (int i = 0; i < coreCount_; ++i) {
    core_.push_back(cores[i]);
    handoverEdges_.push_back(&core_.back()->edge());
  }
  spawnMethod("evaluate", [this] { evaluate(); }, {&out->edge(), &wake_.event()}, handoverEdges_);
}

void ResultManager::evaluate() {
  const uint64_t now = clock_.now();
  if (now == 0)
    for (int i = 0; i < coreCount_; ++i) core_[static_cast<size_t>(i)]->setReady(true);
  takeTransfers(now);
  select(now);
  const uint64_t wake = offered_ != kNone && coreCount_ > 1 ? now + 1 : nextFullSelect(now);
  if (wake > now) wake_.at(wake);
}

void ResultManager::takeTransfers(uint64_t now) {
  if (handledCycle_ == now || now == 0) return;
  handledCycle_ = now;
  const uint64_t edge = now - 1;
  for (int i = 0; i < coreCount_; ++i) {
    // A handover in the previous cycle triggers the channel's edge now, in this first delta.
    if (!handoverEdges_[static_cast<size_t>(i)]->triggered() || !core_[static_cast<size_t>(i)]->transferredIn(edge))
      continue;
    buffer_[static_cast<size_t>(i)] = core_[static_cast<size_t>(i)]->transferred();
    full_[static_cast<size_t>(i)] = true;
    core_[static_cast<size_t>(i)]->setReady(false);
    ++buffered_;
  }
  statistics_.maxBuffered = std::max(statistics_.maxBuffered, buffered_);
  if (offered_ != kNone && out->transferredIn(edge)) {
    full_[static_cast<size_t>(offered_)] = false;
    core_[static_cast<size_t>(offered_)]->setReady(true);
    --buffered_;
    out->withdraw();
    offered_ = kNone;
  }
}

void ResultManager::select(uint64_t now) {
  const int selected = static_cast<int>(now % static_cast<uint64_t>(coreCount_));
  if (full_[static_cast<size_t>(selected)]) {
    if (offered_ == selected) return;
    out->offer(buffer_[static_cast<size_t>(selected)]);
    offered_ = selected;
  } else if (offered_ != kNone) {
    out->withdraw();
    offered_ = kNone;
  }
}

uint64_t ResultManager::nextFullSelect(uint64_t now) const {
  const int selected = static_cast<int>(now % static_cast<uint64_t>(coreCount_));
  int best = 0;
  for (int i = 0; i < coreCount_; ++i) {
    if (!full_[static_cast<size_t>(i)]) continue;
    const int distance = (i - selected + coreCount_ - 1) % coreCount_ + 1;  // 1 .. n
    if (best == 0 || distance < best) best = distance;
  }
  return best == 0 ? 0 : now + static_cast<uint64_t>(best);
}

}  // namespace rtu
