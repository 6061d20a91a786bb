#pragma once
// The most entries a buffer held at once, from intervals decided out of cycle order: an entry
// occupies [from, to). Intervals are swept in cycle order up to a cycle before which no more can
// start (settle), so memory stays bounded by the intervals of the cycles not yet settled.

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace rtu {

class OccupancyPeak {
 public:
  void occupy(uint64_t from, uint64_t to) {
    events_.push_back({from, +1});
    events_.push_back({to, -1});
  }
  size_t unsettled() const { return events_.size(); }
  // Sweeps every change before `before` (ends before starts within a cycle).
  void settle(uint64_t before) {
    std::sort(events_.begin(), events_.end());
    size_t settled = 0;
    for (; settled < events_.size() && events_[settled].first < before; ++settled) {
      current_ += events_[settled].second;
      peak_ = std::max(peak_, current_);
    }
    events_.erase(events_.begin(), events_.begin() + static_cast<long>(settled));
  }
  uint64_t peak() const { return static_cast<uint64_t>(peak_); }

 private:
  std::vector<std::pair<uint64_t, int>> events_;
  int64_t current_ = 0, peak_ = 0;
};

}  // namespace rtu
