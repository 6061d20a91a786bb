#include "sim/ca/host_sink.h"

#include <algorithm>
#include <numeric>
#include <type_traits>
#include <utility>

#include "base/prefault.h"

namespace rtu {

namespace {

// Calls `apply(column)` for each column of `arrivals`.
template <class Apply>
void forEachColumn(HostSink::Arrivals& arrivals, Apply&& apply) {
  apply(arrivals.cycles);
  apply(arrivals.results);
  apply(arrivals.rays);
  apply(arrivals.jobs);
  apply(arrivals.blockedCycles);
  apply(arrivals.instances);
}

}  // namespace

HostSink::HostSink(DecisionPump& pump, uint64_t expected, HostLinkConfig link, Take take)
    : Agent(pump), expected_(expected), link_(link), pacer_(link), take_(std::move(take)) {
  validate(link, "host output");
  if (take_) return;
  forEachColumn(arrivals_, [expected](auto& column) {
    column.reserve(expected);
    prefaultCapacity(column);
  });
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
  in_->collectDelivered(
      [this](uint64_t cycle, const CoreResult& result) { receive(cycle, result); });
  if (in_->offering()) {  // from a reorder buffer
    const uint64_t cycle = firstReadyFrom(in_->offerCycle());
    const CoreResult result = in_->payload();
    in_->take(cycle);
    receive(cycle, result);
  }
}

void HostSink::receive(uint64_t cycle, const CoreResult& result) {
  if (take_) {
    take_(cycle, result);
  } else {
    arrivals_.cycles.push_back(cycle);
    arrivals_.results.push_back(result.result);
    arrivals_.rays.push_back(result.ids.ray);
    arrivals_.jobs.push_back(result.ids.job);
    arrivals_.blockedCycles.push_back(result.blockedCycles);
    arrivals_.instances.push_back(result.instance);
  }
  firstArrival_ = received_++ == 0 ? cycle : std::min(firstArrival_, cycle);
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
// a place per core), so moving each late one back to its place moves few, in place. Should the
// order be far off, a sort of all of them finishes once the moves reach a few per result.
void HostSink::arrange() {
  const size_t n = arrivals_.size();
  uint64_t movesLeft = 8 * n;
  for (size_t late = 1; late < n; ++late) {
    size_t place = late;
    while (place > 0 && before(late, place - 1)) --place;
    if (place == late) continue;
    forEachColumn(arrivals_, [place, late](auto& column) {
      std::rotate(column.begin() + place, column.begin() + late, column.begin() + late + 1);
    });
    if (late - place >= movesLeft) return sortAll();
    movesLeft -= late - place;
  }
}

// The job breaks ties, should there be any, so the order never depends on the sort.
bool HostSink::before(size_t a, size_t b) const {
  const uint64_t cycleA = arrivals_.cycles[a], cycleB = arrivals_.cycles[b];
  return cycleA != cycleB ? cycleA < cycleB : arrivals_.jobs[a] < arrivals_.jobs[b];
}

void HostSink::sortAll() {
  std::vector<size_t> order(arrivals_.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(), [this](size_t a, size_t b) { return before(a, b); });
  forEachColumn(arrivals_, [&order](auto& column) {
    std::remove_reference_t<decltype(column)> sorted;
    sorted.reserve(order.size());
    for (size_t i : order) sorted.push_back(column[i]);
    column.swap(sorted);
  });
}

}  // namespace rtu
