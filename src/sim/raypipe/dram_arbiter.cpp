#include "sim/raypipe/dram_arbiter.h"

#include <algorithm>

namespace rtu {
namespace raypipe_timed {

int64_t DramArbiter::grantCycle(int port) const {
  const Port& p = ports_[static_cast<size_t>(port)];
  const int64_t start = std::max(p.from, idleFrom_);
  const int64_t looked = (pointer_ + (start - idleFrom_)) % kRaypipeDramPorts;
  return start + (port - looked + kRaypipeDramPorts) % kRaypipeDramPorts;
}

void DramArbiter::bookNextGrants(int64_t now) {
  for (int i = 0; i < kRaypipeDramPorts; ++i) {
    const Port& p = ports_[static_cast<size_t>(i)];
    if (p.asking && p.done < 0) calendar_->book(p.groups, std::max(grantCycle(i), now + 1), now);
  }
}

void DramArbiter::request(int port, int64_t from, uint32_t bytes, int64_t now) {
  Port& p = ports_[static_cast<size_t>(port)];
  p.asking = true;
  p.from = from;
  p.bytes = bytes;
  p.done = -1;
  calendar_->book(p.groups, grantCycle(port), now);
}

void DramArbiter::advance(int64_t now) {
  for (;;) {
    int first = -1;
    int64_t firstCycle = INT64_MAX;
    for (int i = 0; i < kRaypipeDramPorts; ++i) {
      const Port& p = ports_[static_cast<size_t>(i)];
      if (!p.asking || p.done >= 0) continue;
      const int64_t g = grantCycle(i);
      if (g < firstCycle) {
        firstCycle = g;
        first = i;
      }
    }
    if (first < 0 || firstCycle > now) return;
    Port& p = ports_[static_cast<size_t>(first)];
    p.done = static_cast<int64_t>(channel_.read(p.bytes, static_cast<uint64_t>(firstCycle)));
    idleFrom_ = p.done + 1;
    pointer_ = (first + 1) % kRaypipeDramPorts;
    calendar_->book(p.groups, p.done, now);
    bookNextGrants(now);
  }
}

RaypipeDramCounts DramArbiter::counts() const {
  const DramStats& s = channel_.stats();
  return {static_cast<int64_t>(s.reads), static_cast<int64_t>(s.bytes),
          static_cast<int64_t>(s.busyCycles)};
}

}  // namespace raypipe_timed
}  // namespace rtu
