#include "host_sink.h"

#include <algorithm>

namespace rtu {

HostSink::HostSink(DecisionPump& pump, uint64_t expected, HostLinkConfig link)
    : Agent(pump), expected_(expected), link_(link), pacer_(link) {
  validate(link, "host output");
  arrivals_.reserve(expected);
}

void HostSink::bind(TransferChannel<CoreResult>& in) {
  in_ = &in;
  if (link_.bytesPerCycle == 0.0 && !pacer_.random()) {
    in_->readyAlways();
    in_->traceReady(0, true);
  } else if (pacer_.random()) {
    in_->readyWhen([this](uint64_t cycle, const CoreResult&) { return readyIn(cycle); });
  } else {
    in_->readyFrom(0);
  }
}

void HostSink::decide() {
  in_->collectDelivered([this](uint64_t cycle, const CoreResult& result) { receive(cycle, result); });
  if (in_->offering()) {  // from a reorder buffer
    const uint64_t cycle = firstReadyFrom(in_->offerCycle());
    const CoreResult result = in_->payload();
    in_->take(cycle);
    receive(cycle, result);
  }
}

void HostSink::receive(uint64_t cycle, const CoreResult& result) {
  arrivals_.push_back({cycle, result});
  notYetArrived_.push_back(cycle);
  lastArrival_ = std::max(lastArrival_, cycle);
  if (complete()) {
    in_->traceReady(lastArrival_ + 1, false);
    return;
  }
  if (in_->alwaysReady()) return;
  allowedFrom_ = pacer_.nextAllowed(cycle);
  activeFrom_.clear();
  drawnUntil_ = allowedFrom_;
  if (pacer_.random())
    in_->readinessChanged();
  else
    in_->readyFrom(allowedFrom_);
}

// A randomly throttled link: one draw per cycle from the link's next slot on.
TransferChannel<CoreResult>::Ready HostSink::readyIn(uint64_t cycle) {
  using Ready = TransferChannel<CoreResult>::Ready;
  if (complete() || cycle < allowedFrom_) return Ready::No;
  while (drawnUntil_ <= cycle) {
    const bool active = pacer_.drawActive();
    activeFrom_.push_back(active);
    in_->traceReady(drawnUntil_, active);
    ++drawnUntil_;
  }
  return activeFrom_[cycle - allowedFrom_] ? Ready::Yes : Ready::No;
}

uint64_t HostSink::firstReadyFrom(uint64_t cycle) {
  if (in_->alwaysReady()) return cycle;
  if (!pacer_.random()) return std::max(cycle, allowedFrom_);
  cycle = std::max(cycle, allowedFrom_);
  while (readyIn(cycle) != TransferChannel<CoreResult>::Ready::Yes) ++cycle;
  return cycle;
}

// Results are decided at most a look-ahead beyond simulated time, so few stay uncounted.
uint64_t HostSink::arrivedBefore(uint64_t cycle) {
  const auto later = std::partition(notYetArrived_.begin(), notYetArrived_.end(),
                                    [cycle](uint64_t arrival) { return arrival >= cycle; });
  arrived_ += static_cast<uint64_t>(notYetArrived_.end() - later);
  notYetArrived_.erase(later, notYetArrived_.end());
  return arrived_;
}

// Results are received nearly in cycle order (at 16 cores half a place late on average, at most
// a place per core), so inserting each late one into the sorted part before it moves few, in
// place. Should the order be far off, std::sort finishes once the moves reach a few per result.
void HostSink::arrange() {
  // The job breaks ties, should there be any, so the order never depends on the sort.
  const auto before = [](const Arrival& a, const Arrival& b) {
    return a.cycle != b.cycle ? a.cycle < b.cycle : a.result.ids.job < b.result.ids.job;
  };
  uint64_t movesLeft = 8 * arrivals_.size();
  for (auto late = arrivals_.begin(); late != arrivals_.end(); ++late) {
    if (late == arrivals_.begin() || !before(*late, *(late - 1))) continue;
    const auto place = std::upper_bound(arrivals_.begin(), late, *late, before);
    const auto moves = static_cast<uint64_t>(late - place);
    std::rotate(place, late, late + 1);
    if (moves >= movesLeft) {
      std::sort(arrivals_.begin(), arrivals_.end(), before);
      return;
    }
    movesLeft -= moves;
  }
}

}  // namespace rtu
