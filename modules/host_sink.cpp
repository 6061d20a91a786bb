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

namespace {

struct ArrivalKey {
  uint64_t cycle;
  size_t index;  // in the order received
};

// Sorts by cycle, stably, in linear time: least significant 16-bit digit first, skipping the
// digits every key shares (the high ones of every run shorter than 2^32 cycles).
void radixSortByCycle(std::vector<ArrivalKey>& keys) {
  constexpr int kDigitBits = 16;
  constexpr uint64_t kDigits = uint64_t{1} << kDigitBits;
  std::vector<ArrivalKey> sorted(keys.size());
  std::vector<size_t> starts(kDigits + 1);
  for (int shift = 0; shift < 64; shift += kDigitBits) {
    const auto digit = [shift](const ArrivalKey& key) { return key.cycle >> shift & (kDigits - 1); };
    std::fill(starts.begin(), starts.end(), 0);
    for (const ArrivalKey& key : keys) ++starts[digit(key) + 1];
    if (std::find(starts.begin(), starts.end(), keys.size()) != starts.end()) continue;
    for (uint64_t d = 1; d <= kDigits; ++d) starts[d] += starts[d - 1];
    for (const ArrivalKey& key : keys) sorted[starts[digit(key)]++] = key;
    keys.swap(sorted);
  }
}

// Results of one cycle, should there be any, go in job order, so the order never depends on the
// order they were received in.
void breakTiesByJob(std::vector<ArrivalKey>& keys, const std::vector<HostSink::Arrival>& arrivals) {
  const auto job = [&arrivals](const ArrivalKey& key) { return arrivals[key.index].result.ids.job; };
  for (auto run = keys.begin(); run != keys.end();) {
    const auto end = std::find_if(run, keys.end(),
                                  [run](const ArrivalKey& key) { return key.cycle != run->cycle; });
    if (end - run > 1)
      std::sort(run, end, [&job](const ArrivalKey& a, const ArrivalKey& b) { return job(a) < job(b); });
    run = end;
  }
}

// Puts arrivals[keys[i].index] at i for every i, moving each arrival once by following the
// permutation's cycles.
void moveInto(std::vector<ArrivalKey>& keys, std::vector<HostSink::Arrival>& arrivals) {
  for (size_t start = 0; start < keys.size(); ++start) {
    if (keys[start].index == start) continue;
    const HostSink::Arrival first = arrivals[start];
    size_t to = start;
    while (keys[to].index != start) {
      const size_t from = keys[to].index;
      arrivals[to] = arrivals[from];
      keys[to].index = to;
      to = from;
    }
    arrivals[to] = first;
    keys[to].index = to;
  }
}

}  // namespace

// Sorts keys rather than the results themselves, which are several times larger.
void HostSink::arrange() {
  std::vector<ArrivalKey> keys(arrivals_.size());
  for (size_t i = 0; i < keys.size(); ++i) keys[i] = {arrivals_[i].cycle, i};
  radixSortByCycle(keys);
  breakTiesByJob(keys, arrivals_);
  moveInto(keys, arrivals_);
}

}  // namespace rtu
