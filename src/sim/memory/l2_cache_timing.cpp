#include "sim/memory/l2_cache_timing.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace rtu {

namespace {

// Validation has to precede the members' construction, hence in the initializer list.
const CacheConfig& validated(const CacheConfig& cache) {
  validate(cache, "L2");
  return cache;
}

const DramConfig& validated(const DramConfig& dram) {
  validate(dram);
  return dram;
}

// RequestOrder::Any: past this many kept MSHR uses the claim uses the treap, until forgetting
// leaves at most kFewMshrUses. A scan costs a few instructions a use and the treap's update a few
// hundred, so the scan stays cheaper up to a few hundred uses: the real frames' case.
constexpr size_t kManyMshrUses = 256, kFewMshrUses = 64;

}  // namespace

L2CacheTiming::L2CacheTiming(const CacheConfig& cache, const DramConfig& dram, RequestOrder order,
                             DramRead external)
    : array_(validated(cache)),
      dram_(validated(dram), order),
      externalDram_(std::move(external)),
      order_(order),
      port_(order),
      uncontendedMiss_(dram.latency + dram_.transferCycles(cache.lineBytes)) {}

uint64_t L2CacheTiming::read(uint64_t byteAddress, uint64_t requestCycle) {
  const bool inCycleOrder = requestCycle >= lastRequestCycle_;
  const uint64_t accept = acceptRequest(requestCycle);
  const uint64_t tagCheckDone = accept + array_.config().hitLatency;
  const CacheLookup line = array_.access(byteAddress, accept);
  if (line.present)
    return std::max(tagCheckDone,
                    inCycleOrder ? line.fillCycle : mergedFill(line.fillCycle, tagCheckDone));
  const uint64_t fill = fetchLine(tagCheckDone);
  array_.allocate(byteAddress, fill);
  return fill;
}

// A request behind the latest one finds a line in flight: the miss that allocated it may have
// been issued after this request's tag check. In cycle order this request would have missed and
// that one merged, so it waits no longer than its own uncontended miss would.
uint64_t L2CacheTiming::mergedFill(uint64_t fillCycle, uint64_t tagCheckDone) const {
  return std::min(fillCycle, tagCheckDone + uncontendedMiss_);
}

void L2CacheTiming::failOutOfOrder(uint64_t requestCycle) const {
  throw std::logic_error("L2 requests must come in cycle order: cycle " +
                         std::to_string(requestCycle) + " after cycle " +
                         std::to_string(lastRequestCycle_));
}

// Returns the cycle the line is filled; it holds an MSHR until then.
uint64_t L2CacheTiming::fetchLine(uint64_t tagCheckDone) {
  const uint64_t issue = claimMshr(tagCheckDone);
  mshrQueueCycles_ += issue - tagCheckDone;
  const uint32_t bytes = array_.config().lineBytes;
  const uint64_t fill = externalDram_ ? externalDram_(bytes, issue) : dram_.read(bytes, issue);
  if (order_ == RequestOrder::Cycle)
    mshrReleases_.push(fill);
  else {
    mshrUses_.push_back({issue, fill});
    if (__builtin_expect(mshrUsesCounted_ || mshrUses_.size() > kManyMshrUses, false))
      keepMshrUse(issue, fill);
  }
  return fill;
}

// The first cycle from `cycle` on in which fewer than maxOutstandingMisses MSHRs are busy.
uint64_t L2CacheTiming::claimMshr(uint64_t cycle) {
  return order_ == RequestOrder::Cycle ? claimMshrInOrder(cycle) : claimMshrAnyOrder(cycle);
}

// In cycle order the busy MSHRs are those released after `cycle`: a heap of at most
// maxOutstandingMisses releases, the earliest taken over when all are busy.
uint64_t L2CacheTiming::claimMshrInOrder(uint64_t cycle) {
  while (!mshrReleases_.empty() && mshrReleases_.top() <= cycle) mshrReleases_.pop();
  if (mshrReleases_.size() < array_.config().maxOutstandingMisses) return cycle;
  const uint64_t release = mshrReleases_.top();
  mshrReleases_.pop();
  return release;
}

