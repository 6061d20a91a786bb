#include "result_manager.h"

#include <algorithm>

namespace rtu {

ResultManager::ResultManager(sc_core::sc_module_name name, const CycleClock& clock)
    : sc_core::sc_module(name), clock_(clock), wake_(clock) {}

void ResultManager::end_of_elaboration() {
  coreCount_ = cores.size();
  buffer_.resize(static_cast<size_t>(coreCount_));
  full_ = CoreSet(coreCount_);
  for (int i = 0; i < coreCount_; ++i) {
    core_.push_back(cores[i]);
    handoverEdges_.push_back(&core_.back()->edge());
    core_.back()->watchTransfer([this, i] { handingOver_.push_back({i, clock_.now()}); });
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
  // A handover in the previous cycle; one whose levels formed in this cycle waits for the next.
  size_t kept = 0;
  for (const Handover& handover : handingOver_) {
    const int i = handover.core;
    ReadyValidIn<CoreResult>& core = *core_[static_cast<size_t>(i)];
    if (handover.cycle == now) {
      handingOver_[kept++] = handover;
    } else if (core.transferredIn(edge) && !full_.contains(i)) {
      buffer_[static_cast<size_t>(i)] = core.transferred();
      full_.assign(i, true);
      core.setReady(false);
      ++buffered_;
    }
  }
  handingOver_.resize(kept);
  statistics_.maxBuffered = std::max(statistics_.maxBuffered, buffered_);
  if (offered_ != kNone && out->transferredIn(edge)) {
    full_.assign(offered_, false);
    core_[static_cast<size_t>(offered_)]->setReady(true);
    --buffered_;
    out->withdraw();
    offered_ = kNone;
  }
}

void ResultManager::select(uint64_t now) {
  const int selected = static_cast<int>(now % static_cast<uint64_t>(coreCount_));
  if (full_.contains(selected)) {
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
  const int next = full_.firstFrom((selected + 1) % coreCount_);
  if (next == CoreSet::kNone) return 0;
  return now + static_cast<uint64_t>((next - selected + coreCount_ - 1) % coreCount_ + 1);
}

}  // namespace rtu