// Out of order a use may have been issued after `cycle`: the busy ones at a cycle are those
// issued by it and released after it. While all are busy, the count stays at least the limit
// until the first release among them, so waiting for that release, as long as all are busy,
// finds the first cycle from `cycle` on with fewer busy: what mshrBusy_ finds at once.
uint64_t L2CacheTiming::claimMshrAnyOrder(uint64_t cycle) {
  const uint32_t limit = array_.config().maxOutstandingMisses;
  if (__builtin_expect(mshrUsesCounted_, false)) return mshrBusy_.firstBelow(cycle, limit);
  for (;;) {
    uint32_t busy = 0;
    uint64_t firstRelease = UINT64_MAX;
    for (const MshrUse& use : mshrUses_) {
      if (use.issue > cycle || use.release <= cycle) continue;
      ++busy;
      firstRelease = std::min(firstRelease, use.release);
    }
    if (busy < limit) return cycle;
    cycle = firstRelease;
  }
}

// The use just kept (the last of mshrUses_) when the uses are, or become, many: counted in
// mshrBusy_ (an external DRAM's empty use, busy at no cycle, is not).
void L2CacheTiming::keepMshrUse(uint64_t issue, uint64_t release) {
  if (mshrUsesCounted_) {
    std::push_heap(mshrUses_.begin(), mshrUses_.end());
    if (issue < release) mshrBusy_.add(issue, release, 1);
    return;
  }
  std::make_heap(mshrUses_.begin(), mshrUses_.end());
  for (const MshrUse& use : mshrUses_)
    if (use.issue < use.release) mshrBusy_.add(use.issue, use.release, 1);
  mshrUsesCounted_ = true;
}

void L2CacheTiming::forgetMshrsBefore(uint64_t cycle) {
  if (!mshrUsesCounted_) {
    mshrUses_.erase(std::remove_if(mshrUses_.begin(), mshrUses_.end(),
                                   [cycle](const MshrUse& use) { return use.release <= cycle; }),
                    mshrUses_.end());
    return;
  }
  while (!mshrUses_.empty() && mshrUses_.front().release <= cycle) {
    const MshrUse& use = mshrUses_.front();
    if (use.issue < use.release) mshrBusy_.add(use.issue, use.release, -1);
    std::pop_heap(mshrUses_.begin(), mshrUses_.end());
    mshrUses_.pop_back();
  }
  if (mshrUses_.size() <= kFewMshrUses) {  // a scan is cheaper again
    mshrBusy_.clear();
    mshrUsesCounted_ = false;
  }
}

void L2CacheTiming::BusyCount::add(uint64_t issue, uint64_t release, int64_t uses) {
  change(issue, uses);
  change(release, -uses);
}

void L2CacheTiming::BusyCount::clear() {
  root_ = 0;
  nodes_.resize(1);
  unused_.clear();
}

// The changes at cycles up to `cycle` sum to the count busy at it. From there it changes only at
// the later cycles with a change: the first of them at which the sum of the changes so far is
// below `limit`. There is one, as all the changes sum to 0.
uint64_t L2CacheTiming::BusyCount::firstBelow(uint64_t cycle, int64_t limit) {
  const auto [upTo, after] = split(root_, cycle, true);
  int64_t busy = nodes_[upTo].sum;
  uint64_t first = cycle;
  for (Index node = after; busy >= limit;) {  // busy + minPrefix of `node` < limit
    const Node& n = nodes_[node];
    if (n.left != 0 && busy + nodes_[n.left].minPrefix < limit) {
      node = n.left;
      continue;
    }
    busy += nodes_[n.left].sum + n.change;
    first = n.cycle;
    node = n.right;
  }
  root_ = merge(upTo, after);
  return first;
}

// Adds `by` to the change at `cycle`: a node while it is not 0.
void L2CacheTiming::BusyCount::change(uint64_t cycle, int64_t by) {
  const auto [before, rest] = split(root_, cycle, false);
  auto [at, later] = split(rest, cycle, true);
  if (at == 0) {
    if (unused_.empty()) {
      at = static_cast<Index>(nodes_.size());
      nodes_.emplace_back();
    } else {
      at = unused_.back();
      unused_.pop_back();
    }
    random_ ^= random_ << 13;
    random_ ^= random_ >> 7;
    random_ ^= random_ << 17;
    nodes_[at] = Node{cycle, random_, by, 0, 0, 0, 0};
    update(at);
  } else if ((nodes_[at].change += by) == 0) {
    unused_.push_back(at);
    at = 0;
  } else {
    update(at);
  }
  root_ = merge(merge(before, at), later);
}

// The cycles before `cycle` (with `withCycle`: up to it) and the others.
std::pair<L2CacheTiming::BusyCount::Index, L2CacheTiming::BusyCount::Index>
L2CacheTiming::BusyCount::split(Index node, uint64_t cycle, bool withCycle) {
  if (node == 0) return {0, 0};
  const uint64_t key = nodes_[node].cycle;
  if (key < cycle || (withCycle && key == cycle)) {
    const auto [earlier, later] = split(nodes_[node].right, cycle, withCycle);
    nodes_[node].right = earlier;
    update(node);
    return {node, later};
  }
  const auto [earlier, later] = split(nodes_[node].left, cycle, withCycle);
  nodes_[node].left = later;
  update(node);
  return {earlier, node};
}

// Every cycle of `earlier` is before every cycle of `later`.
L2CacheTiming::BusyCount::Index L2CacheTiming::BusyCount::merge(Index earlier, Index later) {
  if (earlier == 0) return later;
  if (later == 0) return earlier;
  if (nodes_[earlier].priority >= nodes_[later].priority) {
    const Index right = merge(nodes_[earlier].right, later);
    nodes_[earlier].right = right;
    update(earlier);
    return earlier;
  }
  const Index left = merge(earlier, nodes_[later].left);
  nodes_[later].left = left;
  update(later);
  return later;
}

void L2CacheTiming::BusyCount::update(Index node) {
  Node& n = nodes_[node];
  const Node& left = nodes_[n.left];
  const Node& right = nodes_[n.right];
  const int64_t throughThis = left.sum + n.change;
  n.sum = throughThis + right.sum;
  n.minPrefix = throughThis;
  if (n.left != 0) n.minPrefix = std::min(n.minPrefix, left.minPrefix);
  if (n.right != 0) n.minPrefix = std::min(n.minPrefix, throughThis + right.minPrefix);
}

void L2CacheTiming::forgetBefore(uint64_t cycle) {
  port_.forgetBefore(cycle);
  dram_.forgetBefore(cycle);
  forgetMshrsBefore(cycle);
}

const StatisticGroup<L2Stats>& L2Stats::declaration() {
  static const StatisticGroup<L2Stats> group =
      StatisticGroup<L2Stats>("the L2 and the DRAM behind it")
          .group(Statistic("l2", "", "the shared L2: requests from the L1s"), &L2Stats::cache)
          .count(Statistic("l2/port_queue_cycles", "cycles",
                           "cycles requests waited for the L2's port: sum of accept - request"),
                 &L2Stats::portQueueCycles)
          .count(Statistic("l2/mshr_queue_cycles", "cycles",
                           "cycles misses waited for an MSHR: sum of issue - tag check"),
                 &L2Stats::mshrQueueCycles)
          .group(Statistic("dram", "", "the DRAM channel behind the L2"), &L2Stats::dram);
  return group;
}

L2Stats L2CacheTiming::stats() const {
  L2Stats stats;
  stats.cache = array_.stats();
  stats.dram = dram_.stats();
  stats.portQueueCycles = portQueueCycles_;
  stats.mshrQueueCycles = mshrQueueCycles_;
  return stats;
}

}  // namespace rtu
